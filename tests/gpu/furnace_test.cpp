// White furnace: a closed sphere, albedo 0.5, emission 1 on both sides, seen from inside: L = 1 / (1 - 0.5) = 2
// at every pixel. Tolerances come from the measured variance of each pixel's mean (5 sigma), no depth cap.
// Roulette makes the estimates skewed; 1024 samples per pixel keep the mean's distribution close to normal.
#include <gtest/gtest.h>

#include "app/render_job.h"
#include "support/z_test.h"

using namespace vkmc;
using vkmc::test::withinSigmas;
using vkmc::test::zTest;

namespace {
RenderOptions furnaceOptions(uint32_t spp) {
  RenderOptions o;
  o.scenePath = std::string(VKMC_SOURCE_DIR) + "/scenes/furnace.gltf";
  o.width = 16;
  o.height = 16;
  o.spp = spp;
  o.seed = 1234;
  o.progress = false;
  return o;
}
vk::Context& context() {
  static vk::Context ctx;
  return ctx;
}
}  // namespace

TEST(Furnace, EveryPixelIsTwoWithinFiveSigmaWithoutDepthCap) {
  // A sharp test of every pixel needs many-dof variances: the independent sampler's (1023 dof; the QMC samplers'
  // 1, or 3 with 4 replicates, would widen 5 sigma to 157 or more). The other furnace tests run the default sampler.
  RenderOptions o = furnaceOptions(1024);
  o.estimator.sampler = Sampler::Independent;
  RenderOutcome r = runRender(context(), o);
  const Film& f = r.film;
  ASSERT_EQ(f.totalNonfinite(), 0u);
  ASSERT_EQ(f.totalSamples(), 16u * 16u * 1024u);
  int outside = 0;
  double worstZ = 0.0;
  for (size_t p = 0; p < f.pixels(); ++p) {
    for (int c = 0; c < 3; ++c) {
      double sigma = std::sqrt(f.varianceOfMean(p, c));
      ASSERT_GT(sigma, 0.0) << "a furnace pixel with zero variance means the estimator is not random";
      double z = std::abs(zTest(f.mean(p, c), 2.0, sigma).z());
      worstZ = std::max(worstZ, z);
      outside += z > 5.0;
    }
  }
  EXPECT_EQ(outside, 0) << "worst |z| = " << worstZ;
  glm::dvec3 mean = f.imageMean();
  glm::dvec3 var = f.imageMeanVarianceOfMean();
  for (int c = 0; c < 3; ++c)
    EXPECT_TRUE(withinSigmas(zTest(mean[c], 2.0, std::sqrt(var[c] / f.pixels())), 5.0)) << "channel " << c;
  EXPECT_GT(r.stats.maxBounces, 10u) << "without a cap some paths must run long";
}

// Solid-angle light sampling of the furnace's 1280 small emitters (about 0.01 sr each): a spherical sample that
// rounding put just past an edge was blocked by the neighbouring triangle, and the image read 1.99636 (z = -10);
// clamped onto the triangle (light_sampling.h clampToTriangle) it reads 2.
TEST(Furnace, SolidAngleLightSamplingLosesNoLightAtEdges) {
  RenderOptions o = furnaceOptions(2048);
  o.estimator.lightSampling = LightSampling::SolidAngle;
  RenderOutcome r = runRender(context(), o);
  ASSERT_EQ(r.film.totalNonfinite(), 0u);
  glm::dvec3 mean = r.film.imageMean(), var = r.film.imageMeanVarianceOfMean();
  for (int c = 0; c < 3; ++c) {
    double sigma = std::sqrt(var[c] / r.film.pixels());
    EXPECT_LT(sigma, 0.0018 * 2.0 / 5.0) << "the test must resolve a 0.18% bias at 5 sigma";
    EXPECT_TRUE(withinSigmas(zTest(mean[c], 2.0, sigma), 5.0)) << "channel " << c << ": " << mean[c];
  }
}

TEST(Furnace, DepthCapTruncatesToTheGeometricSeries) {
  // D scattering events collect emission at D + 1 vertices: L = Le (1 - a^(D+1)) / (1 - a) = 1.75 for D = 2.
  RenderOptions o = furnaceOptions(64);
  o.estimator.maxDepth = 2;
  RenderOutcome r = runRender(context(), o);
  glm::dvec3 mean = r.film.imageMean();
  glm::dvec3 var = r.film.imageMeanVarianceOfMean();
  for (int c = 0; c < 3; ++c)
    EXPECT_TRUE(withinSigmas(zTest(mean[c], 1.75, std::sqrt(var[c] / r.film.pixels()), 1e-6), 5.0)) << "channel " << c;
  EXPECT_LE(r.stats.maxBounces, 3u);
}
