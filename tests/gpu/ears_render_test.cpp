// rr ears on the device: what the cache learns against the analytic answer, its factor histogram, its memory
// bound, determinism and its refusals. Its unbiasedness is in stat/estimator_unbiased_test (furnace, Cornell box,
// stiff furnace) and stiff/stiff_render_test (tiny light).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "analysis/error_metrics.h"
#include "error.h"
#include "support/render_helpers.h"

using namespace vkmc;
using namespace vkmc::test;

namespace {
// EARS throughout: what these tests check is the cache's, not the guard's choice (which measures time).
EstimatorConfig ears() {
  EstimatorConfig e;
  e.rr = RouletteMode::Ears;
  e.earsFallback = EarsFallback::Never;
  return e;
}
}  // namespace

TEST(Ears, FurnaceCacheLearnsTheReflectedRadiance) {
  // Albedo 0.5, Le 1: L = 2 everywhere and the radiance a vertex reflects, per unit throughput, is a L = 1 in
  // every channel. A path's records are correlated (one path's copies at depths 0-3 share what follows), so the
  // standard error counts kEarsDepths records as one.
  RenderOutcome r = renderWith("furnace.gltf", ears(), 32, 32, 64);
  ASSERT_TRUE(r.ears);
  const EarsSummary& e = *r.ears;
  ASSERT_GT(e.copies, 1e4);
  EXPECT_GT(e.learningPasses, 0u);
  EXPECT_GT(e.trustedCells, 0u);
  for (int c = 0; c < 3; ++c) {
    const double variance = e.meanLrSquared[c] - e.meanLr[c] * e.meanLr[c];
    const double se = std::sqrt(variance / (e.copies / gpu::kEarsDepths));
    EXPECT_TRUE(withinSigmas(zTest(e.meanLr[c], 1.0, se), 5.0)) << "channel " << c << ": " << e.meanLr[c] << " +- " << se;
  }
  // Each copy costs at least its continuation ray or light sample when it gathers anything.
  EXPECT_GT(e.meanRays, 1.0);
  // Every camera ray hits the sphere: the first row of the histogram counts each sample's first vertex once,
  // the dropped training passes' (2 + 4 spp, not in the image) too; the first (1 spp) is one of the image's 64.
  EXPECT_EQ(e.trainingSamples, 6u);
  EXPECT_EQ(r.film.totalSamples(), 32u * 32u * 64u);
  uint64_t first = 0;
  for (uint64_t n : e.factors[0]) first += n;
  EXPECT_EQ(first, 32u * 32u * (64u + e.trainingSamples));
  EXPECT_GT(e.factors[0][gpu::kEarsBinSplit] + e.factors[0][gpu::kEarsBinRoulette] + e.factors[0][gpu::kEarsBinOne], 0u)
      << "learned factors must decide some first vertices";
}

