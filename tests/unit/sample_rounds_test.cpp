// Adaptive sampling's host side, without a GPU: the allocation's shape and limits, the round schedule, the relMSE
// estimate, and the round combination's unbiasedness on a simulated pixel whose samples are rare and bright. The
// plain sample mean over the same adaptive rounds (the classic trap: counts chosen from the pilot's own values)
// is shown biased on the same data, so the unbiasedness test has the power to see that bias.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "policy/round_film.h"
#include "policy/sample_allocation.h"
#include "policy/sample_rounds.h"
#include "policy/target_error.h"

using namespace vkmc;

TEST(SampleAllocation, FollowsTheSquareRootOfRelativeVarianceWithinItsLimits) {
  std::vector<double> v(100, 1.0);
  for (int p = 50; p < 100; ++p) v[p] = 16.0;
  const std::vector<uint32_t> n = allocateSamples(v, {}, 100 * 10, AllocationLimits{2, 2, 0.0, 8.0, 0.0});
  // sqrt(16) = 4 times as many: 4 and 16 a pixel for a mean of 10.
  EXPECT_EQ(n[0], 4u);
  EXPECT_EQ(n[99], 16u);
  EXPECT_EQ(std::accumulate(n.begin(), n.end(), 0ull), 1000ull);
  for (uint32_t c : n) EXPECT_EQ(c % 2, 0u);
  // A dark pixel keeps the minimum; a noisy one stops at the cap (8x the mean).
  v.assign(100, 0.0);
  v[7] = 1.0;
  const std::vector<uint32_t> capped = allocateSamples(v, {}, 100 * 10, AllocationLimits{2, 2, 0.0, 8.0, 0.0});
  EXPECT_EQ(capped[7], 80u);
  EXPECT_EQ(std::accumulate(capped.begin(), capped.end(), 0u), 1000u);  // the rest spread over the quiet pixels
  EXPECT_LE(*std::max_element(capped.begin(), capped.begin() + 7), 10u);
  // Cost: a pixel four times as costly gets half the samples of one as noisy.
  const std::vector<uint32_t> costly =
      allocateSamples(std::vector<double>(2, 1.0), {4.0, 1.0}, 60, AllocationLimits{1, 1, 0.0, 8.0, 0.0});
  EXPECT_EQ(costly[0], 20u);
  EXPECT_EQ(costly[1], 40u);
  // The defensive floor: a quarter of a mean of 40, 10.
  v[8] = 1e-6;  // quiet, but not silent: at the floor
  const std::vector<uint32_t> floored2 = allocateSamples(v, {}, 100 * 40, AllocationLimits{2, 2, 0.25, 8.0, 0.0});
  EXPECT_EQ(floored2[7], 320u);
  EXPECT_GE(*std::min_element(floored2.begin(), floored2.end()), 10u);
  EXPECT_EQ(std::accumulate(floored2.begin(), floored2.end(), 0u), 4000u);
  // The budget met exactly: counts that do not divide evenly get one multiple more by their remainders.
  const std::vector<uint32_t> exact = allocateSamples({1.0, 1.0, 1.0}, {}, 8, AllocationLimits{2, 2, 0.0, 8.0, 0.0});
  EXPECT_EQ(std::accumulate(exact.begin(), exact.end(), 0u), 8u);
  // No variance anywhere: uniform.
  const std::vector<uint32_t> flat = allocateSamples(std::vector<double>(10, 0.0), {}, 80, AllocationLimits{2, 2, 0.0, 8.0, 0.0});
  for (uint32_t c : flat) EXPECT_EQ(c, 8u);
}

TEST(SampleAllocation, SmoothsRelativeVarianceOverNeighbours) {
  std::vector<glm::dvec3> mean(9, glm::dvec3(1.0)), var(9, glm::dvec3(0.0));
  var[4] = glm::dvec3(9.0 * 1.01);  // epsilon 0.01: relative variance 9 at the centre
  const std::vector<double> s = smoothedRelativeVariance(mean, var, 3, 3, 0.01);
  EXPECT_NEAR(s[4], 1.0, 1e-12);        // the centre's 9 over its 9 neighbours
  EXPECT_NEAR(s[0], 9.0 / 4.0, 1e-12);  // a corner sees 4 pixels
}

