// --target-error: the image's relMSE estimated from its own per-pixel variances, and how sure that estimate is.
#pragma once
#include "render/film.h"

namespace vkmc {

struct RelMseEstimate {
  double value = 0.0;  // mean over pixels of (1/3) sum_c varianceOfMean / (mean^2 + epsilon)
  double upper = 0.0;  // its one-sided 95% upper bound
};

// Each pixel's term t_p is a variance estimate with d_p degrees of freedom (Film::varianceDof), whose own variance
// is 2 t_p^2 / d_p (chi-square); the channels share their samples, so a pixel counts once. The bound is
// value + 1.645 sqrt(sum_p 2 t_p^2 / d_p) / pixels. NaN where the film estimates no variance.
RelMseEstimate estimateRelMse(const Film& film, double epsilon);

}  // namespace vkmc
