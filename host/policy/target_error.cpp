#include "policy/target_error.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vkmc {

RelMseEstimate estimateRelMse(const Film& film, double epsilon) {
  RelMseEstimate e;
  if (!film.estimatesVariance() || film.pixels() == 0) {
    e.value = e.upper = std::numeric_limits<double>::quiet_NaN();
    return e;
  }
  double sum = 0.0, spread = 0.0;
  for (size_t p = 0; p < film.pixels(); ++p) {
    double t = 0.0;
    for (int c = 0; c < 3; ++c) {
      // mean^2 overstates the squared true value by the variance of the mean: taken out, or a few samples'
      // noisy pixels look relatively quieter than they are (veach_mis at 16 spp: 0.018 for an actual 0.025-0.029).
      // At most half of it: a noisy variance near mean^2 would leave epsilon alone (that read 1.4-10).
      const double m = film.mean(p, c), v = film.varianceOfMean(p, c);
      t += v / (std::max(m * m - v, 0.5 * m * m) + epsilon);
    }
    t /= 3.0;
    const double dof = film.varianceDof(p);
    sum += t;
    // A pixel without a variance yet (under two samples or replicates) is as unsure as can be.
    spread += dof > 0.0 ? 2.0 * t * t * (1.0 / dof + 1.0) : std::numeric_limits<double>::infinity();
  }
  const double n = double(film.pixels());
  e.value = sum / n;
  e.upper = e.value + 1.645 * std::sqrt(spread) / n;
  return e;
}

}  // namespace vkmc