TEST(Ears, TheFoldResolvesEachCellAsTheHostDoesFromItsLevelsSums) {
  // What a vertex reads (its finest cell's texels) against the same resolution on the host (ears.h
  // earsResolveLevel) from the table's sums of that cell's three levels, on the Cornell box (light cells too).
  EstimatorConfig e = ears();
  e.earsLightMax = 4.0f;
  const RenderOptions o = optionsFor("cornell_box.gltf", e, 32, 32, 32);
  std::vector<gpu::EarsCell> cells;
  std::vector<glm::vec4> texels;
  uint32_t cellCount = 0, cellMask = 0;
  RunControl run;
  run.inspect = [&](PathRenderer& renderer) {
    cells = renderer.ears().downloadCells();
    texels = renderer.ears().downloadSampling();
    cellCount = renderer.ears().cellCount();
  };
  runRender(sharedContext(), o, run);
  ASSERT_GT(cellCount, 0u);
  ASSERT_EQ(cells.size(), 2u * cellCount);  // the copies' cells, then the light cells
  cellMask = cellCount - 1;
  uint32_t resolved = 0, trusted = 0, lightLearned = 0;
  for (uint32_t slot = 0; slot < cellCount; ++slot) {
    const glm::vec4 variance = texels[gpu::kEarsSamplingTexels * slot + 1];
    ASSERT_EQ(variance.w, std::floor(variance.w));  // a whole key + 1 (0: not resolved)
    const uint32_t keyCode = uint32_t(variance.w);
    if (keyCode == 0) continue;
    ++resolved;
    // The key resolved here hashes here at the finest level.
    ASSERT_EQ(gpu::earsCellIndex(keyCode - 1, 0, cellMask), slot);
    for (bool light : {false, true}) {
      glm::vec3 m(0.0f), v(0.0f);
      float copies = 0.0f;
      for (int level = int(gpu::kEarsLevels) - 1; level >= 0; --level) {
        uint32_t c = gpu::earsCellIndex(keyCode - 1, uint32_t(level), cellMask);
        if (light) c = gpu::earsLightCell(c, cellMask);
        gpu::earsResolveLevel(cells[c].sum, cells[c].sumSquares, m, v, copies);
      }
      const uint32_t at = light ? gpu::earsLightCell(slot, cellMask) : slot;
      const glm::vec4 dm = texels[gpu::kEarsSamplingTexels * at], dv = texels[gpu::kEarsSamplingTexels * at + 1];
      EXPECT_EQ(dm.w, copies) << "slot " << slot << (light ? " (light)" : "");
      // The variance, a difference of the moments, is as exact as the second moment it cancels from.
      for (int c = 0; c < 3; ++c) {
        const float tolerance = 1e-5f * std::max(1.0f, std::abs(m[c]));
        EXPECT_NEAR(dm[c], m[c], tolerance) << "slot " << slot << " channel " << c;
        EXPECT_NEAR(dv[c], v[c], tolerance) << "slot " << slot << " channel " << c;
      }
      EXPECT_EQ(dv.w, variance.w) << "the light cell is resolved for the same key";
      trusted += !light && copies >= gpu::kEarsMinCellCopies;
      lightLearned += light && copies > 0.0f;
    }
  }
  EXPECT_GT(resolved, 100u);
  EXPECT_GT(trusted, 0u);
  EXPECT_GT(lightLearned, 0u);
}

TEST(Ears, FurnaceLightCellsLearnTheDirectLight) {
  // Light sampling alone (mis none): one light sample of the emitting sphere, seen from inside, gathers per unit
  // throughput the direct light a Le = 0.5 in every channel, and every sample traces a shadow ray. Records are
  // counted as in the test above.
  EstimatorConfig e = ears();
  e.mis = MisHeuristic::None;
  e.earsLightMax = gpu::kEarsLightFactorMax;
  RenderOutcome r = renderWith("furnace.gltf", e, 32, 32, 64);
  ASSERT_TRUE(r.ears);
  const EarsSummary& s = *r.ears;
  ASSERT_TRUE(s.learnsLight);
  ASSERT_GT(s.lightSamples, 1e4);
  EXPECT_GT(s.trustedLightCells, 0u);
  EXPECT_LE(s.occupiedLightCells, s.cells);
  for (int c = 0; c < 3; ++c) {
    const double variance = s.meanVSquared[c] - s.meanV[c] * s.meanV[c];
    const double se = std::sqrt(variance / (s.lightSamples / gpu::kEarsDepths));
    EXPECT_TRUE(withinSigmas(zTest(s.meanV[c], 0.5, se), 5.0)) << "channel " << c << ": " << s.meanV[c] << " +- " << se;
  }
  EXPECT_GT(s.meanLightRays, 0.99);
  EXPECT_LE(s.meanLightRays, 1.0);
  // The learned light factors decide the first vertices' light samples once the cells are trusted.
  const auto& first = s.lightFactors[0];
  EXPECT_GT(first[gpu::kEarsBinRoulette] + first[gpu::kEarsBinOne] + first[gpu::kEarsBinSplit], 0u);
  EXPECT_EQ(r.film.totalNonfinite(), 0u);
}

