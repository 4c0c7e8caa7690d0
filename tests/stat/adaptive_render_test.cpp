// Adaptive sampling and --target-error on the device (policy/sample_rounds.h): the image stays unbiased (the
// white furnace's analytic L = 2; the Cornell box against a uniform render), the variance it reports is the spread
// it has, and a target error is met. Sized by samples; fixed seeds. The bias they would catch: rounds combined by
// their sample counts (the classic trap: tens of percent on pixels whose first round saw no light), a run's
// samples written to the wrong pixel or sample number (a shifted or repeated image), or a variance that forgets
// the rounds' weights (off by the allocation's spread, a factor of 2 to 8 on the box's noisy pixels).
#include <gtest/gtest.h>

#include "support/render_helpers.h"

using namespace vkmc;
using namespace vkmc::test;

namespace {

RenderOutcome renderRounds(const std::string& scene, uint32_t w, uint32_t h, uint32_t spp, uint32_t seed, bool adaptive,
                           double targetError = 0.0) {
  RenderOptions o = optionsFor(scene, EstimatorConfig{}, w, h, spp, seed);
  o.adaptive = adaptive;
  o.targetError = targetError;
  return runRender(sharedContext(), o);
}

}  // namespace

TEST(AdaptiveRender, FurnaceMatchesTheAnalyticValue) {
  const RenderOutcome r = renderRounds("furnace.gltf", 16, 16, 256, 17, true);
  ASSERT_TRUE(r.rounds);
  EXPECT_EQ(r.rounds->rounds, 3u);  // 64, 64 and 128 samples a pixel: a pass holds 64 of a 16x16 image
  ASSERT_EQ(r.film.totalNonfinite(), 0u);
  EXPECT_TRUE(regionMatches(whole(r.film), glm::dvec3(2.0), 5.0));
  for (uint32_t q = 0; q < 4; ++q)
    EXPECT_TRUE(regionMatches(region(r.film, (q % 2) * 8, (q / 2) * 8, (q % 2) * 8 + 8, (q / 2) * 8 + 8), glm::dvec3(2.0), 5.0))
        << "quadrant " << q;
}

TEST(AdaptiveRender, CornellBoxMatchesAUniformRenderAndReportsItsSpread) {
  const RenderOutcome uniform = renderWith("cornell_box.gltf", EstimatorConfig{}, 32, 32, 512, 999);
  const RenderOutcome adaptive = renderRounds("cornell_box.gltf", 32, 32, 256, 31, true);
  ASSERT_TRUE(adaptive.rounds);
  // The allocation did spread the samples (the box's light and its corners are far noisier than its walls), within
  // its floor (a quarter of the mean a round) and the image prior.
  EXPECT_GT(adaptive.rounds->maxPixelSamples, 2 * adaptive.rounds->minPixelSamples);
  EXPECT_TRUE(regionsAgree(whole(adaptive.film), whole(uniform.film), 5.0));
  for (uint32_t q = 0; q < 4; ++q)
    EXPECT_TRUE(regionsAgree(region(adaptive.film, (q % 2) * 16, (q / 2) * 16, (q % 2) * 16 + 16, (q / 2) * 16 + 16),
                             region(uniform.film, (q % 2) * 16, (q / 2) * 16, (q % 2) * 16 + 16, (q / 2) * 16 + 16), 5.0))
        << "quadrant " << q;
  // Per pixel, E[(a - u)^2] = Var(a) + Var(u) where both variances are honest: the mean of the difference
  // d_p = (a - u)^2 - (V_a + V_u) over pixels and channels is 0, tested against its own spread.
  EXPECT_TRUE(variancesAreHonest(adaptive.film, uniform.film, 5.0));
}

// The furnace's reference is exact (L = 2), so a render's relMSE against it is its own error alone. The bound is
// one-sided 95%: of 10 renders, at most 3 may miss E (a 5% miss rate gives 4 or more misses with probability 1e-3).
TEST(TargetError, FurnaceRendersMeetTheTarget) {
  const double target = 1e-3;
  int misses = 0;
  for (uint32_t seed = 1; seed <= 10; ++seed) {
    const RenderOutcome r = renderRounds("furnace.gltf", 16, 16, 1u << 16, seed, false, target);
    ASSERT_TRUE(r.rounds);
    EXPECT_TRUE(r.rounds->targetReached) << "seed " << seed;
    EXPECT_LE(r.rounds->relMse.upper, target);
    double relmse = 0.0;
    for (size_t p = 0; p < r.film.pixels(); ++p)
      for (int c = 0; c < 3; ++c) relmse += std::pow(r.film.mean(p, c) - 2.0, 2) / (4.0 + kRelMseEpsilon);
    relmse /= 3.0 * double(r.film.pixels());
    misses += relmse > target;
  }
  EXPECT_LE(misses, 3);
}
