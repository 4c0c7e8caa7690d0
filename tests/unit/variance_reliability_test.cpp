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
// A film whose pixels have one sample in each replicate (replicate mean = the sample), grey, from `draw`.
template <class Draw>
Film filmOf(uint32_t w, uint32_t h, Draw&& draw) {
  Film f(w, h);
  constexpr uint32_t R = gpu::kSampleReplicates;
  for (size_t p = 0; p < f.pixels(); ++p) {
    for (uint32_t r = 0; r < R; ++r) {
      const double v = draw(p, r);
      f.replicateCount[p * R + r] = 1;
      for (int c = 0; c < 3; ++c) {
        f.replicateSum[(p * R + r) * 3 + c] = v;
        f.sum[3 * p + c] += v;
        f.sumSq[3 * p + c] += v * v;
      }
    }
    f.count[p] = R;
  }
  f.replicateVariance = true;
  return f;
}
}  // namespace

TEST(VarianceReliability, ItsStandardErrorMatchesTheSpreadOverFilms) {
  // Skewed, heavy-ish noise (exponential, excess kurtosis 6) around 0, small enough that the weights
  // 1 / (mean^2 + 0.01) hardly move: the test isolates the U-statistic. 1000 films of 1024 pixels, fixed seed.
  std::mt19937_64 rng(2026);
  std::exponential_distribution<double> e(1.0);
  const int films = 1000;
  double sum = 0, sumSq = 0, reportedVar = 0;
  for (int i = 0; i < films; ++i) {
    Film f = filmOf(32, 32, [&](size_t, uint32_t) { return 0.01 * (e(rng) - 1.0); });
    VarianceReliability v = assessVarianceReliability(f);
    sum += v.relVariance;
    sumSq += v.relVariance * v.relVariance;
    reportedVar += std::pow(v.relativeStandardError * v.relVariance, 2) / films;
  }
  const double mean = sum / films, observedVar = (sumSq / films - mean * mean) * films / (films - 1.0);
  // The observed variance over 1000 films is itself uncertain by sqrt(2 / 999) = 4.5% for normal spreads (the
  // films' estimate is near normal: 1024 pixels): a 25% band is 5.5 of those.
  EXPECT_NEAR(reportedVar / observedVar, 1.0, 0.25) << "reported " << reportedVar << ", observed " << observedVar;
  std::printf("reported / observed variance of mean_relvariance: %.3f\n", reportedVar / observedVar);
}

TEST(VarianceReliability, PlainNoiseIsReliableAndOneRareHugeSampleIsNot) {
  // Plain noise of 0.5% around 1 (each pixel's relative variance of its mean ~6e-6), then one sample of 1e4:
  // that pixel's relative variance is ~1 whatever the others do, so it holds ~97% of the estimate.
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n(1.0, 0.005);
  Film plain = filmOf(64, 64, [&](size_t, uint32_t) { return n(rng); });
  VarianceReliability a = assessVarianceReliability(plain);
  EXPECT_TRUE(a.reliable()) << a.relativeStandardError;
  EXPECT_EQ(a.pixelsAssessed, 64u * 64u);
  EXPECT_LT(a.largestPixelShare, 0.01);
  // The same film with one sample 1e4 times the others (a firefly): that pixel is most of the estimate.
  Film firefly = filmOf(64, 64, [&](size_t p, uint32_t r) { return p == 1000 && r == 2 ? 1e4 : n(rng); });
  VarianceReliability b = assessVarianceReliability(firefly);
  EXPECT_FALSE(b.reliable()) << b.relativeStandardError;
  EXPECT_GT(b.largestPixelShare, 0.9);
  // A pixel missing a replicate (fewer samples than replicates) is left out, not guessed.
  Film partial = plain;
  partial.replicateCount[0] = 0;
  EXPECT_EQ(assessVarianceReliability(partial).pixelsAssessed, 64u * 64u - 1u);
}
