// EARS's pure functions (shaders/shared/ears.h), the image statistic its factors are scaled by
// (host/passes/ears_image_statistics.h) and its guard's measure and choice (host/passes/ears_guard.h).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "../shaders/shared/ears.h"
#include "../shaders/shared/roulette.h"
#include "analysis/error_metrics.h"
#include "error.h"
#include "passes/ears_guard.h"
#include "passes/ears_image_statistics.h"

using namespace vkmc;
using namespace vkmc::gpu;

TEST(EarsFactor, SecondMomentDecidesRouletteVarianceDecidesSplitting) {
  // t^2 E[Lr^2] / C = 0.25 in every channel, image factor 1: q = 0.5, roulette.
  EXPECT_FLOAT_EQ(earsFactor(vec3(1.0f), vec3(0.25f), vec3(0.2f), 1.0f), 0.5f);
  // The moment says split (q 3) and so does the variance (q 2): the variance's factor.
  EXPECT_FLOAT_EQ(earsFactor(vec3(1.0f), vec3(9.0f), vec3(4.0f), 1.0f), 2.0f);
  // The moment says split, the variance says roulette (a nearly constant Lr): the vertex is kept as it is.
  EXPECT_FLOAT_EQ(earsFactor(vec3(1.0f), vec3(9.0f), vec3(0.01f), 1.0f), 1.0f);
  // Channels average under the root: t = (2, 0, 0) and moments 1 give sqrt(4 / 3).
  EXPECT_NEAR(earsFactor(vec3(2.0f, 0.0f, 0.0f), vec3(1.0f), vec3(1.0f), 1.0f), std::sqrt(4.0f / 3.0f), 1e-6f);
  // The image factor scales both: roulette 0.25 at half, and at three times the moment's 1.5 and the variance's
  // 3 sqrt(0.2) both split, by the variance's.
  EXPECT_FLOAT_EQ(earsFactor(vec3(1.0f), vec3(0.25f), vec3(0.2f), 0.5f), 0.25f);
  EXPECT_FLOAT_EQ(earsFactor(vec3(1.0f), vec3(0.25f), vec3(0.2f), 3.0f), 3.0f * std::sqrt(0.2f));
}

TEST(EarsShrunk, ALevelCountsByItsCopiesAgainstTheCoarserOnes) {
  const vec3 coarse(4.0f), fine(1.0f);
  // Nothing coarser learned: the level as it is.
  EXPECT_EQ(earsShrunk(vec3(0.0f), 0.0f, fine, 3.0f), fine);
  // No copies at this level: the coarser; kEarsShrinkCopies of them: halfway; many: nearly the level's own.
  EXPECT_EQ(earsShrunk(coarse, 5000.0f, fine, 0.0f), coarse);
  EXPECT_FLOAT_EQ(earsShrunk(coarse, 5000.0f, fine, kEarsShrinkCopies).x, 2.5f);
  EXPECT_NEAR(earsShrunk(coarse, 5000.0f, fine, 1e6f).x, 1.0f, 0.01f);
  // A fine cell that has not yet met the rare bright paths (moment 1 where its region's is 4) is not taken at
  // its word after a few hundred copies: the moment that decides roulette stays well above 1.
  EXPECT_GT(earsShrunk(coarse, 5000.0f, fine, 256.0f).x, 3.0f);
}