// On the glossy room most light samples gather little for their ray: the light cells roulette them, so fewer
// shadow rays are traced for the same image (independent seeds; docs/journal/ears.md has the measurement).
TEST(Ears, LearnedLightSamplesRouletteShadowRaysAndKeepTheMean) {
  EstimatorConfig learned = ears();
  learned.earsLightMax = gpu::kEarsLightFactorMax;
  RenderOutcome off = renderWith("glossy_room.gltf", ears(), 32, 32, 32, 11);
  RenderOutcome on = renderWith("glossy_room.gltf", learned, 32, 32, 32, 12);
  ASSERT_TRUE(off.ears && on.ears);
  EXPECT_FALSE(off.ears->learnsLight);
  ASSERT_TRUE(on.ears->learnsLight);
  uint64_t rouletted = 0;
  for (const auto& depth : on.ears->lightFactors) rouletted += depth[gpu::kEarsBinRoulette];
  EXPECT_GT(rouletted, 0u);
  const double shadowPerVertexOff = double(off.stats.shadowRays) / double(off.stats.cameraRays + off.stats.extensionRays);
  const double shadowPerVertexOn = double(on.stats.shadowRays) / double(on.stats.cameraRays + on.stats.extensionRays);
  EXPECT_LT(shadowPerVertexOn, 0.8 * shadowPerVertexOff);
  EXPECT_TRUE(regionsAgree(whole(on.film), whole(off.film), 4.0));
  EXPECT_EQ(on.film.totalNonfinite(), 0u);
}

// ears_max bounds the factor: at 1 the cache decides roulette alone and no vertex splits, where the default (20)
// splits on the room lit through a slit.
TEST(Ears, AMaximumOfOneLearnsRouletteAloneAndNeverSplits) {
  auto splits = [](const EarsSummary& e) {
    uint64_t n = 0;
    for (const auto& depth : e.factors) n += depth[gpu::kEarsBinSplit];
    return n;
  };
  RenderOutcome free = renderWith("two_rooms.gltf", ears(), 24, 24, 16);
  EstimatorConfig rouletteOnly = ears();
  rouletteOnly.earsMax = 1.0f;
  RenderOutcome bounded = renderWith("two_rooms.gltf", rouletteOnly, 24, 24, 16);
  ASSERT_TRUE(free.ears && bounded.ears);
  EXPECT_GT(splits(*free.ears), 0u);
  EXPECT_EQ(splits(*bounded.ears), 0u);
  uint64_t rouletted = 0;
  for (const auto& depth : bounded.ears->factors) rouletted += depth[gpu::kEarsBinRoulette];
  EXPECT_GT(rouletted, 0u) << "the learned factors still decide roulette";
  EXPECT_LT(bounded.stats.rays(), free.stats.rays());
}

// dark_room (docs/journal/ears.md, ADRRS's motivating case): dark walls lit by a bright room's multi-bounce light through a
// doorway. Throughput roulette keeps the paths that carry most of a pixel's value with probability about a tenth,
// weight 10; EARS learns to keep them. So its honest relative variance times its rays (a cost the machine's load
// cannot change) is below throughput roulette's (0.34-0.43x in this size's renders with seeds 1-4, 0.44-0.57x at
// 48x48 x 64 spp), and its image mean agrees.
TEST(Ears, OnDarkWallsLitIndirectlyItSpendsRaysBetterThanThroughputRoulette) {
  RenderOutcome t = renderWith("dark_room.gltf", EstimatorConfig{}, 64, 64, 128, 21);
  RenderOutcome e = renderWith("dark_room.gltf", ears(), 64, 64, 128, 22);
  ASSERT_EQ(EstimatorConfig{}.rr, RouletteMode::Throughput);
  const double costT = t.film.meanRelativeVariance(kRelMseEpsilon) * double(t.stats.rays());
  const double costE = e.film.meanRelativeVariance(kRelMseEpsilon) * double(e.stats.rays());
  EXPECT_LT(costE, 0.6 * costT) << "relative variance x rays: ears " << costE << ", throughput " << costT;
  EXPECT_TRUE(regionsAgree(whole(e.film), whole(t.film), 4.0));
  EXPECT_EQ(e.film.totalNonfinite() + t.film.totalNonfinite(), 0u);
}

TEST(Ears, SameSeedSameImage) {
  RenderOutcome a = renderWith("cornell_box.gltf", ears(), 24, 24, 8, 7);
  RenderOutcome b = renderWith("cornell_box.gltf", ears(), 24, 24, 8, 7);
  ASSERT_EQ(a.film.sum.size(), b.film.sum.size());
  for (size_t i = 0; i < a.film.sum.size(); ++i) ASSERT_EQ(a.film.sum[i], b.film.sum[i]) << "value " << i;
  EXPECT_EQ(a.stats.rays(), b.stats.rays());
}

