// Film statistics.
#include "render/film.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "../shaders/shared/sampling.h"

namespace vkmc {

Film::Film(uint32_t w, uint32_t h)
    : width(w),
      height(h),
      sum(3 * pixels(), 0.0),
      sumSq(3 * pixels(), 0.0),
      count(pixels(), 0),
      nonfinite(pixels(), 0),
      highRange(pixels(), 0),
      vertices(pixels(), 0.0),
      replicateSum(3 * gpu::kMaxSampleReplicates * pixels(), 0.0),
      replicateCount(gpu::kMaxSampleReplicates * pixels(), 0) {}

namespace {
constexpr double kFilmHighUnscale = 1.0 / double(gpu::kFilmHighScale);  // 2^96: exact
}

double batchChannelSum(const gpu::FilmPixel& f, int c) { return f.sum[c] + double(f.sumHigh[c]) * kFilmHighUnscale; }
double batchChannelSumSq(const gpu::FilmPixel& f, int c) {
  return f.sumSq[c] + double(f.sumSqHigh[c]) * (kFilmHighUnscale * kFilmHighUnscale);
}

void Film::addBatch(const gpu::FilmPixel* px) {
  for (size_t p = 0; p < pixels(); ++p) {
    for (int c = 0; c < 3; ++c) {
      sum[3 * p + c] += batchChannelSum(px[p], c);
      sumSq[3 * p + c] += batchChannelSumSq(px[p], c);
    }
    count[p] += static_cast<uint64_t>(px[p].sum[3]);
    nonfinite[p] += static_cast<uint64_t>(px[p].sumSq[3]);
    highRange[p] += static_cast<uint64_t>(px[p].sumHigh[3]);
    vertices[p] += double(px[p].sumSqHigh[3]);
    // The last replicate is the rest of the batch: its sums and count by difference.
    const uint32_t last = replicates - 1;
    double rest[3];
    uint64_t restCount = static_cast<uint64_t>(px[p].sum[3]);
    for (int c = 0; c < 3; ++c) rest[c] = batchChannelSum(px[p], c);
    for (uint32_t r = 0; r < last; ++r) {
      for (int c = 0; c < 3; ++c) {
        replicateSum[(p * gpu::kMaxSampleReplicates + r) * 3 + c] += px[p].replicate[r][c];
        rest[c] -= px[p].replicate[r][c];
      }
      replicateCount[p * gpu::kMaxSampleReplicates + r] += static_cast<uint64_t>(px[p].replicate[r][3]);
      restCount -= static_cast<uint64_t>(px[p].replicate[r][3]);
    }
    for (int c = 0; c < 3; ++c) replicateSum[(p * gpu::kMaxSampleReplicates + last) * 3 + c] += rest[c];
    replicateCount[p * gpu::kMaxSampleReplicates + last] += restCount;
  }
}

std::vector<glm::vec4> runningPixelEstimate(const Film& film, const gpu::FilmPixel* batch) {
  std::vector<glm::vec4> estimate(film.pixels(), glm::vec4(0.0f));
  for (size_t p = 0; p < estimate.size(); ++p) {
    double n = double(film.count[p]) + (batch ? batch[p].sum.w : 0.0);
    if (n < 1.0) continue;
    glm::dvec3 mean;
    for (int c = 0; c < 3; ++c) {
      double batchSum = batch ? batchChannelSum(batch[p], c) : 0.0;
      mean[c] = (film.sum[3 * p + c] + batchSum) / n;
    }
    estimate[p] = glm::vec4(glm::vec3(mean), gpu::luminance(glm::vec3(mean)));
  }
  return estimate;
}

double Film::cost(size_t p) const {
  const uint64_t n = count[p] + nonfinite[p];
  return n ? vertices[p] / double(n) : 0.0;
}

double Film::efficiency(size_t p) const {
  double rel = 0.0;
  for (int c = 0; c < 3; ++c) rel += varianceOfMean(p, c) / (mean(p, c) * mean(p, c) + kRelMseEpsilon) / 3.0;
  const double spent = vertices[p] * rel;
  return spent > 0.0 && std::isfinite(spent) ? 1.0 / spent : 0.0;
}

double Film::mean(size_t p, int c) const { return count[p] ? sum[3 * p + c] / static_cast<double>(count[p]) : 0.0; }

double Film::varianceOfMean(size_t p, int c) const {
  if (!estimatesVariance()) return std::numeric_limits<double>::quiet_NaN();  // never a 0 that reads as certainty
  return replicateVariance ? replicateVarianceOfMean(p, c) : sampleVarianceOfMean(p, c);
}

double Film::replicateVarianceOfMean(size_t p, int c) const {
  double means[gpu::kMaxSampleReplicates];
  int k = 0;
  for (uint32_t r = 0; r < gpu::kMaxSampleReplicates; ++r) {
    uint64_t n = replicateCount[p * gpu::kMaxSampleReplicates + r];
    if (n) means[k++] = replicateSum[(p * gpu::kMaxSampleReplicates + r) * 3 + c] / static_cast<double>(n);
  }
  if (k < 2) return 0.0;
  double m = 0.0;
  for (int i = 0; i < k; ++i) m += means[i];
  m /= k;
  double ss = 0.0;
  for (int i = 0; i < k; ++i) ss += (means[i] - m) * (means[i] - m);
  return ss / (double(k) * double(k - 1));
}

double Film::varianceDof(size_t p) const {
  if (!replicateVariance) return count[p] < 2 ? 0.0 : double(count[p] - 1);
  int k = 0;
  for (uint32_t r = 0; r < gpu::kMaxSampleReplicates; ++r) k += replicateCount[p * gpu::kMaxSampleReplicates + r] != 0;
  return k < 2 ? 0.0 : double(k - 1);
}

double Film::sampleVarianceOfMean(size_t p, int c) const {
  double n = static_cast<double>(count[p]);
  if (n < 2.0) return 0.0;
  double m = sum[3 * p + c] / n;
  double var = std::max(0.0, (sumSq[3 * p + c] - n * m * m) / (n - 1.0));
  return var / n;
}

glm::dvec3 Film::imageMean() const {
  glm::dvec3 acc(0.0);
  for (size_t p = 0; p < pixels(); ++p) acc += glm::dvec3(mean(p, 0), mean(p, 1), mean(p, 2));
  return pixels() ? acc / static_cast<double>(pixels()) : acc;
}

glm::dvec3 Film::imageMeanVarianceOfMean() const {
  glm::dvec3 acc(0.0);
  for (size_t p = 0; p < pixels(); ++p) acc += glm::dvec3(varianceOfMean(p, 0), varianceOfMean(p, 1), varianceOfMean(p, 2));
  return pixels() ? acc / static_cast<double>(pixels()) : acc;
}

double Film::meanRelativeVariance(double epsilon) const {
  double acc = 0.0;
  for (size_t p = 0; p < pixels(); ++p)
    for (int c = 0; c < 3; ++c) {
      const double m = mean(p, c);
      acc += varianceOfMean(p, c) / (m * m + epsilon);
    }
  return acc / (3.0 * static_cast<double>(std::max<size_t>(1, pixels())));
}

uint64_t Film::totalNonfinite() const {
  uint64_t n = 0;
  for (uint64_t v : nonfinite) n += v;
  return n;
}

uint64_t Film::totalHighRange() const {
  uint64_t n = 0;
  for (uint64_t v : highRange) n += v;
  return n;
}

uint64_t Film::totalSamples() const {
  uint64_t n = 0;
  for (uint64_t v : count) n += v;
  return n;
}

std::vector<PixelSums> batchPixelSums(const gpu::FilmPixel* batch, size_t pixels) {
  std::vector<PixelSums> sums(pixels);
  if (!batch) return sums;
  for (size_t p = 0; p < pixels; ++p) {
    sums[p].n = batch[p].sum.w;
    for (int c = 0; c < 3; ++c) {
      sums[p].sum[c] = batchChannelSum(batch[p], c);
      sums[p].sumSq[c] = batchChannelSumSq(batch[p], c);
    }
  }
  return sums;
}

}  // namespace vkmc