TEST(EarsResolve, TheFoldShrinksALevelsSumsAsAVertexReadingThemOneByOneWould) {
  // Sums of n copies with mean Lr a, mean Lr^2 b, mean rays c: earsSampling gives b / c and (b - a^2) / c.
  auto sums = [](float n, float a, float b, float c) { return std::make_pair(vec4(vec3(a * n), n), vec4(vec3(b * n), c * n)); };
  const auto coarse = sums(5000.0f, 1.0f, 4.0f, 2.0f), mid = sums(0.0f, 0.0f, 0.0f, 0.0f), fine = sums(300.0f, 0.5f, 1.0f, 2.0f);
  vec3 moment(0.0f), variance(0.0f);
  float copies = 0.0f;
  for (const auto& level : {coarse, mid, fine}) earsResolveLevel(level.first, level.second, moment, variance, copies);
  // The empty middle level is skipped; the fine one counts 300 copies against kEarsShrinkCopies.
  EXPECT_FLOAT_EQ(moment.x, earsShrunk(vec3(2.0f), 5000.0f, vec3(0.5f), 300.0f).x);
  EXPECT_FLOAT_EQ(variance.y, earsShrunk(vec3(1.5f), 5000.0f, vec3(0.375f), 300.0f).y);
  EXPECT_FLOAT_EQ(copies, 5000.0f);  // the most of any level: trusted though the fine cell alone is not
  // A slot resolved for another key (the table's slots collide) is not read as this key's.
  const uint key = earsCellKey(vec3(0.3f, 0.2f, 0.1f), vec3(0.0f, 1.0f, 0.0f), vec4(0.0f, 0.0f, 0.0f, 10.0f));
  EXPECT_TRUE(earsResolvedFor(vec4(variance, float(key + 1u)), key));
  EXPECT_FALSE(earsResolvedFor(vec4(variance, float(key + 2u)), key));
  EXPECT_FALSE(earsResolvedFor(vec4(variance, 0.0f), key));  // never resolved
}

TEST(EarsFactor, ClampedToEarsRange) {
  EXPECT_FLOAT_EQ(earsFactor(vec3(1e-6f), vec3(1.0f), vec3(1.0f), 1.0f), kEarsFactorMin);
  EXPECT_FLOAT_EQ(earsFactor(vec3(1e6f), vec3(1.0f), vec3(1.0f), 1.0f), kEarsFactorMax);
  EXPECT_FLOAT_EQ(earsFactor(vec3(0.0f), vec3(0.0f), vec3(0.0f), 0.0f), kEarsFactorMin);  // nothing to gain: roulette
}

TEST(EarsFactor, NanCellsLeaveTheVertexAsItIs) {
  const float nan = std::nanf("");
  EXPECT_FLOAT_EQ(earsFactor(vec3(1.0f), vec3(nan), vec3(nan), 1.0f), 1.0f);
}

TEST(SplitCount, NeverMoreThanCeilQAndMeanQ) {
  // The largest u the samplers return is 1 - 2^-24; floor(q + u) in float would give q + 1 for a whole q
  // (the pool reserves ceil(q) - 1 slots beside the path's own).
  const float uMax = 1.0f - 1.0f / 16777216.0f;
  for (float q : {0.05f, 0.5f, 1.0f, 2.0f, 2.5f, 19.99f, 20.0f}) {
    EXPECT_LE(splitCount(q, uMax), uint(std::ceil(q))) << q;
    EXPECT_GE(splitCount(q, 0.0f), uint(std::floor(q))) << q;
    double mean = 0.0;
    const int n = 1 << 16;
    for (int i = 0; i < n; ++i) mean += splitCount(q, (i + 0.5f) / n);
    EXPECT_NEAR(mean / n, q, 1e-4) << q;
  }
}

TEST(EarsSampling, MomentsPerCostFromTheSums) {
  // Three copies with Lr 1, 2, 3 (red), rays 2, 4, 6.
  vec4 sum(6.0f, 0.0f, 0.0f, 3.0f), squares(14.0f, 0.0f, 0.0f, 12.0f), moment, variance;
  earsSampling(sum, squares, moment, variance);
  const float cost = 4.0f, second = 14.0f / 3.0f, var = second - 4.0f;
  EXPECT_FLOAT_EQ(moment.x, second / cost);
  EXPECT_FLOAT_EQ(moment.w, 3.0f);
  EXPECT_NEAR(variance.x, var / cost, 1e-6f);
  EXPECT_FLOAT_EQ(variance.w, cost);
  EXPECT_FLOAT_EQ(moment.y, 0.0f);
  // No copies, or copies that cost nothing: nothing to decide with (the factor's fallback reads w).
  earsSampling(vec4(0.0f), vec4(0.0f), moment, variance);
  EXPECT_EQ(moment, vec4(0.0f));
  earsSampling(vec4(1.0f, 1.0f, 1.0f, 2.0f), vec4(1.0f, 1.0f, 1.0f, 0.0f), moment, variance);
  EXPECT_EQ(vec3(moment), vec3(0.0f));
  EXPECT_FLOAT_EQ(moment.w, 2.0f);
}

