// Error metrics on synthetic images with known answers; estimator configuration parsing and validation.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "analysis/error_metrics.h"
#include "analysis/student_t.h"
#include "error.h"
#include "../shaders/shared/roulette.h"
#include "estimators/efficiency_roulette.h"
#include "estimators/estimator_config.h"

using namespace vkmc;

namespace {
ExrImage constant(int w, int h, float v, float variance = -1.0f) {
  ExrImage img;
  img.width = w;
  img.height = h;
  for (const char* c : {"R", "G", "B"}) img.channels[c].assign(size_t(w) * h, v);
  if (variance >= 0.0f)
    for (const char* c : {"variance.R", "variance.G", "variance.B"}) img.channels[c].assign(size_t(w) * h, variance);
  return img;
}
}  // namespace

TEST(ErrorMetrics, KnownMseAndRelMse) {
  ExrImage ref = constant(8, 4, 0.5f), img = constant(8, 4, 0.6f);
  ErrorMetrics m = compareImages(img, ref);
  EXPECT_NEAR(m.mse, 0.01, 1e-7);
  EXPECT_NEAR(m.relmse, 0.01 / (0.25 + kRelMseEpsilon), 1e-6);
  EXPECT_NEAR(m.rmse, 0.1, 1e-6);
  EXPECT_NEAR(m.meanAbsoluteError, 0.1, 1e-6);
  EXPECT_NEAR(m.meanDifference, 0.1, 1e-6);
  EXPECT_FALSE(m.hasZTest);
}

// The reference's own noise, in relMSE terms: its variance channels over value^2 + epsilon; against a noisy
// reference an independent image's relMSE is its own relative variance plus that (the bench summary's line).
TEST(ErrorMetrics, AReferencesOwnNoiseAddsToEveryRelMse) {
  EXPECT_NEAR(referenceRelativeVariance(constant(4, 4, 0.5f, 0.002f)), 0.002 / (0.25 + kRelMseEpsilon), 1e-9);
  EXPECT_TRUE(std::isnan(referenceRelativeVariance(constant(4, 4, 0.5f))));
  const int w = 200, h = 200;
  const float truth = 0.5f, imageVar = 0.004f, referenceVar = 0.001f;
  ExrImage img = constant(w, h, truth), ref = constant(w, h, truth, referenceVar);
  std::mt19937 rng(17);
  std::normal_distribution<float> noise(0.0f, 1.0f);
  for (const char* c : {"R", "G", "B"})
    for (size_t p = 0; p < size_t(w) * h; ++p) {
      img.channels[c][p] += std::sqrt(imageVar) * noise(rng);
      ref.channels[c][p] += std::sqrt(referenceVar) * noise(rng);
    }
  const double expected = (imageVar + referenceVar) / (truth * truth + kRelMseEpsilon);
  // 120,000 squared normals: the relMSE's relative standard deviation is about 0.4%, the noisy denominators'
  // shift about 1.5% (below); 5% is beyond both.
  EXPECT_NEAR(compareImages(img, ref).relmse, expected, 0.05 * expected);
  // Noisy values in the denominators shift both by about Var(y^2) / (y^2 + epsilon)^2 = 1.5%.
  const double own = referenceVar / (truth * truth + kRelMseEpsilon);
  EXPECT_NEAR(referenceRelativeVariance(ref), own, 0.05 * own);
}

TEST(ErrorMetrics, ZTestCountsPixelsOutsideTheirNoise) {
  ExrImage ref = constant(10, 10, 1.0f, 0.01f), img = constant(10, 10, 1.0f, 0.01f);
  img.channels["G"][37] = 3.0f;  // 2 / sqrt(0.02) = 14 sigma
  img.channels["R"][5] = 1.2f;   // 1.4 sigma: passes
  ErrorMetrics m = compareImages(img, ref);
  ASSERT_TRUE(m.hasZTest);
  EXPECT_NEAR(m.zTestPassFraction, 0.99, 1e-12);
  EXPECT_GT(m.zThreshold, 3.5);  // Sidak over 300 tests at 1%
  EXPECT_LT(m.zThreshold, 4.5);
}

