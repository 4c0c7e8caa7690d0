#include "analysis/student_t.h"

#include <cmath>
#include <limits>

namespace vkmc {

double regularizedIncompleteBeta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  if (x > (a + 1.0) / (a + b + 2.0)) return 1.0 - regularizedIncompleteBeta(b, a, 1.0 - x);  // converges faster
  const double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x));
  const double tiny = 1e-300;
  auto guard = [&](double v) { return std::abs(v) < tiny ? tiny : v; };
  double c = 1.0, d = 1.0 / guard(1.0 - (a + b) * x / (a + 1.0)), f = d;
  for (int m = 1; m < 100000; ++m) {
    const double even = m * (b - m) * x / ((a + 2.0 * m - 1.0) * (a + 2.0 * m));
    d = 1.0 / guard(1.0 + even * d);
    c = guard(1.0 + even / c);
    f *= c * d;
    const double odd = -(a + m) * (a + b + m) * x / ((a + 2.0 * m) * (a + 2.0 * m + 1.0));
    d = 1.0 / guard(1.0 + odd * d);
    c = guard(1.0 + odd / c);
    const double delta = c * d;
    f *= delta;
    if (std::abs(delta - 1.0) < 1e-15) break;
  }
  return front * f / a;
}

double studentTwoSidedTail(double t, double dof) {
  if (!(dof < 1e7)) return std::erfc(std::abs(t) / std::sqrt(2.0));  // the normal, where t and z agree to 1e-7
  return regularizedIncompleteBeta(0.5 * dof, 0.5, dof / (dof + t * t));
}

double studentBoundForSigmas(double k, double dof) {
  const double p = std::erfc(k / std::sqrt(2.0));
  double lo = k, hi = k;
  while (studentTwoSidedTail(hi, dof) > p) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-9 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (studentTwoSidedTail(mid, dof) > p ? lo : hi) = mid;
  }
  return hi;
}

double welchDof(double va, double dofA, double vb, double dofB) {
  const double den = (dofA > 0 ? va * va / dofA : 0.0) + (dofB > 0 ? vb * vb / dofB : 0.0);
  if (den <= 0.0) return std::numeric_limits<double>::infinity();
  return (va + vb) * (va + vb) / den;
}

}  // namespace vkmc