TEST(EarsFactor, RelativeThroughputUsesRelMsesEpsilon) { EXPECT_NEAR(double(kEarsEpsilon), kRelMseEpsilon, 1e-9); }

TEST(EarsCell, GridCellsLevelsAndNormalBins) {
  const vec4 grid(0.0f, 0.0f, 0.0f, 4.0f);  // finest cells of 1/4
  const uint mask = (1u << 16) - 1u;
  const vec3 up(0.0f, 1.0f, 0.0f);
  auto cell = [&](vec3 p, vec3 n, uint level) { return earsCellIndex(earsCellKey(p, n, grid), level, mask); };
  // Points in one cell with one normal share it; the next cell, the opposite side or another axis does not.
  EXPECT_EQ(cell(vec3(0.30f, 0.30f, 0.30f), up, 0), cell(vec3(0.26f, 0.49f, 0.45f), up, 0));
  EXPECT_NE(cell(vec3(0.30f, 0.30f, 0.30f), up, 0), cell(vec3(0.55f, 0.30f, 0.30f), up, 0));
  EXPECT_NE(cell(vec3(0.30f, 0.30f, 0.30f), up, 0), cell(vec3(0.30f, 0.30f, 0.30f), -up, 0));
  EXPECT_NE(cell(vec3(0.30f, 0.30f, 0.30f), up, 0), cell(vec3(0.30f, 0.30f, 0.30f), vec3(0.9f, 0.3f, 0.0f), 0));
  // A coarser level joins 4 cells per axis (1 unit here): the next fine cell shares its level-1 cell, the next
  // unit does not; levels do not share cells.
  EXPECT_EQ(cell(vec3(0.30f, 0.30f, 0.30f), up, 1), cell(vec3(0.55f, 0.80f, 0.99f), up, 1));
  EXPECT_NE(cell(vec3(0.30f, 0.30f, 0.30f), up, 1), cell(vec3(1.30f, 0.30f, 0.30f), up, 1));
  EXPECT_EQ(cell(vec3(0.30f, 0.30f, 0.30f), up, 2), cell(vec3(3.9f, 3.9f, 3.9f), up, 2));
  EXPECT_NE(cell(vec3(0.30f, 0.30f, 0.30f), up, 1), cell(vec3(0.30f, 0.30f, 0.30f), up, 2));
  // Keys stay in their 7-bit fields, even outside the grid, and indices within the table.
  for (float x : {-100.0f, -0.1f, 0.0f, 7.3f, 1e6f}) {
    uint key = earsCellKey(vec3(x, -x, x), up, grid);
    EXPECT_LT(key, 6u << 21);
    for (uint level = 0; level < kEarsLevels; ++level) EXPECT_LE(earsCellIndex(key, level, mask), mask);
  }
}

TEST(EarsCell, LightCellsFollowTheCopiesCellsAndTagsFindTheirRecords) {
  const uint mask = (1u << 10) - 1u;
  EXPECT_EQ(earsLightCell(0u, mask), mask + 1u);
  EXPECT_EQ(earsLightCell(mask, mask), 2u * mask + 1u);  // the table's last cell
  // A first light sample's tag names its copy's record, for the largest slot the pool allows (2^24 paths a pass
  // times kEarsPoolFactor = 4) and every training depth; untagged slots stay below the tag bit.
  for (uint slot : {0u, 1u, 12345u, (1u << 26) - 1u})
    for (uint depth = 0; depth < kEarsDepths; ++depth) {
      const uint tag = earsFirstLightTag(slot, depth);
      EXPECT_NE(tag & kEarsFirstLightTag, 0u);
      EXPECT_EQ(tag & kEarsSlotMask, slot);
      EXPECT_EQ(earsTaggedRecord(tag), slot * kEarsDepths + depth);
    }
  EXPECT_EQ(((1u << 26) - 1u) & kEarsFirstLightTag, 0u);
}