// The guard (ears_guard.h): after a warm-up pass of EARS, 4 samples a pixel of EARS and a pass of throughput
// roulette as large as its later ones are measured, EARS again on its next pass where the first measure was close,
// then the rest rendered by the choice. `always` takes the second look and then the switch whatever was measured,
// so it is reproducible; `never` never compares.
TEST(Ears, GuardComparesOnePassEachThenRendersTheRestWithItsChoice) {
  EstimatorConfig always = ears();
  always.earsFallback = EarsFallback::Always;
  RenderOutcome a = renderWith("furnace.gltf", always, 24, 24, 128);
  ASSERT_TRUE(a.ears);
  const EarsGuardOutcome& g = a.earsGuard;
  ASSERT_TRUE(g.compared);
  EXPECT_TRUE(g.fellBack);
  // Training passes (1, 2, 4 spp, dropped), then EARS's warm-up pass of 8, its measured 4, throughput roulette's
  // measured pass of 64 (a pass's most at 24 x 24; dropped), and EARS's second look, 4 again.
  ASSERT_TRUE(g.secondLook);
  EXPECT_EQ(g.firstEars.samples, 4u);
  EXPECT_EQ(g.ears.samples, 4u);
  EXPECT_EQ(g.throughput.samples, 64u);
  EXPECT_EQ(g.fromSample, 17u);  // after the first training pass, which stays
  EXPECT_EQ(a.film.totalSamples(), 24u * 24u * 128u);
  // What choosing cost, on the render's own clock: its 17 kept samples count at the rest's rate.
  EXPECT_GT(g.decidedAtSeconds, 0.0);
  ASSERT_TRUE(std::isfinite(g.learningCostSeconds));
  EXPECT_LT(g.learningCostSeconds, g.decidedAtSeconds);
  for (const PolicyPass& p : {g.ears, g.throughput}) {
    EXPECT_GT(p.relativeVariance, 0.0);
    EXPECT_GT(p.secondsPerSample, 0.0);
    EXPECT_GT(p.efficiency(), 0.0);
    EXPECT_TRUE(std::isfinite(p.efficiency()));
  }
  // Throughput roulette's passes render the rest: their first vertices (every camera ray hits the sphere) are not
  // counted in EARS's histogram, which holds the dropped training passes' (2 + 4), the kept one's (1) and EARS's
  // 8 + 4 + 4 samples a pixel.
  uint64_t first = 0;
  for (uint64_t n : a.ears->factors[0]) first += n;
  EXPECT_EQ(a.ears->trainingSamples, 6u);
  EXPECT_EQ(first, 24u * 24u * (a.ears->trainingSamples + 17u));
  // Unbiased across the switch (stat/estimator_unbiased_test has the Cornell box's and the quadrants'): L = 2.
  EXPECT_TRUE(regionMatches(whole(a.film), glm::dvec3(2.0), 5.0));
  // Auto compares too; never does not.
  EstimatorConfig automatic = ears();
  automatic.earsFallback = EarsFallback::Auto;
  EXPECT_TRUE(renderWith("cornell_box.gltf", automatic, 24, 24, 32).earsGuard.compared);
  EXPECT_FALSE(renderWith("cornell_box.gltf", ears(), 24, 24, 32).earsGuard.compared);
  // Too few samples for the comparison: EARS renders them all.
  EXPECT_FALSE(renderWith("cornell_box.gltf", automatic, 24, 24, 10).earsGuard.compared);
}

// Where a pass takes one sample a pixel in tiles (a wavefront of 1024 paths on 48 x 48 pixels: three tiles), the
// guard measures EARS over four passes and throughput roulette over four more, every tile's time counted.
TEST(Ears, GuardMeasuresOverSeveralTiledPasses) {
  RenderOptions o;
  o.scenePath = scenePath("furnace.gltf");
  o.width = o.height = 48;
  o.spp = 16;
  o.wavefrontPaths = 1024;
  o.estimator = ears();
  o.estimator.earsFallback = EarsFallback::Always;
  o.progress = false;
  RenderOutcome r = runRender(sharedContext(), o);
  ASSERT_TRUE(r.ears);
  ASSERT_TRUE(r.earsGuard.compared);
  // Training passes of one sample each (the first kept, 2 dropped), the warm-up pass (1), then 4 of EARS and 4 of
  // throughput roulette (dropped) measured, and EARS's 4 again.
  EXPECT_EQ(r.ears->trainingSamples, 2u);
  EXPECT_EQ(r.earsGuard.firstEars.samples, 4u);
  EXPECT_EQ(r.earsGuard.ears.samples, 4u);
  EXPECT_EQ(r.earsGuard.throughput.samples, 4u);
  EXPECT_EQ(r.earsGuard.fromSample, 10u);
  EXPECT_GT(r.earsGuard.ears.secondsPerSample, 0.0);
  EXPECT_GT(r.earsGuard.throughput.secondsPerSample, 0.0);
  EXPECT_EQ(r.film.totalSamples(), 48u * 48u * 16u);
  EXPECT_TRUE(regionMatches(whole(r.film), glm::dvec3(2.0), 5.0));
}