TEST(ErrorMetrics, WithDegreesOfFreedomEachPixelIsWelchsT) {
  // 9.2 sigma fails the z-test (Sidak over 300 tests: 4.1); at 3 + 3 dof (two QMC pixels: Welch's 6) the t
  // bound at that level is ~11, so the same difference passes; with 1000 dof each it fails again.
  ExrImage ref = constant(10, 10, 1.0f, 0.01f), img = constant(10, 10, 1.0f, 0.01f);
  img.channels["G"][37] = 2.3f;
  for (ExrImage* i : {&ref, &img}) i->channels["variance.dof"].assign(100, 3.0f);
  ErrorMetrics few = compareImages(img, ref);
  EXPECT_TRUE(few.studentT);
  EXPECT_EQ(few.zTestPassFraction, 1.0);
  img.channels["G"][37] = 300.0f;  // 2114 sigma: beyond t's bound at 6 dof too
  EXPECT_NEAR(compareImages(img, ref).zTestPassFraction, 0.99, 1e-12);
  img.channels["G"][37] = 2.3f;
  for (ExrImage* i : {&ref, &img}) i->channels["variance.dof"].assign(100, 1000.0f);
  EXPECT_NEAR(compareImages(img, ref).zTestPassFraction, 0.99, 1e-12);
}

TEST(StudentT, TailsAndBoundsMatchClosedForms) {
  // dof 1 (Cauchy): 1 - (2 / pi) atan(t); dof 2: 1 - t / sqrt(2 + t^2); many dof: the normal.
  for (double t : {0.1, 1.0, 2.0, 7.5, 100.0}) {
    EXPECT_NEAR(studentTwoSidedTail(t, 1.0), 1.0 - 2.0 / M_PI * std::atan(t), 1e-12) << t;
    EXPECT_NEAR(studentTwoSidedTail(t, 2.0), 1.0 - t / std::sqrt(2.0 + t * t), 1e-12) << t;
    EXPECT_NEAR(studentTwoSidedTail(t, 1e6), std::erfc(t / std::sqrt(2.0)), 1e-6) << t;  // t_1e6 by the beta
  }
  EXPECT_NEAR(studentTwoSidedTail(2.0, 10.0), 0.0733880347707, 1e-10);  // tables: t_10
  EXPECT_NEAR(studentTwoSidedTail(3.0, 1e5), std::erfc(3.0 / std::sqrt(2.0)), 1e-6);
  // The bound has the normal's false-positive rate at every dof.
  for (double dof : {1.0, 3.0, 10.0, 63.0, 4095.0})
    for (double k : {3.0, 5.0})
      EXPECT_NEAR(studentTwoSidedTail(studentBoundForSigmas(k, dof), dof), std::erfc(k / std::sqrt(2.0)),
                  1e-7 * std::erfc(k / std::sqrt(2.0)))
          << dof << " dof, " << k << " sigma";
  EXPECT_NEAR(studentBoundForSigmas(3.0, 3.0), 9.2189, 1e-3);  // t_3 at two-sided 0.0027
  // Welch: equal variances and dofs add their dofs; one exact variance leaves the other's dof.
  EXPECT_NEAR(welchDof(1.0, 3.0, 1.0, 3.0), 6.0, 1e-12);
  EXPECT_NEAR(welchDof(1.0, 3.0, 0.0, 3.0), 3.0, 1e-12);
}

TEST(ErrorMetrics, MismatchedImagesAreRejected) {
  EXPECT_THROW(compareImages(constant(4, 4, 1), constant(4, 5, 1)), Error);
  ExrImage noGreen = constant(4, 4, 1);
  noGreen.channels.erase("G");
  EXPECT_THROW(compareImages(noGreen, constant(4, 4, 1)), Error);
}

TEST(EstimatorConfig, JsonRoundTripAndDefaults) {
  EstimatorConfig c;
  c.rr = RouletteMode::Fixed;
  c.rrQ = 0.25f;
  c.lightSamples = 7;
  c.mis = MisHeuristic::Balance;
  c.lightSampling = LightSampling::SolidAngle;
  EstimatorConfig d;
  d.applyJson(c.toJson());
  EXPECT_EQ(d.toJson(), c.toJson());
  EXPECT_EQ(EstimatorConfig{}.toJson()["rr"], "throughput");
  EXPECT_EQ(EstimatorConfig{}.toJson()["bsdf_sampling"], "bsdf");
}

