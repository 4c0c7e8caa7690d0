// Stiff cases rendered against analytic answers; rows go to the stability table (tools/stability_table.sh).
#include <gtest/gtest.h>

#include <fstream>

#include "analysis/variance_reliability.h"
#include "support/render_helpers.h"
#include "scene/gltf_loader.h"
#include "support/test_scenes.h"
#include "support/stability_row.h"

using namespace vkmc;
using namespace vkmc::test;

namespace {
// Stiff case 2: L(x, z) = rho / pi * Le * A * h^2 / (h^2 + x^2 + z^2)^2, averaged over pixel (i, j)'s footprint
// (x in -1 + 2 [i, i + 1] / n, z likewise with j: the orthographic camera of scenes/stiff/tiny_light.gltf).
double tinyLightPixel(uint32_t i, uint32_t j, uint32_t n) {
  const int sub = 64;
  double sum = 0;
  for (int a = 0; a < sub; ++a)
    for (int b = 0; b < sub; ++b) {
      double x = -1 + 2 * (i + (a + 0.5) / sub) / n, z = -1 + 2 * (j + (b + 0.5) / sub) / n, d2 = 1 + x * x + z * z;
      sum += 0.5 / 3.14159265358979323846 * 1e6 * 1e-6 / (d2 * d2);
    }
  return sum / (sub * sub);
}
double tinyLightImageMean(uint32_t n) {
  double mean = 0;
  for (uint32_t j = 0; j < n; ++j)
    for (uint32_t i = 0; i < n; ++i) mean += tinyLightPixel(i, j, n) / (n * n);
  return mean;
}
}  // namespace

TEST(StiffRender, TinyIntenseLightMatchesTheAnalyticRadiance) {
  const uint32_t n = 16;
  // Pixel by pixel at 3 sigma: the independent sampler, whose pixel variances have 255 dof (sobol's 3 with
  // 4 replicates would widen 3 sigma to 9.2, its default 1 far more).
  EstimatorConfig independent;
  independent.sampler = Sampler::Independent;
  // 4 replicates: the reliability figure below is then the unbiased U-statistic (with 2 it is an upper bound).
  independent.replicates = 4;
  RenderOutcome r = renderWith("stiff/tiny_light.gltf", independent, n, n, 256);
  ASSERT_EQ(r.film.totalNonfinite(), 0u);
  const double expectedMean = tinyLightImageMean(n);
  RegionStats s = whole(r.film);
  ZTest image = zTest(s.mean.x, expectedMean, std::sqrt(s.variance.x));
  EXPECT_TRUE(belowSigmas(image, 3.0)) << "image mean";
  stabilityRow("2", "tiny intense light (1 mm^2, Le 1e6): image mean", std::to_string(expectedMean), s.mean.x, image.sigma,
               image.below(3.0));
  for (auto [i, j] : {std::pair{8u, 8u}, std::pair{3u, 12u}, std::pair{0u, 0u}}) {
    size_t p = size_t(j) * n + i;
    double expected = tinyLightPixel(i, j, n);
    ZTest pixel = zTest(r.film.mean(p, 0), expected, std::sqrt(r.film.varianceOfMean(p, 0)));
    EXPECT_TRUE(belowSigmas(pixel, 3.0)) << "pixel " << i << "," << j;
    stabilityRow("2", "tiny intense light: pixel (" + std::to_string(i) + "," + std::to_string(j) + ")", std::to_string(expected),
                 r.film.mean(p, 0), pixel.sigma, pixel.below(3.0));
  }
  // BSDF sampling alone finds a 1e-6 sr light about once in ten million samples: the estimate stays finite and
  // non-negative (nearly black) and its sampled variance is no evidence of accuracy, which the report shows.
  EstimatorConfig off;
  off.nee = false;
  off.replicates = 4;
  RenderOutcome b = renderWith("stiff/tiny_light.gltf", off, n, n, 64);
  EXPECT_EQ(b.film.totalNonfinite(), 0u);
  EXPECT_GE(whole(b.film).mean.x, 0.0);
  EXPECT_LT(whole(b.film).mean.x, expectedMean);
  // The report says so: with light sampling the variance estimate is trustworthy, without it is not (the few
  // samples that found the light, or none at all, decide it).
  EXPECT_TRUE(assessVarianceReliability(r.film).reliable()) << assessVarianceReliability(r.film).relativeStandardError;
  EXPECT_FALSE(assessVarianceReliability(b.film).reliable()) << assessVarianceReliability(b.film).relativeStandardError;
  stabilityRow("2", "tiny intense light, NEE off (64 spp): finite, practically black",
               "finite, <= " + std::to_string(expectedMean), whole(b.film).mean.x, std::sqrt(whole(b.film).variance.x),
               b.film.totalNonfinite() == 0);
}

