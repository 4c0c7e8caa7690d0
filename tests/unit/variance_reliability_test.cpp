// The report's reliability figure for its variance estimate (analysis/variance_reliability.h): its standard error
// is calibrated (over many synthetic films, the reported variance of mean_relvariance matches the spread of
// mean_relvariance itself), and one pixel's rare huge sample makes it unreliable while plain noise does not.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "analysis/variance_reliability.h"

using namespace vkmc;

namespace {
// A film whose pixels have one sample in each of R replicates (replicate mean = the sample), grey, from `draw`.
template <class Draw>
Film filmOf(uint32_t w, uint32_t h, uint32_t R, Draw&& draw) {
  Film f(w, h);
  constexpr uint32_t kSlots = gpu::kMaxSampleReplicates;
  f.replicates = R;
  for (size_t p = 0; p < f.pixels(); ++p) {
    for (uint32_t r = 0; r < R; ++r) {
      const double v = draw(p, r);
      f.replicateCount[p * kSlots + r] = 1;
      for (int c = 0; c < 3; ++c) {
        f.replicateSum[(p * kSlots + r) * 3 + c] = v;
        f.sum[3 * p + c] += v;
        f.sumSq[3 * p + c] += v * v;
      }
    }
    f.count[p] = R;
  }
  f.replicateVariance = true;
  return f;
}

class VarianceReliabilityOf : public ::testing::TestWithParam<uint32_t> {};  // the replicates per pixel
}  // namespace

TEST_P(VarianceReliabilityOf, ItsStandardErrorMatchesTheSpreadOverFilms) {
  // Skewed, heavy-ish noise (exponential, excess kurtosis 6) around 0, small enough that the weights
  // 1 / (mean^2 + 0.01) hardly move: the test isolates the U-statistic. 1000 films of 1024 pixels, fixed seed.
  // With 4 replicates the variance of the estimate is unbiased: ratio 1. With 2 or 3 it is the upper bound
  // E[U^2] = Var(U) + E[U]^2 (variance_reliability.h). For unit exponentials (4th central moment 9), h = (Xa - Xb)^2 / 2
  // has E[h] = 1, Var(h) = 5 and Cov(h_ab, h_ac) = 2, so Var(U) = 5 with 2 replicates and (2 / 6)(2 * 2 + 5) = 3
  // with 3: expected ratios 6 / 5 and 4 / 3.
  const uint32_t R = GetParam();
  const double expected = R == 4 ? 1.0 : R == 3 ? 4.0 / 3.0 : 1.2;
  std::mt19937_64 rng(2026);
  std::exponential_distribution<double> e(1.0);
  const int films = 1000;
  double sum = 0, sumSq = 0, reportedVar = 0;
  for (int i = 0; i < films; ++i) {
    Film f = filmOf(32, 32, R, [&](size_t, uint32_t) { return 0.01 * (e(rng) - 1.0); });
    VarianceReliability v = assessVarianceReliability(f);
    sum += v.relVariance;
    sumSq += v.relVariance * v.relVariance;
    reportedVar += std::pow(v.relativeStandardError * v.relVariance, 2) / films;
  }
  const double mean = sum / films, observedVar = (sumSq / films - mean * mean) * films / (films - 1.0);
  // The observed variance over 1000 films is itself uncertain by sqrt(2 / 999) = 4.5% for normal spreads (the
  // films' estimate is near normal: 1024 pixels): a 25% band is 5.5 of those.
  EXPECT_NEAR(reportedVar / observedVar, expected, 0.25) << "reported " << reportedVar << ", observed " << observedVar;
  // The bound of 2 or 3 replicates is an upper bound: above 1 (by 4 of the observed variance's 4.5% errors).
  if (R < 4) {
    EXPECT_GT(reportedVar / observedVar, 1.0) << "an upper bound below the observed variance";
  }
  std::printf("%u replicates: reported / observed variance of mean_relvariance: %.3f (expected %.1f)\n", R,
              reportedVar / observedVar, expected);
}

TEST_P(VarianceReliabilityOf, PlainNoiseIsReliableAndOneRareHugeSampleIsNot) {
  const uint32_t R = GetParam();
  // Plain noise of 0.5% around 1 (each pixel's relative variance of its mean ~6e-6), then one sample of 1e4:
  // that pixel's relative variance is ~1 whatever the others do, so it holds ~97% of the estimate.
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n(1.0, 0.005);
  Film plain = filmOf(64, 64, R, [&](size_t, uint32_t) { return n(rng); });
  VarianceReliability a = assessVarianceReliability(plain);
  EXPECT_TRUE(a.reliable()) << a.relativeStandardError;
  EXPECT_EQ(a.pixelsAssessed, 64u * 64u);
  EXPECT_LT(a.largestPixelShare, 0.01);
  // The same film with one sample 1e4 times the others (a firefly): that pixel is most of the estimate.
  Film firefly = filmOf(64, 64, R, [&](size_t p, uint32_t r) { return p == 1000 && r == R - 1 ? 1e4 : n(rng); });
  VarianceReliability b = assessVarianceReliability(firefly);
  EXPECT_FALSE(b.reliable()) << b.relativeStandardError;
  EXPECT_GT(b.largestPixelShare, 0.9);
  // A pixel missing a replicate (fewer samples than replicates) is left out, not guessed.
  Film partial = plain;
  partial.replicateCount[0] = 0;
  EXPECT_EQ(assessVarianceReliability(partial).pixelsAssessed, 64u * 64u - 1u);
}

INSTANTIATE_TEST_SUITE_P(Replicates, VarianceReliabilityOf, ::testing::Values(2u, 3u, 4u));