TEST(EstimatorConfig, RejectsUnknownKeysBadValuesAndEndlessPaths) {
  EstimatorConfig c;
  EXPECT_THROW(c.applyJson({{"rr_typo", 1}}), Error);
  EXPECT_THROW(c.applyJson({{"mis", "best"}}), Error);
  EXPECT_THROW(c.applyJson({{"light_samples", -2}}), Error);
  EstimatorConfig q;
  q.rrQ = 1.0f;
  EXPECT_THROW(q.validate(), Error);
  EstimatorConfig endless;
  endless.rr = RouletteMode::None;
  EXPECT_THROW(endless.validate(), Error) << "no roulette and no depth cap never ends";
  endless.maxDepth = 8;
  EXPECT_NO_THROW(endless.validate());
  EstimatorConfig never;
  never.rr = RouletteMode::Fixed;
  never.rrQ = 0.0f;
  EXPECT_THROW(never.validate(), Error) << "survival 1 at every depth never ends a path";
  never.maxDepth = 4;
  EXPECT_NO_THROW(never.validate());
  EstimatorConfig late;
  late.rrDepth = 100000;
  EXPECT_THROW(late.validate(), Error) << "no roulette for 100000 bounces is a hang in a closed scene";
}

namespace {
// 1000 pilot paths alike: each gathers `gathered` by every depth and ends at lastDepth with `radiance`.
std::vector<PilotPath> alikePaths(float radiance, uint32_t lastDepth, float beta, float gathered) {
  std::vector<PilotPath> pilot(1000);
  for (PilotPath& p : pilot) {
    p.radiance = radiance;
    p.lastDepth = lastDepth;
    p.beta.fill(beta);
    p.gathered.fill(gathered);
  }
  return pilot;
}
}  // namespace

TEST(EfficiencyRoulette, KillsFreelyWhereTheContinuationAddsNothing) {
  // Every path gathers all of its estimate by depth 1: later decisions may kill at no variance cost.
  std::vector<PilotPath> pilot = alikePaths(1.0f, 10, 0.5f, 1.0f);
  RouletteTable t = optimizeRouletteScales(pilot, 0.1, 2.0, 1);
  EXPECT_TRUE(std::isinf(t.scale[0])) << "depths before the first decision are left alone";
  for (uint32_t d = 1; d < 9; ++d) {
    EXPECT_NEAR(t.scale[d], 0.01f, 1e-6f) << "depth " << d;
    // No variance is added, so the gain is the cost ratio: 1 + 2 x 11 rays against what remains after killing
    // with survival 0.01 x 0.5 the 2 (10 - d) rays of the continuation.
    double saved = (1.0 - 0.005) * 2.0 * (10 - d);
    EXPECT_NEAR(t.predictedGain[d], 23.0 / (23.0 - saved), 1e-6) << "depth " << d;
  }
}

TEST(EfficiencyRoulette, KeepsPathsWhoseContinuationCarriesTheEstimate) {
  // The whole estimate arrives late and cheaply: killing would add far more variance than it saves cost.
  std::vector<PilotPath> pilot = alikePaths(10.0f, 4, 0.9f, 0.0f);
  RouletteTable t = optimizeRouletteScales(pilot, 1e-4, 2.0, 1);
  for (uint32_t d = 1; d < 4; ++d) EXPECT_GE(t.scale[d], 1.0f / 0.9f) << "depth " << d << ": survival must stay 1";
}

// The table's predicted efficiency against the throughput rule (what --estimator auto reads before it spends a pilot
// pass on rr efficiency): each path's decisions in sequence, as the kernels take them.
TEST(EfficiencyRoulette, PredictsNoGainWherePathsEndBeforeTheRouletteDepth) {
  std::vector<PilotPath> pilot(1000);
  for (size_t i = 0; i < pilot.size(); ++i) {
    PilotPath& p = pilot[i];
    p.radiance = float(i % 7);
    p.lastDepth = 1;
    p.beta.fill(-1.0f), p.gathered.fill(-1.0f);
    p.beta[0] = 0.5f, p.gathered[0] = p.radiance;
  }
  EXPECT_EQ(optimizeRouletteScales(pilot, 0.3, 2.0, 2).gainOverThroughput, 1.0) << "no decision: both rules alike";
}