// The estimator chosen by its pilots, and each pixel's samples by its measured variance: whatever they choose,
// the tiny light's image mean and pixels stay the analytic radiance (the pilots and the rounds are rounds of the
// image with weights fixed before their samples are seen). 32x32 at 512 samples: pilots of 64 a pixel.
class TinyIntenseLightChosen : public ::testing::TestWithParam<bool> {};

TEST_P(TinyIntenseLightChosen, MeanAndPixelsAreTheAnalyticRadiance) {
  const uint32_t n = 32;
  EstimatorConfig start;
  start.sampler = Sampler::Independent;  // pixel variances with many degrees of freedom, for the pixels' z-tests
  const RenderOutcome r = renderAuto("stiff/tiny_light.gltf", n, n, 512, 61, start, {}, GetParam());
  ASSERT_TRUE(r.choice);
  EXPECT_GE(r.choice->candidates.size(), 2u);
  ASSERT_EQ(r.film.totalNonfinite(), 0u);
  const RegionStats s = whole(r.film);
  EXPECT_TRUE(belowSigmas(zTest(s.mean.x, tinyLightImageMean(n), std::sqrt(s.variance.x)), 4.0)) << "image mean";
  for (auto [i, j] : {std::pair{16u, 16u}, std::pair{6u, 25u}, std::pair{0u, 0u}}) {
    const size_t p = size_t(j) * n + i;
    const ZTest pixel = zTest(r.film.mean(p, 0), tinyLightPixel(i, j, n), std::sqrt(r.film.varianceOfMean(p, 0)));
    EXPECT_TRUE(belowSigmas(pixel, 4.0)) << "pixel " << i << "," << j;
  }
}

INSTANTIATE_TEST_SUITE_P(StiffRender, TinyIntenseLightChosen, ::testing::Bool(), [](const ::testing::TestParamInfo<bool>& p) {
  return p.param ? std::string("AdaptiveRounds") : std::string("UniformRest");
});

// The same light under rr ears: a pixel's few bright vertices get split, the rest rouletted; the image mean and
// the pixels stay the analytic radiance. With learned light samples too, the light cells split or roulette each
// copy's light samples.
class TinyIntenseLightWithEars : public ::testing::TestWithParam<float> {};

