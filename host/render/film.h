// Per-pixel sums of the sample estimates, in double: the GPU's float batch sums are folded in every batch,
// so precision does not degrade with the sample count.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include "../shaders/shared/layout.h"
#include "passes/ears_image_statistics.h"

namespace vkmc {

// relMSE's and relative variance's (v / (mean^2 + epsilon)) epsilon: keeps near-black pixels from dominating.
inline constexpr double kRelMseEpsilon = 1e-2;

struct Film {
  uint32_t width = 0, height = 0;
  std::vector<double> sum;      // 3 per pixel
  std::vector<double> sumSq;    // 3 per pixel
  std::vector<uint64_t> count;  // finite samples per pixel
  std::vector<uint64_t> nonfinite;
  std::vector<uint64_t> highRange;  // finite samples with a channel >= 2^56, kept in the scaled high sums
  // Per pixel: its samples' camera-path vertices (depth + 1 each, split children not counted), finite samples or
  // not: what the pixel cost, about a ray and a shadow ray a vertex. cost() is a sample's mean.
  std::vector<double> vertices;
  // Replicates (shaders/shared/sampler.h): per pixel kMaxSampleReplicates slots of sums (3 each) and counts,
  // the first `replicates` used (the estimator's `replicates`; the device's last one is the batch's rest).
  std::vector<double> replicateSum;
  std::vector<uint64_t> replicateCount;
  uint32_t replicates = gpu::kMaxSampleReplicates;
  // QMC samplers: a pixel's samples are correlated, so the variance of its mean comes from the spread of the
  // replicate means; the independent sampler's samples are independent, so from the samples (more dof).
  bool replicateVariance = false;
  // Whether the film estimates a variance at all: one scrambling a pixel (`--replicates 1` under a QMC sampler)
  // has no independent replicates, and no unbiased variance of its mean exists (its samples' spread overstates it).
  bool estimatesVariance() const { return !replicateVariance || replicates >= 2; }

  Film() = default;
  // Folds one batch of the GPU's float partial sums (at most 64 samples a pixel) into the double sums: the
  // float error stays that of 64 additions however many batches follow.
  // Adds one batch of the device film (gpu::FilmPixel per pixel).
  void addBatch(const gpu::FilmPixel* batch);
  Film(uint32_t w, uint32_t h);
  size_t pixels() const { return static_cast<size_t>(width) * height; }
  double mean(size_t pixel, int c) const;
  double cost(size_t pixel) const;  // mean camera-path vertices a sample (0 without samples)
  // The pixel's efficiency, 1 / (relative variance of its mean x what its samples cost), the variance relative as
  // in relMSE (over mean^2 + kRelMseEpsilon, averaged over the channels): 0 where it shows no variance yet.
  double efficiency(size_t pixel) const;
  // The variance of the pixel mean, estimated without bias: sample variance / n, or with replicateVariance
  // the replicate means' sample variance / (number of replicates). 0 below two samples (or replicates); NaN
  // where the film estimates no variance (estimatesVariance).
  double varianceOfMean(size_t pixel, int c) const;
  double sampleVarianceOfMean(size_t pixel, int c) const;     // from the samples, as if independent
  double replicateVarianceOfMean(size_t pixel, int c) const;  // from the replicate means
  // Degrees of freedom of varianceOfMean: replicates with samples - 1, or samples - 1. A z-test on one pixel
  // whose variance has few (replicates - 1 with the QMC samplers) needs Student's t, not the normal, for its bound.
  double varianceDof(size_t pixel) const;

  glm::dvec3 imageMean() const;
  glm::dvec3 imageMeanVarianceOfMean() const;  // image mean of the per-pixel variance of the mean
  // The expected relMSE of an unbiased render: each pixel's variance of the mean over mean^2 + epsilon, averaged
  // over pixels and channels (the report's mean_relvariance); NaN where the film estimates no variance.
  double meanRelativeVariance(double epsilon) const;
  uint64_t totalNonfinite() const;
  uint64_t totalSamples() const;
  uint64_t totalHighRange() const;
};

// A batch pixel's sum and sum of squares of channel c in double, its high-range sums (times kFilmHighScale)
// added back.
double batchChannelSum(const gpu::FilmPixel& f, int c);
double batchChannelSumSq(const gpu::FilmPixel& f, int c);
// The device batch's sums per pixel, its high-range sums added back (null batch: zeros).
std::vector<PixelSums> batchPixelSums(const gpu::FilmPixel* batch, size_t pixels);

// The running pixel estimate that shadow-ray roulette and EARS compare contributions against: per pixel the mean
// of the folded film and, when given, the device's unfolded batch (rgb), and its luminance (w); 0 where no
// sample is yet.
std::vector<glm::vec4> runningPixelEstimate(const Film& film, const gpu::FilmPixel* batch = nullptr);

}  // namespace vkmc
