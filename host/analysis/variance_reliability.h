// How far the report's variance estimate can be trusted (issue 14, item 6). mean_relvariance averages each
// pixel's estimated variance of its mean (over mean^2 + epsilon); with heavy-tailed samples a few pixels' rare
// huge samples decide it, and an estimator that has not yet met its rare samples looks better than it is.
//
// The estimate's own standard error comes from each pixel's replicate means (sampler.h: R per pixel, the
// estimator's `replicates`, under every sampler), without any extra moment on the device. With h(a, b) =
// sum_c w_c (x_ac - x_bc)^2 / 2 over the channels (w_c = 1 / (mean_c^2 + epsilon)), the pixel's term t = U / R,
// U = the mean of h over the pairs of replicates, estimates sum_c w_c Var(pixel mean_c) without bias. For Var(U):
// with 4 replicates U^2 - theta2, where theta2 = the mean of h(a, b) h(c, d) over the 3 ways to split the replicates
// into two disjoint pairs (an unbiased estimate of E[h]^2: the U-statistic variance estimator for 4 samples);
// with 2 or 3 no two pairs are disjoint, so U^2, whose mean Var(U) + E[U]^2 bounds it from above (for one channel
// of normal replicate means by 1 + (R - 1) / 2 in variance: sqrt(3/2) in the standard error at R = 2, sqrt(2) at 3;
// less for heavier tails, more when the channels are less correlated). Summed over the pixels (independent)
// this gives Var(mean_relvariance); its square root over the estimate is the relative standard error. Channels
// need no independence: they share one h. Under the independent sampler the report's variance comes from the
// samples (more degrees of freedom), so the replicates' figure is conservative there.
#pragma once
#include <cstddef>

#include "render/film.h"

namespace vkmc {

struct VarianceReliability {
  double relVariance = 0.0;            // the replicates' estimate of mean_relvariance
  double relativeStandardError = 0.0;  // of that estimate; infinity when it is 0 or no pixel has every replicate
  size_t pixelsAssessed = 0;           // pixels with samples in every replicate
  double largestPixelShare = 0.0;      // the largest single pixel's share of the estimate
  // An efficiency figure whose variance is uncertain by more than this (one standard error) cannot rank two
  // estimators that differ by less: the report then marks it unreliable.
  static constexpr double kReliableBelow = 0.1;
  bool reliable() const { return relativeStandardError <= kReliableBelow; }
};

VarianceReliability assessVarianceReliability(const Film& film);

}  // namespace vkmc
