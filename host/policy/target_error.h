// --target-error: the image's relMSE estimated from its own per-pixel variances, and how sure that estimate is.
#pragma once
#include "render/film.h"

namespace vkmc {

struct RelMseEstimate {
  double value = 0.0;  // the expected relMSE: the mean of t_p below
  double upper = 0.0;  // one-sided 95%: the render's relMSE is under it in about 95% of renders
};

// What a render's relMSE against the truth will read, and a bound it stays under in about 95% of renders. Each
// pixel's term t_p = (1/3) sum_c V_c / (max(m_c^2 - V_c, m_c^2 / 2) + epsilon) (m^2 - V: an unbiased estimate of
// the squared true value; m^2 alone overstates it, most at few samples; at most halved, as a noisy V near m^2
// would otherwise leave epsilon alone). The bound adds 1.645 standard deviations of two
// independent fluctuations, each chi-square in shape: the variance estimate's own (2 t_p^2 / d_p, d_p its degrees
// of freedom: Film::varianceDof) and the render's actual squared error around its expectation (2 t_p^2); the
// channels share their samples, so a pixel counts once. NaN where the film estimates no variance.
RelMseEstimate estimateRelMse(const Film& film, double epsilon);

}  // namespace vkmc