TEST(SampleRounds, ScheduleDoublesToTheSampleCount) {
  SampleRoundsPlan plan;
  plan.spp = 64;
  std::vector<uint32_t> sizes;
  for (uint32_t done = 0, s; (s = nextRoundSpp(plan, done, 2, {}, 0.0, 0.0)) > 0; done += s) sizes.push_back(s);
  EXPECT_EQ(sizes, (std::vector<uint32_t>{8, 8, 16, 32}));
  // A target error: no more than the estimate predicts (relMSE ~ 1/samples), rounded to the replicates.
  plan.spp = 1u << 20;
  plan.targetError = 0.01;
  EXPECT_EQ(nextRoundSpp(plan, 64, 2, RelMseEstimate{0.012, 0.0125}, 0.0, 0.0), 18u);  // 64 * 0.25 * 1.05 = 16.8
  EXPECT_EQ(nextRoundSpp(plan, 64, 2, RelMseEstimate{0.01, 0.0101}, 0.0, 0.0), 16u);   // at least a quarter
  // A time budget: no more than fits in what is left.
  plan.targetError = 0.0;
  plan.timeBudget = 10.0;
  EXPECT_EQ(nextRoundSpp(plan, 64, 2, {}, 3.0, 0.5), 6u);
  EXPECT_EQ(nextRoundSpp(plan, 0, 2, {}, 10.0, 0.0), 4u);  // the first round measures the pace
  plan.passSpp = 7;                                        // rounds fill passes: multiples of 14
  EXPECT_EQ(nextRoundSpp(plan, 0, 2, {}, 10.0, 0.0), 14u);
  EXPECT_EQ(nextRoundSpp(plan, 14, 2, {}, 100.0, 0.5), 14u);
}

