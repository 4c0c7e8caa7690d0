#include "policy/target_error.h"

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
      const double m = film.mean(p, c);
      t += film.varianceOfMean(p, c) / (m * m + epsilon);
    }
    t /= 3.0;
    const double dof = film.varianceDof(p);
    sum += t;
    // A pixel without a variance yet (under two samples or replicates) is as unsure as can be.
    spread += dof > 0.0 ? 2.0 * t * t / dof : std::numeric_limits<double>::infinity();
  }
  const double n = double(film.pixels());
  e.value = sum / n;
  e.upper = e.value + 1.645 * std::sqrt(spread) / n;
  return e;
}

}  // namespace vkmc
