// Adaptive sampling's allocation: how many samples each pixel gets in the next round, from what the earlier rounds
// measured. The image's relMSE is sum_p v_p / n_p (v_p: a sample's relative variance at pixel p), so for a fixed
// cost sum_p c_p n_p it is least with n_p proportional to sqrt(v_p / c_p), c_p a sample's cost there.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace vkmc {

struct AllocationLimits {
  uint32_t multiple = 1;  // every count a multiple of this (the replicates: each gets as many samples)
  uint32_t minimum = 1;   // the fewest a pixel gets (a multiple of `multiple`): every pixel stays in every round
  // The fewest as a factor of the round's mean, defensively: a pixel whose rare bright paths no earlier sample
  // found looks quiet, and a round's mean from its few samples weighs what the round weighs; at a quarter of the
  // mean its variance is at most 4x a uniform render's (glass_bulb: at `minimum` alone, 30-80x the relMSE).
  double minFactor = 0.25;
  double maxFactor = 8.0;  // the most a pixel gets, as a factor of the round's mean
  // v_p + imagePrior * (the image's mean v) in place of v_p: a prior that every pixel may hold what the image's
  // noisiest hold. At 1, glass_bulb's scattered fireflies cost 0.9x at equal samples (0.3x without it), veach_mis
  // keeps 2.2x of its 4.2x (docs/journal/adaptive-sampling.md).
  double imagePrior = 1.0;
};

// Samples per pixel for a round of `budget` samples over the image (exactly, where the budget is a multiple of
// `multiple` and the limits allow): sqrt((v_p + prior) / c_p) scaled to the budget, clamped to the limits, in
// multiples. Uniform where no pixel has a variance yet. `cost` may be
// empty (every sample costs the same).
std::vector<uint32_t> allocateSamples(const std::vector<double>& relVariance, const std::vector<double>& cost, uint64_t budget,
                                      const AllocationLimits& limits);

// A sample's relative variance per pixel, (1/3) sum_c var_c / (mean_c^2 + epsilon), averaged over the pixel's 3x3
// neighbourhood: one pixel's estimate from a few samples is noisy, and noise seen by a neighbour is likely here too.
std::vector<double> smoothedRelativeVariance(const std::vector<glm::dvec3>& mean, const std::vector<glm::dvec3>& sampleVariance,
                                             uint32_t width, uint32_t height, double epsilon);

}  // namespace vkmc
