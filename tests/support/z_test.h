// The one z-test of the statistical tests: an estimate against an expected value, or two independent estimates,
// their difference measured in standard errors, with a readable message for gtest failures.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace vkmc::test {

struct ZTest {
  double estimate = 0.0;  // two-sample: the first estimate
  double expected = 0.0;  // two-sample: the second estimate
  double sigma = 0.0;     // standard error of estimate - expected
  double slack = 0.0;     // absolute allowance beyond the noise (float rounding), where a test needs one

  double difference() const { return estimate - expected; }
  double z() const { return difference() / sigma; }
  // |difference| <= k sigma + slack, compared as EXPECT_NEAR compares.
  bool within(double k) const { return std::abs(difference()) <= k * sigma + slack; }
  // |z| < k, for tests stated as a bound on z.
  bool below(double k) const { return std::abs(z()) < k; }
  // estimate <= expected + k sigma: one-sided, for upper bounds such as energy conservation.
  bool atMost(double k) const { return estimate <= expected + k * sigma; }

  std::string describe(double k) const {
    std::ostringstream s;
    s.precision(8);
    s << estimate << " against " << expected << ": difference " << difference() << ", sigma " << sigma << ", z = " << z()
      << " (bound " << k << " sigma";
    if (slack != 0.0) s << " + " << slack;
    s << ")";
    return s.str();
  }
};

// One sample: an estimate with standard error `sigma` against an exact value.
inline ZTest zTest(double estimate, double expected, double sigma, double slack = 0.0) {
  return {estimate, expected, sigma, slack};
}

// Two independent estimates, each with the variance of its mean.
inline ZTest zTest2(double a, double varianceA, double b, double varianceB, double slack = 0.0) {
  return {a, b, std::sqrt(varianceA + varianceB), slack};
}

// The mean of n samples from their sum and sum of squares, and its standard error.
struct SampleMean {
  double mean = 0.0, sigma = 0.0;
};
inline SampleMean sampleMean(double sum, double sumSq, double n) {
  double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sumSq / n - mean * mean) / n)};
}

// gtest forms: EXPECT_TRUE(withinSigmas(zTest(...), 5.0)) << what; the failure message gives z and the bound.
inline ::testing::AssertionResult withinSigmas(const ZTest& t, double k) {
  if (t.within(k)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << t.describe(k);
}
inline ::testing::AssertionResult belowSigmas(const ZTest& t, double k) {
  if (t.below(k)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << t.describe(k);
}
inline ::testing::AssertionResult atMostSigmas(const ZTest& t, double k) {
  if (t.atMost(k)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "one-sided: " << t.describe(k);
}

// The largest |z| over several tests (an estimate's colour channels); a test with sigma 0 has no noise to be
// measured against and is left out.
inline double maxAbsZ(const std::vector<ZTest>& tests) {
  double z = 0.0;
  for (const ZTest& t : tests)
    if (t.sigma > 0) z = std::max(z, std::abs(t.difference()) / t.sigma);
  return z;
}

// Passes when every test with noise has |z| < k; the message lists each test.
inline ::testing::AssertionResult allBelowSigmas(const std::vector<ZTest>& tests, double k) {
  if (maxAbsZ(tests) < k) return ::testing::AssertionSuccess();
  ::testing::AssertionResult r = ::testing::AssertionFailure();
  r << "largest |z| " << maxAbsZ(tests) << " not below " << k << ":";
  for (size_t i = 0; i < tests.size(); ++i)
    r << "\n  [" << i << "] " << (tests[i].sigma > 0 ? tests[i].describe(k) : "sigma 0: not tested");
  return r;
}

}  // namespace vkmc::test