namespace {

// A pixel whose sample is 10 with probability 0.05, else 0: mean 0.5, and most first rounds see only zeros.
double drawSample(std::mt19937& rng) { return std::uniform_real_distribution<double>(0.0, 1.0)(rng) < 0.05 ? 10.0 : 0.0; }

// One round's film from per-pixel counts (grey samples; replicates by sample number, as the device assigns them).
Film simulateRound(const std::vector<uint32_t>& counts, std::vector<uint32_t>& next, std::mt19937& rng,
                   std::vector<double>& pooledSum, std::vector<double>& pooledCount) {
  Film f(uint32_t(counts.size()), 1);
  f.replicates = 2, f.replicateVariance = true;
  for (size_t p = 0; p < counts.size(); ++p)
    for (uint32_t s = 0; s < counts[p]; ++s) {
      const double x = drawSample(rng);
      const uint32_t r = (next[p] + s) % 2;
      for (int c = 0; c < 3; ++c) {
        f.sum[3 * p + c] += x, f.sumSq[3 * p + c] += x * x;
        f.replicateSum[(p * gpu::kMaxSampleReplicates + r) * 3 + c] += x;
      }
      f.count[p] += 1, f.replicateCount[p * gpu::kMaxSampleReplicates + r] += 1;
      pooledSum[p] += x, pooledCount[p] += 1;
    }
  for (size_t p = 0; p < counts.size(); ++p) next[p] += counts[p];
  return f;
}

struct Trial {
  std::vector<double> estimate, variance, replicateVariance, pooled;
};

// Rounds of 4, 4 and 8 samples a pixel on average, the later two allocated from the earlier ones (no defensive
// floor: the allocation as uneven as it gets, which is what makes the pooled mean's bias plain).
Trial simulateAdaptiveRender(uint32_t pixels, std::mt19937& rng) {
  RoundFilm independent(pixels, 1, 2, false), replicated(pixels, 1, 2, true);
  std::vector<uint32_t> next(pixels, 0);
  std::vector<double> pooledSum(pixels, 0.0), pooledCount(pixels, 0.0);
  uint32_t done = 0;
  for (uint32_t spp : {4u, 4u, 8u}) {
    std::vector<uint32_t> counts(pixels, spp);
    if (independent.rounds() > 0) {
      std::vector<double> rel(pixels);
      const auto m = independent.means();
      const auto v = independent.sampleVariances();
      for (uint32_t p = 0; p < pixels; ++p) rel[p] = v[p].x / (m[p].x * m[p].x + 0.01);
      counts = allocateSamples(rel, {}, uint64_t(spp) * pixels, AllocationLimits{2, 2, 0.0, 8.0, 0.0});
    }
    const Film round = simulateRound(counts, next, rng, pooledSum, pooledCount);
    const double later = 16.0 - done - spp;  // the plan: 16 samples a pixel on average
    std::vector<double> w(pixels);
    for (uint32_t p = 0; p < pixels; ++p)
      w[p] = roundWeight(independent.weightSoFar(p), counts[p], double(counts[p]) / spp * later, later <= 0.0);
    independent.addRound(round, w);
    replicated.addRound(round, w);
    done += spp;
  }
  for (uint32_t p = 0; p < pixels; ++p) EXPECT_NEAR(independent.weightSoFar(p), 1.0, 1e-12);
  Trial t;
  const Film a = independent.image(), b = replicated.image();
  for (uint32_t p = 0; p < pixels; ++p) {
    t.estimate.push_back(a.mean(p, 0));
    EXPECT_DOUBLE_EQ(a.mean(p, 0), b.mean(p, 0));
    t.variance.push_back(a.varianceOfMean(p, 0));
    t.replicateVariance.push_back(b.varianceOfMean(p, 0));
    t.pooled.push_back(pooledSum[p] / pooledCount[p]);
  }
  return t;
}

struct Moments {
  double mean = 0.0, standardError = 0.0;
};
Moments moments(const std::vector<double>& x) {
  Moments m;
  for (double v : x) m.mean += v;
  m.mean /= double(x.size());
  double ss = 0.0;
  for (double v : x) ss += (v - m.mean) * (v - m.mean);
  m.standardError = std::sqrt(ss / double(x.size() - 1) / double(x.size()));
  return m;
}

}  // namespace

TEST(RoundFilm, AdaptiveRoundsStayUnbiasedWhereThePooledMeanIsNot) {
  std::mt19937 rng(12345);
  std::vector<double> estimate, variance, replicateVariance, pooled;
  for (int trial = 0; trial < 400; ++trial) {
    Trial t = simulateAdaptiveRender(256, rng);
    estimate.insert(estimate.end(), t.estimate.begin(), t.estimate.end());
    variance.insert(variance.end(), t.variance.begin(), t.variance.end());
    replicateVariance.insert(replicateVariance.end(), t.replicateVariance.begin(), t.replicateVariance.end());
    pooled.insert(pooled.end(), t.pooled.begin(), t.pooled.end());
  }
  const Moments e = moments(estimate), trap = moments(pooled);
  EXPECT_LT(std::abs(e.mean - 0.5), 5.0 * e.standardError) << "weighted rounds: " << e.mean << " +- " << e.standardError;
  EXPECT_GT(std::abs(trap.mean - 0.5), 5.0 * trap.standardError) << "the pooled mean: " << trap.mean;
  // The variance each pixel reports is the spread of its estimate: the mean reported variance against the
  // measured variance of the estimates (pixels are independent and alike), within 5 combined standard errors.
  std::vector<double> squared;
  for (double x : estimate) squared.push_back((x - 0.5) * (x - 0.5));
  const Moments measured = moments(squared);
  for (const std::vector<double>* reported : {&variance, &replicateVariance}) {
    const Moments r = moments(*reported);
    EXPECT_LT(std::abs(r.mean - measured.mean), 5.0 * std::hypot(r.standardError, measured.standardError))
        << "reported " << r.mean << " measured " << measured.mean;
  }
}

