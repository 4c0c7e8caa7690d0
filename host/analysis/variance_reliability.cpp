#include "analysis/variance_reliability.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/error_metrics.h"

namespace vkmc {

VarianceReliability assessVarianceReliability(const Film& film) {
  constexpr uint32_t kSlots = gpu::kMaxSampleReplicates;
  const uint32_t R = std::min(film.replicates, kSlots);
  VarianceReliability out;
  double sumT = 0.0, sumVarT = 0.0, largestT = 0.0;
  for (size_t p = 0; p < film.pixels(); ++p) {
    double x[kSlots][3];
    bool complete = R >= 2;
    for (uint32_t r = 0; r < R && complete; ++r) {
      const uint64_t n = film.replicateCount[p * kSlots + r];
      complete = n > 0;
      for (int c = 0; c < 3 && complete; ++c) x[r][c] = film.replicateSum[(p * kSlots + r) * 3 + c] / double(n);
    }
    if (!complete) continue;
    double w[3];
    for (int c = 0; c < 3; ++c) {
      const double m = film.mean(p, c);
      w[c] = 1.0 / (m * m + kRelMseEpsilon);
    }
    auto h = [&](uint32_t a, uint32_t b) {
      double d = 0.0;
      for (int c = 0; c < 3; ++c) d += w[c] * (x[a][c] - x[b][c]) * (x[a][c] - x[b][c]);
      return 0.5 * d;
    };
    double u = 0.0, varU = 0.0;
    if (R == 4) {
      const double h01 = h(0, 1), h02 = h(0, 2), h03 = h(0, 3), h12 = h(1, 2), h13 = h(1, 3), h23 = h(2, 3);
      u = (h01 + h02 + h03 + h12 + h13 + h23) / 6.0;
      const double theta2 = (h01 * h23 + h02 * h13 + h03 * h12) / 3.0;
      varU = u * u - theta2;
    } else {
      for (uint32_t a = 0; a < R; ++a)
        for (uint32_t b = a + 1; b < R; ++b) u += h(a, b);
      u /= double(R * (R - 1) / 2);
      varU = u * u;  // E[U^2] = Var(U) + E[U]^2: an upper bound with no disjoint pairs to estimate E[U]^2 from
    }
    const double t = u / R;  // sum over channels of w_c times the variance of the pixel mean
    sumT += t;
    sumVarT += varU / double(R * R);
    largestT = std::max(largestT, t);
    ++out.pixelsAssessed;
  }
  const double terms = 3.0 * double(std::max<size_t>(1, film.pixels()));
  out.relVariance = sumT / terms;
  out.relativeStandardError = sumT > 0.0 ? std::sqrt(std::max(0.0, sumVarT)) / sumT : std::numeric_limits<double>::infinity();
  out.largestPixelShare = sumT > 0.0 ? largestT / sumT : 0.0;
  return out;
}

}  // namespace vkmc
