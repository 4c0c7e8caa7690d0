// Per-pixel sums of the sample estimates, in double: the GPU's float batch sums are folded in every batch,
// so precision does not degrade with the sample count.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include "../shaders/shared/layout.h"

namespace vkmc {

struct Film {
  uint32_t width = 0, height = 0;
  std::vector<double> sum;      // 3 per pixel
  std::vector<double> sumSq;    // 3 per pixel
  std::vector<uint64_t> count;  // finite samples per pixel
  std::vector<uint64_t> nonfinite;

  Film() = default;
  // Folds one batch of the GPU's float partial sums (at most 64 samples a pixel) into the double sums: the
  // float error stays that of 64 additions however many batches follow.
  // Adds one batch of the device film (gpu::FilmPixel per pixel).
  void addBatch(const gpu::FilmPixel* batch);
  Film(uint32_t w, uint32_t h);
  size_t pixels() const { return static_cast<size_t>(width) * height; }
  double mean(size_t pixel, int c) const;
  // Unbiased sample variance / n: the variance of the pixel mean.
  double varianceOfMean(size_t pixel, int c) const;
  glm::dvec3 imageMean() const;
  glm::dvec3 imageMeanVarianceOfMean() const;  // image mean of the per-pixel variance of the mean
  uint64_t totalNonfinite() const;
  uint64_t totalSamples() const;
};

}  // namespace vkmc
