// EARS's pure functions (shaders/shared/ears.h) and the image statistics its factors are scaled by
// (host/render/ears_cache.h).
#include <gtest/gtest.h>

#include <cmath>

#include "../shaders/shared/ears.h"
#include "../shaders/shared/roulette.h"
#include "analysis/error_metrics.h"
#include "render/ears_cache.h"

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

TEST(EarsImageStatistics, RelativeVarianceAndEstimateFromFilmAndBatch) {
  // Two pixels: one with samples 1 and 3 folded (mean 2, variance 2), one with samples 0 and 0 in the batch.
  Film film(2, 1);
  for (int c = 0; c < 3; ++c) film.sum[c] = 4.0, film.sumSq[c] = 10.0;
  film.count[0] = 2;
  FilmPixel batch[2] = {};
  batch[1].sum.w = 2.0f;
  const double eps = kRelMseEpsilon;
  EarsImageStatistics s = earsImageStatistics(film, batch, eps);
  EXPECT_FLOAT_EQ(s.pixelEstimate[0].x, 2.0f);
  EXPECT_NEAR(s.pixelEstimate[0].w, 2.0f, 1e-5f);  // luminance of grey
  EXPECT_FLOAT_EQ(s.pixelEstimate[1].x, 0.0f);
  // The noisier pixel is the share left out (at least one): the other's 0 remains.
  EXPECT_EQ(s.relativeVariance, 0.0);
  // The batch adds to the folded sums: a third sample 2 leaves the mean at 2 and makes the variance 1.
  batch[0].sum = vec4(2.0f, 2.0f, 2.0f, 1.0f);
  batch[0].sumSq = vec4(4.0f, 4.0f, 4.0f, 0.0f);
  s = earsImageStatistics(film, batch, eps);
  EXPECT_FLOAT_EQ(s.pixelEstimate[0].x, 2.0f);
}

TEST(EarsImageStatistics, MeanOverPixelsLeavesOutTheNoisiest) {
  // 2000 pixels of two samples each: 1998 with samples 0 and 2 (relative variance 2 / (1 + eps)), two with 0 and
  // 2000 (a firefly). A 0.1% share drops two pixels: the fireflies.
  Film film(2000, 1);
  for (size_t p = 0; p < 2000; ++p) {
    const double hi = p < 2 ? 2000.0 : 2.0;
    for (int c = 0; c < 3; ++c) film.sum[3 * p + c] = hi, film.sumSq[3 * p + c] = hi * hi;
    film.count[p] = 2;
  }
  const double eps = kRelMseEpsilon;
  EarsImageStatistics s = earsImageStatistics(film, nullptr, eps);
  EXPECT_NEAR(s.relativeVariance, 2.0 / (1.0 + eps), 1e-9);
}