TEST(EarsTraining, APassTrainsAboutKEarsTrainingPathsSamplesAtLeastOneAPixel) {
  // Small images: whole samples a pixel, as near kEarsTrainingPaths as rounding allows, never more than the pass.
  EXPECT_EQ(earsTrainingSamples(96u * 96u, 64u), 2u);  // 18,432 samples
  EXPECT_EQ(earsTrainingSamples(64u * 64u, 64u), 4u);
  EXPECT_EQ(earsTrainingSamples(64u * 64u, 3u), 3u);
  EXPECT_EQ(earsTrainingSamples(1u, 1u << 20), kEarsTrainingPaths);
  // Large images (and pixel chunks): one sample a pixel.
  EXPECT_EQ(earsTrainingSamples(kEarsTrainingPaths, 16u), 1u);
  EXPECT_EQ(earsTrainingSamples(1920u * 1080u, 16u), 1u);
  for (uint pixels : {1u, 7u, 100u, 9216u, kEarsTrainingPaths - 1u, 1u << 24})
    for (uint samples : {1u, 2u, 5u, 64u}) {
      const uint t = earsTrainingSamples(pixels, samples);
      EXPECT_GE(t, 1u);
      EXPECT_LE(t, samples);
    }
}

TEST(EarsImageStatistics, PassSumsAreTheBatchAfterMinusBefore) {
  FilmPixel batch[2] = {};
  batch[0].sum = vec4(1.0f, 2.0f, 3.0f, 2.0f);
  batch[0].sumSq = vec4(1.0f, 4.0f, 9.0f, 0.0f);
  batch[1].sum.w = 1.0f;
  batch[1].sumHigh = vec4(1.0f, 0.0f, 0.0f, 1.0f);  // one channel in the high range: 2^96 unscaled
  std::vector<PixelSums> after = batchPixelSums(batch, 2);
  EXPECT_EQ(after[0].n, 2.0);
  EXPECT_EQ(after[0].sum, glm::dvec3(1.0, 2.0, 3.0));
  EXPECT_EQ(after[0].sumSq, glm::dvec3(1.0, 4.0, 9.0));
  EXPECT_EQ(after[1].sum.x, std::ldexp(1.0, 96));
  std::vector<PixelSums> before = batchPixelSums(nullptr, 2);
  before[0].n = 1.0;
  before[0].sum = glm::dvec3(1.0);
  before[0].sumSq = glm::dvec3(1.0);
  std::vector<PixelSums> pass = passPixelSums(after, before);
  EXPECT_EQ(pass[0].n, 1.0);
  EXPECT_EQ(pass[0].sum, glm::dvec3(0.0, 1.0, 2.0));
  EXPECT_EQ(pass[0].sumSq, glm::dvec3(0.0, 3.0, 8.0));
  EXPECT_EQ(pass[1].n, 1.0);
}