TEST(EfficiencyRoulette, PredictsTheCostSavedWhereTheContinuationAddsNothing) {
  // As KillsFreely...: every path has gathered its estimate by depth 1, so only the rays differ. The table's
  // scale 0.01 at depth 1 keeps 0.005 of the paths, whose throughput is then 100, so every later decision
  // survives with the cap (0.999): 2 + 0.005 (1 + 0.999 + ... + 0.999^8) vertices. The sqrt rule survives with
  // sqrt(beta / P), P what survived before.
  std::vector<PilotPath> pilot = alikePaths(1.0f, 10, 0.5f, 1.0f);
  const RouletteTable t = optimizeRouletteScales(pilot, 0.1, 2.0, 1);
  ASSERT_NEAR(t.scale[1], 0.01f, 1e-6f);
  double reach = 1.0, vertices = 0.0;
  for (uint32_t d = 0; d <= 10; ++d) {
    vertices += reach;
    if (d >= 1) reach *= std::min(std::sqrt(0.5 / reach), double(gpu::kRouletteMaxSurvival));
  }
  double capped = 0.0;
  for (int j = 0; j < 9; ++j) capped += std::pow(double(gpu::kRouletteMaxSurvival), j);
  const double sqrtRays = 1.0 + 2.0 * vertices, tableRays = 1.0 + 2.0 * (2.0 + 0.005 * capped);
  EXPECT_NEAR(t.gainOverThroughput, sqrtRays / tableRays, 1e-4 * sqrtRays / tableRays);
}

TEST(EfficiencyRoulette, PredictsTheVarianceTheThroughputRuleAddsWhereTheEstimateArrivesLate) {
  // As KeepsPaths...: the whole estimate (10, weight 1) arrives after the last decision. The table's scales keep
  // every path but for the survival cap (0.999 at each of depths 1-4); the sqrt rule survives with sqrt(0.9 / P).
  // Each adds 100 (1/P - 1) to the second moment of 1e-4, P the probability of surviving all four decisions.
  std::vector<PilotPath> pilot = alikePaths(10.0f, 4, 0.9f, 0.0f);
  const RouletteTable t = optimizeRouletteScales(pilot, 1e-4, 2.0, 1);
  for (uint32_t d = 1; d <= 4; ++d) ASSERT_GE(t.scale[d] * 0.9f, 1.0f) << "depth " << d;
  auto product = [](auto survival) {
    double reach = 1.0, vertices = 0.0;
    for (uint32_t d = 0; d <= 4; ++d) {
      vertices += reach;
      if (d >= 1) reach *= survival(0.9 / reach);
    }
    return (1e-4 + 100.0 * (1.0 / reach - 1.0)) * (1.0 + 2.0 * vertices);
  };
  const double cap = gpu::kRouletteMaxSurvival;
  const double expected = product([&](double b) { return std::min(std::sqrt(b), cap); }) / product([&](double) { return cap; });
  EXPECT_NEAR(t.gainOverThroughput, expected, 1e-4 * expected);
  EXPECT_GT(t.gainOverThroughput, 10.0) << "the sqrt rule's variance far outweighs the rays it saves";
}

// A NaN or an infinity in either image would make every metric NaN (and `compare` exit 0 with it): refused, naming
// the image, the pixel and the channel.
TEST(ErrorMetrics, NonFiniteImagesAreRefused) {
  ExrImage img, ref;
  img.width = ref.width = 2, img.height = ref.height = 1;
  for (const char* c : {"R", "G", "B"}) img.channels[c] = ref.channels[c] = {1.0f, 2.0f};
  EXPECT_NO_THROW(compareImages(img, ref));
  img.channels["G"][1] = std::nanf("");
  try {
    compareImages(img, ref);
    ADD_FAILURE() << "a NaN pixel was compared";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the image's pixel (1, 0) has a non-finite G"), std::string::npos) << e.what();
  }
  img.channels["G"][1] = 2.0f;
  ref.channels["variance.R"] = {0.0f, INFINITY};
  EXPECT_THROW(compareImages(img, ref), Error);
}