TEST_P(TinyIntenseLightWithEars, MeanAndPixelsAreTheAnalyticRadiance) {
  const uint32_t n = 16;
  EstimatorConfig e;
  e.sampler = Sampler::Independent;
  e.rr = RouletteMode::Ears;
  e.earsFallback = EarsFallback::Never;
  e.earsLightMax = GetParam();
  RenderOutcome r = renderWith("stiff/tiny_light.gltf", e, n, n, 256);
  ASSERT_EQ(r.film.totalNonfinite(), 0u);
  const double expectedMean = tinyLightImageMean(n);
  RegionStats s = whole(r.film);
  EXPECT_TRUE(belowSigmas(zTest(s.mean.x, expectedMean, std::sqrt(s.variance.x)), 4.0)) << "image mean";
  for (auto [i, j] : {std::pair{8u, 8u}, std::pair{3u, 12u}, std::pair{0u, 0u}}) {
    size_t p = size_t(j) * n + i;
    ZTest pixel = zTest(r.film.mean(p, 0), tinyLightPixel(i, j, n), std::sqrt(r.film.varianceOfMean(p, 0)));
    EXPECT_TRUE(belowSigmas(pixel, 4.0)) << "pixel " << i << "," << j;
  }
  ASSERT_TRUE(r.ears);
  EXPECT_GT(r.ears->trustedCells, 0u);
  if (GetParam() > 0.0f) {
    EXPECT_GT(r.ears->trustedLightCells, 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(StiffRender, TinyIntenseLightWithEars, ::testing::Values(0.0f, gpu::kEarsLightFactorMax),
                         [](const ::testing::TestParamInfo<float>& p) {
                           return p.param > 0.0f ? std::string("LearnedLightSamples") : std::string("Default");
                         });

TEST(StiffRender, RouletteAndSplittingAtTheEdges) {
  // Case 9 on the white furnace (L = 2). One roulette decision (at the first continuation, depth cap 1, so
  // L = Le (1 + a) = 1.5) with termination probability 0.999: survivors weigh 1000; the mean is unchanged and
  // the variance grows by E[F^2] (1/s - 1) for survival s, so its growth over no roulette is 999 / 1 = 999
  // times the growth at s = 0.5 (Poisson noise of ~65 survivors: within a factor 2). Then q = 0 with c != 0
  // (never terminates, so c has no effect; under a depth cap of 8 the truncated series 2 (1 - 0.5^9)), and a
  // splitting factor of 64 at the first hit.
  auto oneDecision = [](float q) {
    EstimatorConfig c;
    c.sampler = Sampler::Independent;  // the variance formula is for independent samples (sobol stratifies "none")
    c.rr = q > 0.0f ? RouletteMode::Fixed : RouletteMode::None;
    c.rrQ = q;
    c.rrDepth = 1;
    c.maxDepth = 1;
    return c;
  };
  RenderOutcome none = renderWith("furnace.gltf", oneDecision(0.0f), 16, 16, 256);
  RenderOutcome half = renderWith("furnace.gltf", oneDecision(0.5f), 16, 16, 256);
  RenderOutcome a = renderWith("furnace.gltf", oneDecision(0.999f), 16, 16, 256);
  RegionStats sa = whole(a.film);
  EXPECT_TRUE(regionMatches(sa, glm::dvec3(1.5), 5.0));
  stabilityRow("9", "fixed roulette q = 0.999, one decision (furnace, cap 1)", "1.5", sa.mean.x, std::sqrt(sa.variance.x),
               maxZ(sa, glm::dvec3(1.5)) < 5.0);
  double v0 = whole(none.film).variance.x, growthHalf = whole(half.film).variance.x - v0, growth = sa.variance.x - v0;
  double ratio = growth / growthHalf;
  EXPECT_GT(ratio, 999.0 / 2.0);
  EXPECT_LT(ratio, 999.0 * 2.0);
  stabilityRow("9", "variance growth q = 0.999 over q = 0.5 (theory 999)", "999", ratio, 0.0,
               ratio > 999.0 / 2 && ratio < 999.0 * 2);

  EstimatorConfig never;
  never.rr = RouletteMode::Fixed;
  never.rrQ = 0.0f;
  never.rrC = 0.7f;
  never.rrDepth = 1;
  never.maxDepth = 8;
  RenderOutcome b = renderWith("furnace.gltf", never, 16, 16, 64);
  RegionStats sb = whole(b.film);
  double truncated = 2.0 * (1.0 - std::pow(0.5, 9));
  EXPECT_TRUE(regionMatches(sb, glm::dvec3(truncated), 5.0));
  stabilityRow("9", "fixed roulette q = 0, c = 0.7, depth cap 8", std::to_string(truncated), sb.mean.x, std::sqrt(sb.variance.x),
               maxZ(sb, glm::dvec3(truncated)) < 5.0);

  EstimatorConfig split;
  split.bsdfSamples = 64.0f;
  RenderOutcome c = renderWith("furnace.gltf", split, 16, 16, 64);
  RenderOutcome base = renderWith("furnace.gltf", EstimatorConfig{}, 16, 16, 64);
  RegionStats sc = whole(c.film), sbase = whole(base.film);
  EXPECT_TRUE(regionMatches(sc, glm::dvec3(2.0), 5.0));
  // 64 continuations per camera sample: the variance of what follows the first hit falls about 64-fold, so
  // the per-sample variance must drop well below the unsplit one.
  EXPECT_LT(sc.variance.x, 0.1 * sbase.variance.x);
  stabilityRow("9", "splitting factor 64: variance over unsplit (theory about 1/64)", "< 0.1", sc.variance.x / sbase.variance.x,
               0.0, sc.variance.x < 0.1 * sbase.variance.x);
  EXPECT_EQ(c.film.totalNonfinite(), 0u);
  stabilityRow("9", "splitting factor 64 at the first hit (furnace)", "2", sc.mean.x, std::sqrt(sc.variance.x),
               maxZ(sc, glm::dvec3(2.0)) < 5.0);
}

TEST(StiffRender, DegenerateGeometryIsSkippedCountedAndHarmless) {
  // Case 7: zero-area triangles, repeated vertices, a sliver of aspect 1e6, a coincident face; and a scene of a
  // single triangle. Lit by the background; no sample may be non-finite.
  auto dir = makeTempDir("degenerate");
  GltfSpec s = quadSpec();
  std::vector<float> extra = {0.2f, 0.2f, 0.5f, 0.8f, 0.2f, 0.5f, 0.5f, 0.2f + 6e-7f,
                              0.5f,  // sliver, aspect 1e6
                              3,    3,    3,    4,    4,    4,    5,    5,
                              5,  // collinear: zero area
                              0,    0,    0,    1,    0,    0,    1,    1,
                              0};  // coincident with the quad
  s.positions.insert(s.positions.end(), extra.begin(), extra.end());
  s.indices.insert(s.indices.end(), {4, 5, 6, 7, 8, 9, 10, 11, 12, 0, 0, 2});  // ..., repeated vertex
  std::string path = writeGltf(dir, "degenerate", s);
  Scene scene = loadGltf(path);
  EXPECT_EQ(scene.degenerateTriangles, 2u);
  EXPECT_EQ(scene.triangleCount(), 4u);
  RenderOptions o;
  o.scenePath = path;
  o.width = 24;
  o.height = 24;
  o.spp = 32;
  o.progress = false;
  o.background = glm::vec3(1.0f);
  RenderOutcome r = runRender(sharedContext(), o);
  EXPECT_EQ(r.film.totalNonfinite(), 0u);
  EXPECT_EQ(r.degenerateTriangles, 2u);
  stabilityRow("7", "zero-area, repeated-vertex, sliver (1e6), coincident triangles", "0 non-finite, 2 skipped",
               double(r.film.totalNonfinite()), 0.0, r.film.totalNonfinite() == 0 && r.degenerateTriangles == 2);
  GltfSpec one = quadSpec();
  one.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  one.indices.clear();
  o.scenePath = writeGltf(dir, "single", one);
  RenderOutcome single = runRender(sharedContext(), o);
  EXPECT_EQ(single.film.totalNonfinite(), 0u);
  EXPECT_GT(whole(single.film).mean.x, 0.0);
  stabilityRow("7", "a single triangle", "0 non-finite", double(single.film.totalNonfinite()), 0.0,
               single.film.totalNonfinite() == 0);
}

namespace {
class DepthCapOnTheStiffFurnace : public ::testing::TestWithParam<uint32_t> {};
}  // namespace

TEST_P(DepthCapOnTheStiffFurnace, TruncationMatchesTheory) {
  // Case 1's truncation part: albedo 0.99, Le = 1, no roulette, cap D: L_D = (1 - 0.99^(D+1)) / (1 - 0.99).
  const uint32_t cap = GetParam();
  EstimatorConfig c;
  c.rr = RouletteMode::None;
  c.maxDepth = cap;
  RenderOutcome r = renderWith("furnace_stiff.gltf", c, 8, 8, 16);
  RegionStats s = whole(r.film);
  double expected = (1.0 - std::pow(0.99, cap + 1.0)) / (1.0 - 0.99);
  ZTest t = zTest(s.mean.x, expected, std::sqrt(s.variance.x), 1e-6 * expected);
  EXPECT_TRUE(withinSigmas(t, 5.0)) << "cap " << cap;
  EXPECT_LT(t.sigma, 1e-3 * expected) << "the test must resolve 0.1%";
  stabilityRow("1", "albedo 0.99 furnace, depth cap " + std::to_string(cap) + ", no roulette: truncation theory",
               std::to_string(expected), s.mean.x, t.sigma, t.within(5.0));
}

INSTANTIATE_TEST_SUITE_P(StiffRender, DepthCapOnTheStiffFurnace, ::testing::Values(1u, 10u, 50u),
                         [](const auto& info) { return "cap" + std::to_string(info.param); });