TEST(EarsImageStatistics, FirefliesCountAgainstTheEarlierEstimateAndTheLargestAreLeftOut) {
  // 2000 pixels of one sample each, all estimated at 1 by earlier passes. Three fireflies (101, 51, 11); every
  // other sample is 1. Against its own mean a single sample would show no error at all; against the earlier
  // estimate each firefly's is (x - 1)^2 / (1 + eps). The 0.1% share leaves out two pixels, the two largest: 10^2 / (1 + eps)
  // remains, over the 1998 samples kept.
  std::vector<PixelSums> pass(2000);
  EarsPixelEstimate estimate;
  estimate.mean.assign(2000, glm::vec4(1.0f));
  estimate.smoothed = estimate.mean;
  for (size_t p = 0; p < pass.size(); ++p) {
    const double x = p == 7 ? 101.0 : p == 500 ? 51.0 : p == 1999 ? 11.0 : 1.0;
    pass[p].n = 1.0;
    pass[p].sum = glm::dvec3(x);
    pass[p].sumSq = glm::dvec3(x * x);
  }
  const double eps = kRelMseEpsilon;
  EXPECT_NEAR(earsRelativeVariance(pass, estimate, eps), 100.0 / (1.0 + eps) / 1998.0, 1e-12);
  // A pixel whose estimate is off by 1 adds 1 per sample, relative to its smoothed estimate: mean 2, smoothed 3.
  estimate.mean[3] = glm::vec4(2.0f);
  estimate.smoothed[3] = glm::vec4(3.0f);
  EXPECT_NEAR(earsRelativeVariance(pass, estimate, eps), (100.0 / (1.0 + eps) + 1.0 / (9.0 + eps)) / 1998.0, 1e-12);
  // Sums and estimate of different images are an internal error, not a silent read past the end.
  estimate.smoothed.pop_back();
  EXPECT_THROW(earsRelativeVariance(pass, estimate, eps), Error);
  EXPECT_THROW(earsPixelEstimate(std::vector<glm::vec4>(34), 7, 5), Error);
}

TEST(EarsImageStatistics, SmoothedEstimateIsTheBoxMeanClippedAtTheEdges) {
  // 7 x 5 pixels, a single bright pixel at (3, 2): every box that holds it gets 25 over the box's pixel count,
  // 25 where the box lies inside the image and fewer where the edges clip it (a corner box holds 9 pixels).
  std::vector<glm::vec4> mean(35, glm::vec4(0.0f));
  mean[2 * 7 + 3] = glm::vec4(25.0f);
  EarsPixelEstimate e = earsPixelEstimate(mean, 7, 5);
  EXPECT_EQ(e.mean, mean);
  for (uint32_t y = 0; y < 5; ++y)
    for (uint32_t x = 0; x < 7; ++x) {
      const int dx = std::abs(int(x) - 3), dy = std::abs(int(y) - 2);
      const int across = std::min(int(x), 2) + std::min(6 - int(x), 2) + 1,
                down = std::min(int(y), 2) + std::min(4 - int(y), 2) + 1;
      const float expected = dx <= 2 && dy <= 2 ? 25.0f / float(across * down) : 0.0f;
      EXPECT_NEAR(e.smoothed[y * 7 + x].x, expected, 1e-6f) << x << "," << y;
    }
  EXPECT_NEAR(e.smoothed[0].x, 0.0f, 0.0f);
  mean.assign(35, glm::vec4(1.0f));  // a constant stays constant, edges included
  for (const glm::vec4& v : earsPixelEstimate(mean, 7, 5).smoothed) EXPECT_NEAR(v.x, 1.0f, 1e-6f);
}

TEST(EarsGuard, RelativeSampleVarianceIsEachPixelsUnbiasedVarianceOverTheScale) {
  // Pixel 0: samples 1 and 3 in every channel (variance 2), scale 2 (relative 2 / 4); pixel 1: samples 0, 0, 6 in
  // red only (variance 12, channels averaged: 4), scale 1; pixel 2 has one sample and is left out.
  std::vector<PixelSums> pass(3);
  pass[0].n = 2, pass[0].sum = glm::dvec3(4.0), pass[0].sumSq = glm::dvec3(10.0);
  pass[1].n = 3, pass[1].sum = glm::dvec3(6.0, 0.0, 0.0), pass[1].sumSq = glm::dvec3(36.0, 0.0, 0.0);
  pass[2].n = 1, pass[2].sum = glm::dvec3(100.0), pass[2].sumSq = glm::dvec3(1e4);
  const std::vector<glm::vec4> scale = {glm::vec4(2.0f), glm::vec4(1.0f), glm::vec4(1.0f)};
  EXPECT_NEAR(relativeSampleVariance(pass, scale, 0.0), (0.5 + 4.0) / 2.0, 1e-12);
  // Epsilon joins the scale's square, as in relMSE.
  EXPECT_NEAR(relativeSampleVariance(pass, scale, 1.0), (2.0 / 5.0 + 4.0 / 2.0) / 2.0, 1e-12);
  EXPECT_THROW(relativeSampleVariance(pass, {glm::vec4(1.0f)}, 0.0), Error);
  EXPECT_TRUE(std::isnan(relativeSampleVariance({pass[2]}, {glm::vec4(1.0f)}, 0.0))) << "no pixel with two samples";
}

