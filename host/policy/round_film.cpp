#include "policy/round_film.h"

#include <algorithm>
#include <cmath>

namespace vkmc {

namespace {
constexpr uint32_t kSlots = gpu::kMaxSampleReplicates;
}

double roundWeight(double weightSoFar, double samples, double laterSamples, bool last) {
  const double left = std::max(0.0, 1.0 - weightSoFar);
  if (last || laterSamples <= 0.0) return left;
  return left * samples / (samples + laterSamples);
}

RoundFilm::RoundFilm(uint32_t width, uint32_t height, uint32_t replicates, bool replicateVariance)
    : width_(width), height_(height), replicates_(replicates), replicateVariance_(replicateVariance) {
  const size_t pixels = size_t(width) * height;
  weight_.assign(pixels, 0.0);
  replicateSum_.assign(pixels * kSlots * 3, 0.0);
  varianceSum_.assign(pixels * 3, 0.0);
  squares_.assign(pixels * 3, 0.0);
  squaresDof_.assign(pixels, 0);
  replicateCount_.assign(pixels * kSlots, 0);
  count_.assign(pixels, 0), nonfinite_.assign(pixels, 0), highRange_.assign(pixels, 0);
  vertices_.assign(pixels, 0.0);
}

void RoundFilm::addRound(const Film& round, const std::vector<double>& weights) {
  for (size_t p = 0; p < round.pixels(); ++p) {
    const double n = double(round.count[p]), weight = weights[p];
    weight_[p] += weight;
    for (uint32_t r = 0; r < kSlots; ++r) {
      const uint64_t k = round.replicateCount[p * kSlots + r];
      replicateCount_[p * kSlots + r] += k;
      // A replicate with no finite sample this round adds 0 (only non-finite samples, which are counted, do that).
      for (int c = 0; c < 3 && k; ++c)
        replicateSum_[(p * kSlots + r) * 3 + c] += weight * round.replicateSum[(p * kSlots + r) * 3 + c] / double(k);
    }
    for (int c = 0; c < 3 && n >= 1.0; ++c) {
      const double m = round.sum[3 * p + c] / n;
      const double ss = std::max(0.0, round.sumSq[3 * p + c] - n * m * m);
      squares_[3 * p + c] += ss;
      if (n >= 2.0) varianceSum_[3 * p + c] += weight * weight * ss / (n - 1.0) / n;
    }
    squaresDof_[p] += round.count[p] ? round.count[p] - 1 : 0;
    count_[p] += round.count[p], nonfinite_[p] += round.nonfinite[p], highRange_[p] += round.highRange[p];
    vertices_[p] += round.vertices[p];
  }
  ++rounds_;
}

std::vector<glm::dvec3> RoundFilm::means() const {
  std::vector<glm::dvec3> m(count_.size(), glm::dvec3(0.0));
  for (size_t p = 0; p < m.size(); ++p) {
    if (weight_[p] <= 0.0) continue;
    int used = 0;
    for (uint32_t r = 0; r < replicates_; ++r) {
      if (!replicateCount_[p * kSlots + r]) continue;
      ++used;
      for (int c = 0; c < 3; ++c) m[p][c] += replicateSum_[(p * kSlots + r) * 3 + c] / weight_[p];
    }
    if (used) m[p] /= double(used);
  }
  return m;
}

std::vector<glm::dvec3> RoundFilm::sampleVariances() const {
  std::vector<glm::dvec3> v(count_.size(), glm::dvec3(0.0));
  for (size_t p = 0; p < v.size(); ++p)
    if (squaresDof_[p]) v[p] = glm::dvec3(squares_[3 * p], squares_[3 * p + 1], squares_[3 * p + 2]) / double(squaresDof_[p]);
  return v;
}

std::vector<double> RoundFilm::costs() const {
  std::vector<double> c(count_.size(), 0.0);
  for (size_t p = 0; p < c.size(); ++p)
    if (const uint64_t n = count_[p] + nonfinite_[p]) c[p] = vertices_[p] / double(n);
  return c;
}

Film RoundFilm::image() const {
  Film f(width_, height_);
  f.replicates = replicates_;
  f.replicateVariance = replicateVariance_;
  const std::vector<glm::dvec3> m = means();
  for (size_t p = 0; p < f.pixels(); ++p) {
    const double n = double(count_[p]);
    f.count[p] = count_[p], f.nonfinite[p] = nonfinite_[p], f.highRange[p] = highRange_[p], f.vertices[p] = vertices_[p];
    for (uint32_t r = 0; r < kSlots; ++r) {
      const uint64_t k = replicateCount_[p * kSlots + r];
      f.replicateCount[p * kSlots + r] = k;
      for (int c = 0; c < 3 && k && weight_[p] > 0.0; ++c)
        f.replicateSum[(p * kSlots + r) * 3 + c] = replicateSum_[(p * kSlots + r) * 3 + c] / weight_[p] * double(k);
    }
    for (int c = 0; c < 3; ++c) {
      f.sum[3 * p + c] = m[p][c] * n;
      // Film's sample variance of the mean is (sumSq - n m^2) / ((n - 1) n): sumSq chosen so that it reads V.
      const double V = weight_[p] > 0.0 ? varianceSum_[3 * p + c] / (weight_[p] * weight_[p]) : 0.0;
      f.sumSq[3 * p + c] = n >= 2.0 ? V * n * (n - 1.0) + n * m[p][c] * m[p][c] : 0.0;
    }
  }
  return f;
}

}  // namespace vkmc