// Under a time budget too short for EARS to learn and the guard to compare (kEarsLearningBudgetShare of it),
// training stops after its first pass and, under auto, throughput roulette renders the image without a
// comparison; under never, EARS goes on with what it learned. (A budget of a microsecond: no pass fits in a
// quarter of it on any device, so this depends on no machine's speed.)
TEST(Ears, ABudgetTooShortToLearnIn) {
  for (EarsFallback mode : {EarsFallback::Auto, EarsFallback::Never}) {
    RenderOptions o;
    o.scenePath = scenePath("furnace.gltf");
    o.width = o.height = 16;
    o.spp = 64;
    o.timeBudget = 1e-6;
    o.estimator = ears();
    o.estimator.earsFallback = mode;
    o.progress = false;
    RenderOutcome r = runRender(sharedContext(), o);
    ASSERT_TRUE(r.ears);
    EXPECT_TRUE(r.earsGuard.outOfBudget);
    EXPECT_FALSE(r.earsGuard.compared);
    EXPECT_EQ(r.earsGuard.fellBack, mode == EarsFallback::Auto);
    EXPECT_EQ(r.earsGuard.fromSample, 1u) << "after the first training pass, which stays";
    EXPECT_EQ(r.ears->trainingSamples, 0u) << "training stops after its first pass, and that one stays";
    EXPECT_EQ(r.film.totalSamples(), 16u * 16u) << "one pass, as any render whose budget is spent";
    EXPECT_NE(earsGuardLine(r.earsGuard).find("time budget"), std::string::npos);
    EXPECT_TRUE(std::isnan(r.earsGuard.passOverhead)) << "no second pass of throughput roulette";
    EXPECT_GE(r.earsGuard.decidedAtSeconds, 0.0);
    EXPECT_TRUE(std::isnan(r.earsGuard.learningCostSeconds)) << "no pass after the decision to cost it by";
  }
}

// Where the guard falls back, its image holds throughput roulette's own samples: the fallback's kernels (shade and
// the shadow stage built with throughput roulette beside EARS's) draw the same random numbers with the same seed,
// so its equal-time ratio to throughput roulette is its ratio of samples reached, and what it costs is its choosing
// (ears.guard.learning_cost_seconds). Out of budget, the guard's one pass is that fallback's first; the Cornell box's
// area light gives it a shadow stage, so both of the fallback's own kernels run.
TEST(Ears, FallenBackItRendersThroughputRoulettesOwnSamples) {
  EstimatorConfig guarded = ears();
  guarded.earsFallback = EarsFallback::Auto;
  RenderOptions withGuard = optionsFor("cornell_box.gltf", guarded, 24, 24, 64);
  RenderOptions throughput = optionsFor("cornell_box.gltf", EstimatorConfig{}, 24, 24, 64);
  withGuard.timeBudget = throughput.timeBudget = 1e-6;  // one pass of one sample a pixel, on any device
  RenderOutcome g = runRender(sharedContext(), withGuard);
  RenderOutcome t = runRender(sharedContext(), throughput);
  ASSERT_TRUE(g.ears);
  ASSERT_TRUE(g.earsGuard.outOfBudget);
  ASSERT_TRUE(g.earsGuard.fellBack);
  ASSERT_EQ(g.film.totalSamples(), t.film.totalSamples());
  ASSERT_EQ(g.film.sum.size(), t.film.sum.size());
  size_t nonzero = 0;
  for (size_t i = 0; i < g.film.sum.size(); ++i) {
    ASSERT_EQ(g.film.sum[i], t.film.sum[i]) << "value " << i;
    nonzero += g.film.sum[i] != 0.0 ? 1 : 0;
  }
  EXPECT_GT(nonzero, g.film.sum.size() / 2) << "an image, not two empty films";
}