TEST(EarsGuard, TalliesAddPassesAndEarsIsCostedAsInItsLaterPasses) {
  PolicyTally t;
  std::vector<PixelSums> pass(2);
  pass[0].n = 2, pass[0].sum = glm::dvec3(1.0), pass[0].sumSq = glm::dvec3(1.0);
  t.addPass(pass, 2, 0.5);
  t.addPass(pass, 1, 0.25);
  EXPECT_EQ(t.samples, 3u);
  EXPECT_DOUBLE_EQ(t.seconds, 0.75);
  EXPECT_DOUBLE_EQ(t.sums[0].n, 4.0);
  EXPECT_DOUBLE_EQ(t.sums[0].sumSq.y, 2.0);
  EXPECT_THROW(t.addPass(std::vector<PixelSums>(3), 1, 0.1), Error);
  // Nothing split into training and lean: the whole passes' seconds a sample.
  EXPECT_DOUBLE_EQ(earsSecondsPerSample(t, 100.0, 8.0, 100.0), 0.25);
  // 100 pixels; a training pixel-sample 3 ms, a lean one 1 ms. A later pass of 8 a pixel of which 100 pixel-samples
  // train: (100 x 3 + 700 x 1) ms / 800 pixel-samples, 100 pixel-samples a sample.
  t.trainSeconds = 0.3, t.trainPixelSamples = 100.0, t.leanSeconds = 0.2, t.leanPixelSamples = 200.0;
  EXPECT_NEAR(earsSecondsPerSample(t, 100.0, 8.0, 100.0), (0.3 + 0.7) / 800.0 * 100.0, 1e-12);
  // A later pass that trains on everything costs as training does; nothing lean measured: as training too.
  EXPECT_NEAR(earsSecondsPerSample(t, 100.0, 1.0, 100.0), 0.3, 1e-12);
  t.leanPixelSamples = 0.0;
  EXPECT_NEAR(earsSecondsPerSample(t, 100.0, 8.0, 100.0), 0.3, 1e-12);
}

TEST(EarsGuard, TheMoreEfficientPolicyRendersTheRest) {
  const PolicyPass ears{2.0, 0.5}, throughput{4.0, 0.2};  // 1/(V T): 1 against 1.25
  EXPECT_DOUBLE_EQ(ears.efficiency(), 1.0);
  EXPECT_TRUE(earsFallsBack(EarsFallback::Auto, ears, throughput));
  EXPECT_FALSE(earsFallsBack(EarsFallback::Auto, PolicyPass{1.0, 0.5}, throughput));  // 2 against 1.25
  // A tie goes to the cheaper kernels; never and always decide alone.
  EXPECT_TRUE(earsFallsBack(EarsFallback::Auto, PolicyPass{4.0, 0.2}, throughput));
  // Within the margin EARS's reading is not trusted (kEarsGuardMargin): 1.2x is not enough, 1.3x is.
  EXPECT_TRUE(earsFallsBack(EarsFallback::Auto, PolicyPass{1.0, 1.0 / (1.2 * kEarsGuardMargin)}, throughput));
  EXPECT_FALSE(earsFallsBack(EarsFallback::Auto, PolicyPass{1.0, 1.0 / (1.3 * kEarsGuardMargin)}, throughput));
  EXPECT_FALSE(earsFallsBack(EarsFallback::Never, ears, throughput));
  EXPECT_TRUE(earsFallsBack(EarsFallback::Always, PolicyPass{1.0, 0.01}, throughput));
  // A noiseless pass is infinitely efficient; a non-finite one (poisoned sums) never wins.
  EXPECT_TRUE(std::isinf(PolicyPass{0.0, 1.0}.efficiency()));
  EXPECT_FALSE(earsFallsBack(EarsFallback::Auto, PolicyPass{0.0, 1.0}, throughput));
  EXPECT_EQ((PolicyPass{std::nan(""), 1.0}.efficiency()), 0.0);
  EXPECT_TRUE(earsFallsBack(EarsFallback::Auto, PolicyPass{std::nan(""), 1.0}, throughput));
  EXPECT_FALSE(earsFallsBack(EarsFallback::Auto, ears, PolicyPass{INFINITY, 1.0}));
}

