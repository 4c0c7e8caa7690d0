// Chi-square goodness-of-fit for direction samplers against their pdfs (after pbrt-v4 and Mitsuba 3): an odd-
// sized theta x phi grid over the sphere, the pdf integrated per cell with a sub-grid, cells expecting fewer
// than 5 samples pooled, failed samples (a sampler's rejected directions) in a bin of their own.
#pragma once
#include <glm/glm.hpp>

#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace vkmc::test {

// Regularized upper incomplete gamma Q(a, x) (Numerical Recipes' gammq).
inline double incompleteGammaQ(double a, double x) {
  if (x <= 0.0) return 1.0;
  double gln = std::lgamma(a);
  if (x < a + 1.0) {
    double ap = a, sum = 1.0 / a, del = sum;
    for (int n = 0; n < 10000; ++n) {
      ap += 1.0;
      del *= x / ap;
      sum += del;
      if (std::abs(del) < std::abs(sum) * 1e-15) break;
    }
    return 1.0 - sum * std::exp(-x + a * std::log(x) - gln);
  }
  double b = x + 1.0 - a, c = 1.0 / 1e-300, d = 1.0 / b, h = d;
  for (int i = 1; i < 10000; ++i) {
    double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < 1e-300) d = 1e-300;
    c = b + an / c;
    if (std::abs(c) < 1e-300) c = 1e-300;
    d = 1.0 / d;
    double del = d * c;
    h *= del;
    if (std::abs(del - 1.0) < 1e-15) break;
  }
  return std::exp(-x + a * std::log(x) - gln) * h;
}

struct Chi2Result {
  double statistic = 0.0;
  int dof = 0;
  double pValue = 1.0;
  double pdfIntegral = 0.0;  // integral of the pdf over the sphere
  double failedFraction = 0.0;
  std::string table;  // observed vs expected, for failure messages
};

// Pearson's test of observed against expected counts, pooling cells that expect fewer than 5.
inline Chi2Result chi2FromCounts(const std::vector<double>& observed, const std::vector<double>& expected) {
  Chi2Result r;
  std::vector<size_t> order(observed.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  double pooledObs = 0, pooledExp = 0;
  int cells = 0;
  std::ostringstream table;
  for (size_t i : order) {
    if (expected[i] < 5.0) {
      pooledObs += observed[i];
      pooledExp += expected[i];
      if (expected[i] == 0.0 && observed[i] > 0.0) {  // a sample where the pdf is zero: certain failure
        r.statistic = 1e300;
        table << "cell " << i << ": " << observed[i] << " samples where the pdf is 0\n";
      }
      continue;
    }
    double d = observed[i] - expected[i];
    r.statistic += d * d / expected[i];
    ++cells;
    if (std::abs(d) > 4.0 * std::sqrt(expected[i]))
      table << "cell " << i << ": observed " << observed[i] << " expected " << expected[i] << "\n";
  }
  if (pooledExp > 0.0) {
    double d = pooledObs - pooledExp;
    r.statistic += d * d / pooledExp;
    ++cells;
  }
  r.dof = std::max(1, cells - 1);
  r.pValue = r.statistic >= 1e300 ? 0.0 : incompleteGammaQ(0.5 * r.dof, 0.5 * r.statistic);
  r.table = table.str();
  return r;
}

// sample(index) returns a unit direction, or a zero vector for a failed sample; pdf(direction) is the
// solid-angle density the sampler claims.
inline Chi2Result chi2Sphere(const std::function<glm::vec3(uint32_t)>& sample, const std::function<double(glm::vec3)>& pdf,
                             uint32_t samples, int thetaBins = 21, int phiBins = 41, int subdiv = 12) {
  const double pi = 3.14159265358979323846;
  std::vector<double> observed(thetaBins * phiBins + 1, 0.0), expected(thetaBins * phiBins + 1, 0.0);
  uint32_t failed = 0;
  for (uint32_t i = 0; i < samples; ++i) {
    glm::vec3 w = sample(i);
    if (w == glm::vec3(0.0f)) {
      ++failed;
      continue;
    }
    double theta = std::acos(std::clamp(static_cast<double>(w.z), -1.0, 1.0));
    double phi = std::atan2(static_cast<double>(w.y), static_cast<double>(w.x));
    if (phi < 0) phi += 2 * pi;
    int t = std::min(thetaBins - 1, static_cast<int>(theta / pi * thetaBins));
    int p = std::min(phiBins - 1, static_cast<int>(phi / (2 * pi) * phiBins));
    observed[t * phiBins + p] += 1.0;
  }
  double integral = 0.0;
  for (int t = 0; t < thetaBins; ++t)
    for (int p = 0; p < phiBins; ++p) {
      double sum = 0.0;
      double dt = pi / thetaBins / subdiv, dp = 2 * pi / phiBins / subdiv;
      for (int a = 0; a < subdiv; ++a)
        for (int b = 0; b < subdiv; ++b) {
          double theta = (t * subdiv + a + 0.5) * dt, phi = (p * subdiv + b + 0.5) * dp;
          glm::vec3 w(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
          sum += pdf(w) * std::sin(theta) * dt * dp;
        }
      expected[t * phiBins + p] = sum * samples;
      integral += sum;
    }
  observed.back() = failed;
  expected.back() = std::max(0.0, 1.0 - integral) * samples;
  Chi2Result r = chi2FromCounts(observed, expected);
  r.pdfIntegral = integral;
  r.failedFraction = static_cast<double>(failed) / samples;
  return r;
}

// Significance for one of `tests` tests at an overall level of 1%, Sidak-corrected.
inline double sidakLevel(int tests) { return 1.0 - std::pow(1.0 - 0.01, 1.0 / tests); }

}  // namespace vkmc::test
