// EARS's pure functions (shaders/shared/ears.h) and the image statistics its factors are scaled by
// (host/render/ears_cache.h).
#include <gtest/gtest.h>

#include <cmath>

#include "../shaders/shared/ears.h"
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

TEST(EarsFactor, ClampedToEarsRange) {
  EXPECT_FLOAT_EQ(earsFactor(vec3(1e-6f), vec3(1.0f), vec3(1.0f), 1.0f), kEarsFactorMin);
  EXPECT_FLOAT_EQ(earsFactor(vec3(1e6f), vec3(1.0f), vec3(1.0f), 1.0f), kEarsFactorMax);
  EXPECT_FLOAT_EQ(earsFactor(vec3(0.0f), vec3(0.0f), vec3(0.0f), 0.0f), kEarsFactorMin);  // nothing to gain: roulette
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

TEST(EarsCell, GridCellsAndNormalBins) {
  const vec4 grid(0.0f, 0.0f, 0.0f, 4.0f);  // cells of 1/4
  const uint mask = (1u << 16) - 1u;
  const vec3 up(0.0f, 1.0f, 0.0f);
  // Points in one cell with one normal share it; the next cell, the opposite side or another axis does not.
  EXPECT_EQ(earsCell(vec3(0.30f, 0.30f, 0.30f), up, grid, mask), earsCell(vec3(0.26f, 0.49f, 0.45f), up, grid, mask));
  EXPECT_NE(earsCell(vec3(0.30f, 0.30f, 0.30f), up, grid, mask), earsCell(vec3(0.55f, 0.30f, 0.30f), up, grid, mask));
  EXPECT_NE(earsCell(vec3(0.30f, 0.30f, 0.30f), up, grid, mask), earsCell(vec3(0.30f, 0.30f, 0.30f), -up, grid, mask));
  EXPECT_NE(earsCell(vec3(0.30f, 0.30f, 0.30f), up, grid, mask),
            earsCell(vec3(0.30f, 0.30f, 0.30f), vec3(0.9f, 0.3f, 0.0f), grid, mask));
  // Always within the table, even below the grid's origin.
  for (float x : {-100.0f, -0.1f, 0.0f, 7.3f, 1e6f}) EXPECT_LE(earsCell(vec3(x, -x, x), up, grid, mask), mask);
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
  // Per sample, over pixels and channels: (2 / (4 + eps) + 0) / 2.
  EXPECT_NEAR(s.relativeVariance, 0.5 * 2.0 / (4.0 + eps), 1e-12);
  // The batch adds to the folded sums: a third sample 2 leaves the mean at 2 and makes the variance 1.
  batch[0].sum = vec4(2.0f, 2.0f, 2.0f, 1.0f);
  batch[0].sumSq = vec4(4.0f, 4.0f, 4.0f, 0.0f);
  s = earsImageStatistics(film, batch, eps);
  EXPECT_FLOAT_EQ(s.pixelEstimate[0].x, 2.0f);
  EXPECT_NEAR(s.relativeVariance, 0.5 * 1.0 / (4.0 + eps), 1e-12);
}