TEST(EarsGuard, ACloseFirstMeasureOfEarsIsTakenAgain) {
  const PolicyPass throughput{1.0, 1.0};                                                    // efficiency 1
  EXPECT_TRUE(earsGuardLooksAgain(EarsFallback::Auto, PolicyPass{1.0, 1.25}, throughput));  // 0.8
  EXPECT_TRUE(earsGuardLooksAgain(EarsFallback::Auto, PolicyPass{1.0, 1.0 / kEarsSecondLookRatio}, throughput));
  EXPECT_FALSE(earsGuardLooksAgain(EarsFallback::Auto, PolicyPass{1.0, 2.0}, throughput));  // 0.5: clearly worse
  EXPECT_FALSE(earsGuardLooksAgain(EarsFallback::Auto, PolicyPass{1.0, 0.5}, throughput));  // 2: EARS wins
  EXPECT_TRUE(earsGuardLooksAgain(EarsFallback::Auto, PolicyPass{1.0, 0.9}, throughput));   // 1.11: within the margin
  EXPECT_FALSE(earsGuardLooksAgain(EarsFallback::Never, PolicyPass{1.0, 1.25}, throughput));
  EXPECT_TRUE(earsGuardLooksAgain(EarsFallback::Always, PolicyPass{1.0, 0.5}, throughput));  // its tests' path
}

// Under a time budget, learning (training passes, EARS's looks and throughput roulette's pass, each costed at its
// proxy's seconds a sample) must fit in kEarsLearningBudgetShare of it; without a budget it always fits.
TEST(EarsGuard, LearningMustFitInItsShareOfATimeBudget) {
  EXPECT_DOUBLE_EQ(earsLearningSecondsLeft(6, 9, 0.01, 28 * 0.02), 15 * 0.01 + 28 * 0.02);
  EXPECT_DOUBLE_EQ(earsLearningSecondsLeft(0, 0, 0.5, 0.0), 0.0);
  EXPECT_TRUE(earsLearningFits(0.0, 100.0, 1e9)) << "no budget";
  EXPECT_TRUE(earsLearningFits(4.0, 0.2, kEarsLearningBudgetShare * 4.0 - 0.2));
  EXPECT_FALSE(earsLearningFits(4.0, 0.2, kEarsLearningBudgetShare * 4.0 - 0.1));
  EXPECT_FALSE(earsLearningFits(16.0, kEarsLearningBudgetShare * 16.0 + 0.01, 0.0)) << "already past its share";
}