TEST(RoundFilm, WeightsOfUnchangingCountsAreThePlainMean) {
  // 8, 8, 16 and 32 samples: each round's share of 64.
  double so = 0.0;
  const double later[] = {56, 48, 32, 0};
  const double samples[] = {8, 8, 16, 32};
  for (int r = 0; r < 4; ++r) {
    const double w = roundWeight(so, samples[r], later[r], later[r] == 0.0);
    EXPECT_NEAR(w, samples[r] / 64.0, 1e-15);
    so += w;
  }
  EXPECT_NEAR(so, 1.0, 1e-15);
  // A planned last round takes what is left; a pixel whose count rises later gave its early rounds less.
  EXPECT_DOUBLE_EQ(roundWeight(0.75, 4, 100, true), 0.25);
  EXPECT_DOUBLE_EQ(roundWeight(0.0, 8, 120, false), 8.0 / 128.0);
}

TEST(SampleRounds, PlansTheSamplesLeftFromWhatIsKnown) {
  SampleRoundsPlan plan;
  plan.spp = 64;
  EXPECT_EQ(plannedLaterSpp(plan, 16, 16, {}, 0.0, 0.0), 32.0);
  EXPECT_EQ(plannedLaterSpp(plan, 32, 32, {}, 0.0, 0.0), 0.0);
  plan.spp = 1u << 20;
  plan.targetError = 0.01;
  EXPECT_EQ(plannedLaterSpp(plan, 0, 8, {}, 0.0, 0.0), 56.0);                      // the first round: an eighth
  EXPECT_NEAR(plannedLaterSpp(plan, 64, 64, {0.0, 0.04}, 0.0, 0.0), 128.0, 1e-9);  // 0.04 * 64 / 0.01 - 128
  EXPECT_EQ(plannedLaterSpp(plan, 64, 8, {0.0, 0.0101}, 0.0, 0.0), 72.0);          // never less than what is done
  plan.targetError = 0.0;
  plan.timeBudget = 10.0;
  EXPECT_EQ(plannedLaterSpp(plan, 64, 64, {}, 4.0, 0.5), 8.0);
}

TEST(TargetError, EstimatesRelMseAndBoundsIt) {
  Film f(2, 1);
  f.replicateVariance = false;
  // Pixel 0: 4 samples of 1 and 3 (mean 2, sample variance 4/3, of the mean 1/3); pixel 1: no spread.
  for (double x : {1.0, 3.0, 1.0, 3.0})
    for (int c = 0; c < 3; ++c) f.sum[c] += x, f.sumSq[c] += x * x;
  f.count[0] = 4;
  for (int c = 0; c < 3; ++c) f.sum[3 + c] = 4.0, f.sumSq[3 + c] = 4.0;
  f.count[1] = 4;
  const RelMseEstimate e = estimateRelMse(f, 0.01);
  const double t0 = (1.0 / 3.0) / (4.0 - 1.0 / 3.0 + 0.01);  // the mean's square less its variance
  Film dark = f;  // a pixel whose variance passes half its squared mean: the square halved, no further
  for (int c = 0; c < 3; ++c) dark.sum[c] = 0.4, dark.sumSq[c] = 4.0 * (2.0 / 3.0 * 3.0 + 0.01);
  const double m = 0.1, v = (dark.sumSq[0] - 4.0 * m * m) / 3.0 / 4.0;
  EXPECT_NEAR(estimateRelMse(dark, 0.01).value, (v / (0.5 * m * m + 0.01)) / 2.0, 1e-12);
  EXPECT_NEAR(e.value, t0 / 2.0, 1e-12);
  EXPECT_NEAR(e.upper, t0 / 2.0 + 1.645 * std::sqrt(2.0 * t0 * t0 * (1.0 / 3.0 + 1.0)) / 2.0, 1e-12);
}