// Under a budget that learning fits (an hour, on a 16x16 furnace), auto's first two passes are throughput
// roulette's own (1 and 2 samples a pixel, kept): they measure a pass's fixed overhead, which costs the guard's
// measured pass (ears_guard.h earsThroughputPassSeconds); then EARS trains, the guard compares, and the image
// stays unbiased.
TEST(Ears, UnderABudgetTwoThroughputPassesMeasureAPasssOverhead) {
  EstimatorConfig guarded = ears();
  guarded.earsFallback = EarsFallback::Auto;
  RenderOptions o = optionsFor("furnace.gltf", guarded, 16, 16, 64);
  o.timeBudget = 3600.0;
  RenderOutcome r = runRender(sharedContext(), o);
  ASSERT_TRUE(r.ears);
  EXPECT_FALSE(r.earsGuard.outOfBudget);
  EXPECT_TRUE(r.earsGuard.compared);
  ASSERT_TRUE(std::isfinite(r.earsGuard.passOverhead));
  EXPECT_GE(r.earsGuard.passOverhead, 0.0);
  EXPECT_GE(r.earsGuard.fromSample, 3u) << "both throughput passes stay in the image";
  EXPECT_EQ(r.film.totalSamples(), 16u * 16u * 64u);
  EXPECT_TRUE(regionMatches(whole(r.film), glm::dvec3(2.0), 5.0));
}

TEST(Ears, GuardWithAlwaysIsReproducible) {
  EstimatorConfig always = ears();
  always.earsFallback = EarsFallback::Always;
  RenderOutcome a = renderWith("cornell_box.gltf", always, 16, 16, 24, 3);
  RenderOutcome b = renderWith("cornell_box.gltf", always, 16, 16, 24, 3);
  ASSERT_EQ(a.film.sum.size(), b.film.sum.size());
  for (size_t i = 0; i < a.film.sum.size(); ++i) ASSERT_EQ(a.film.sum[i], b.film.sum[i]) << "value " << i;
}

TEST(Ears, MemoryIsBoundedOnAMillionTriangles) {
  const std::filesystem::path model =
      std::filesystem::path(VKMC_SHARED_SCENES) / "MetalRoughSpheresNoTextures" / "MetalRoughSpheresNoTextures.gltf";
  if (!std::filesystem::exists(model)) GTEST_SKIP() << "no " << model;
  RenderOptions o;
  o.scenePath = model.string();
  o.width = o.height = 32;
  o.spp = 2;
  o.estimator = ears();
  o.progress = false;
  RenderOutcome r = runRender(sharedContext(), o);
  ASSERT_TRUE(r.ears);
  EXPECT_GT(r.sceneInfo.triangles, 500000u);
  // The cache does not grow with the scene: at most 2^19 cells (sums, a key word and learned texels; light cells
  // are off by default), and each path slot's records, slot sums and training-list entries (a record index per
  // record, a slot index per slot).
  const uint64_t slots = uint64_t(32 * 32 * 2) * kEarsPoolFactor;
  const uint64_t perSlot = gpu::kEarsDepths * (sizeof(gpu::EarsRecord) + 4) + sizeof(gpu::EarsSlot) + 4;
  EXPECT_LE(r.ears->deviceBytes, (uint64_t(1) << 19) * (sizeof(gpu::EarsCell) + 4 + gpu::kEarsSamplingTexels * 16) +
                                     slots * perSlot + sizeof(gpu::EarsHeader));
  EXPECT_LE(r.ears->occupiedCells, r.ears->cells);
  EXPECT_EQ(r.film.totalNonfinite(), 0u);
}

TEST(Ears, RefusedWhereItCannotSplit) {
  RenderOptions o;
  o.scenePath = scenePath("cornell_box.gltf");
  o.width = o.height = 8;
  o.spp = 1;
  o.estimator = ears();
  o.integrator = Integrator::Megakernel;
  try {
    runRender(sharedContext(), o);
    FAIL() << "the megakernel cannot split paths";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("rr ears"), std::string::npos) << e.what();
  }
  EstimatorConfig both = ears();
  both.bsdfSamples = 2.0f;
  EXPECT_THROW(both.validate(), Error);
}