// Throughput roulette's measured passes costed from the first pass: a pass's overhead once a pass, the rest by
// samples; the overhead from two passes of different sizes (t = a + b n), clamped, 0 where they cannot tell.
TEST(EarsGuard, ThroughputRoulettesPassIsCostedAsOverheadPlusSamples) {
  // dark_room at 96x96 (docs/journal/ears.md): 1 spp in 0.0375 s, 28 spp in 0.238 s, so a = 0.030, b = 0.0074.
  EXPECT_DOUBLE_EQ(earsPassOverhead(0.0375, 1, 0.238, 28, 1.0), (0.0375 * 28 - 0.238) / 27);
  EXPECT_NEAR(earsThroughputPassSeconds(0.0375, 1, 0.03, 1, 28), 0.03 + 28 * 0.0075, 1e-12);
  EXPECT_DOUBLE_EQ(earsThroughputPassSeconds(0.0375, 1, 0.0, 1, 28), 28 * 0.0375) << "no overhead: the upper bound";
  EXPECT_DOUBLE_EQ(earsThroughputPassSeconds(0.0375, 1, 0.0375, 1, 28), 0.0375) << "all overhead: one first pass";
  EXPECT_DOUBLE_EQ(earsThroughputPassSeconds(0.0375, 1, 0.0375, 4, 4), 4 * 0.0375) << "four passes of one sample";
  EXPECT_DOUBLE_EQ(earsPassOverhead(0.1, 2, 0.1, 2, 1.0), 0.0) << "same size";
  EXPECT_DOUBLE_EQ(earsPassOverhead(0.1, 2, 0.3, 4, 1.0), 0.0) << "time growing faster than samples: no overhead";
  EXPECT_DOUBLE_EQ(earsPassOverhead(0.1, 2, 0.11, 4, 0.05), 0.05) << "capped at the first pass";
}

// Only auto watches the EARS it chose; the report's line says what the watch saw and where it switched.
TEST(EarsGuard, AutoWatchesTheEarsItChoseAndTheLineSaysWhatItSaw) {
  EXPECT_TRUE(earsGuardWatches(EarsFallback::Auto));
  EXPECT_FALSE(earsGuardWatches(EarsFallback::Never));
  EXPECT_FALSE(earsGuardWatches(EarsFallback::Always));
  EarsGuardOutcome g;
  g.compared = g.watched = true;
  g.ears = PolicyPass{1.0, 0.5, 4};         // efficiency 2
  g.throughput = PolicyPass{2.0, 1.0, 28};  // 0.5
  g.fromSample = 13;
  EXPECT_NE(earsGuardLine(g).find("ears from sample 13"), std::string::npos) << earsGuardLine(g);
  g.watchedEars = PolicyPass{4.0, 1.0, 60};  // 0.25: behind
  g.fellBack = g.switchedLater = true;
  g.switchedAt = 73;
  const std::string line = earsGuardLine(g);
  EXPECT_NE(line.find("ears from sample 13; watched over 60 samples a pixel, ears read 0.25: throughput roulette from sample 73"),
            std::string::npos)
      << line;
}

// The guard's cost, from one render's own clock: the seconds to the decision less its kept samples at the rest's
// seconds a sample; NaN where nothing was decided or nothing followed. The report's line gives it.
TEST(EarsGuard, ChoosingCostsWhatItsSecondsHoldBeyondItsKeptSamplesAtTheRestsRate) {
  // Decided 2 s in, with 10 samples a pixel kept; 90 more took 9 s (0.1 s each): the 10 would have taken 1 s.
  EXPECT_DOUBLE_EQ(earsLearningCostSeconds(2.0, 10, 11.0, 90), 1.0);
  EXPECT_DOUBLE_EQ(earsLearningCostSeconds(0.5, 0, 4.5, 40), 0.5) << "nothing kept: all of it";
  EXPECT_LT(earsLearningCostSeconds(1.0, 10, 3.0, 10), 0.0) << "kept samples cheaper than the rest's";
  EXPECT_TRUE(std::isnan(earsLearningCostSeconds(2.0, 10, 2.0, 0))) << "no rest to cost by";
  EXPECT_TRUE(std::isnan(earsLearningCostSeconds(std::numeric_limits<double>::quiet_NaN(), 10, 5.0, 10))) << "no decision";
  EarsGuardOutcome g;
  g.outOfBudget = g.fellBack = true;
  g.fromSample = 3;
  EXPECT_EQ(earsGuardLine(g).find("choosing cost"), std::string::npos) << "nothing measured, nothing said";
  g.decidedAtSeconds = 0.25;
  g.learningCostSeconds = 0.125;
  const std::string line = earsGuardLine(g);
  EXPECT_NE(line.find("from sample 3; choosing cost 0.125 s (decided at 0.25 s)"), std::string::npos) << line;
}
