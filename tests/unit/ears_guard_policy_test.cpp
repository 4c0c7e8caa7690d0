// rr ears's pass policy (host/passes/ears_guard_policy.h) without a GPU: a made-up renderer carries out its plans,
// each pass's samples with a chosen variance a sample and seconds a sample for EARS's kernels and for throughput
// roulette's, and the tests follow the phases it goes through.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "passes/ears_guard_policy.h"
#include "passes/pass_policies.h"

using namespace vkmc;
using Phase = EarsGuardPolicy::Phase;

namespace {

// Per-pixel sums of n samples of mean 1 whose unbiased sample variance is v.
std::vector<PixelSums> passSums(uint32_t n, double v, size_t pixels = 16) {
  PixelSums s;
  s.n = n;
  s.sum = glm::dvec3(n);
  s.sumSq = glm::dvec3(n + (n - 1.0) * v);
  return std::vector<PixelSums>(pixels, s);
}

struct FakeRenderer {
  double earsVariance = 0.1, throughputVariance = 1.0;  // a sample's
  double earsSeconds = 0.01, throughputSeconds = 0.01;  // a sample's
  double passOverhead = 0.0;                            // a pass's fixed seconds
  uint32_t spp = 1000, passSamples = 8, maxPassSamples = 8;
  uint32_t nextSample = 0;
  double elapsed = 0.0;
  std::vector<PixelSums> sums;
  std::vector<glm::vec4> scale = std::vector<glm::vec4>(16, glm::vec4(1.0f));

  PassContext context() const {
    PassContext c;
    c.nextSample = nextSample, c.spp = spp, c.passSamples = passSamples, c.maxPassSamples = maxPassSamples;
    c.elapsed = elapsed;
    return c;
  }
  // Plans the next pass, carries it out and records it; returns the plan.
  PassPlan step(PassPolicy& policy) {
    const PassPlan plan = policy.next(context());
    if (plan.stop()) return plan;
    const bool throughput = plan.kernels == PassKernels::Throughput;
    PassOutcome o;
    o.plan = plan;
    o.seconds = passOverhead + plan.samples * (throughput ? throughputSeconds : earsSeconds);
    elapsed += o.seconds;
    if (plan.use == PassUse::Image) nextSample += plan.samples;
    o.nextSample = nextSample;
    o.elapsed = elapsed;
    sums = passSums(plan.samples, throughput ? throughputVariance : earsVariance);
    if (plan.learns || plan.use == PassUse::Measured) o.sums = &sums, o.scale = &scale;
    policy.record(o);
    return plan;
  }
};

EarsGuardSettings settings(EarsFallback fallback, double budget = 0.0, uint32_t maxPass = 8) {
  EarsGuardSettings s;
  s.fallback = fallback;
  s.compares = fallback != EarsFallback::Never;
  s.timeBudget = budget;
  s.maxPassSamples = maxPass;
  s.pixels = 16.0;
  s.trainingPixelSamples = 16.0;  // one sample a pixel of a full pass trains
  return s;
}

void expectPlan(const PassPlan& p, uint32_t samples, PassKernels kernels, PassUse use) {
  EXPECT_EQ(p.samples, samples);
  EXPECT_EQ(int(p.kernels), int(kernels));
  EXPECT_EQ(int(p.use), int(use));
}

}  // namespace

TEST(EarsGuardPolicy, TrainsThenMeasuresEachPolicyThenRendersTheMoreEfficient) {
  FakeRenderer r;
  EarsGuardPolicy policy(settings(EarsFallback::Auto));
  // Training: the first pass is kept (it learns from nothing), the later two are dropped.
  expectPlan(r.step(policy), 1, PassKernels::EarsTraining, PassUse::Image);
  expectPlan(r.step(policy), 2, PassKernels::EarsTraining, PassUse::Training);
  expectPlan(r.step(policy), 4, PassKernels::EarsTraining, PassUse::Training);
  EXPECT_EQ(policy.phase(), Phase::Ears);
  EXPECT_EQ(r.nextSample, 1u);
  // A warm-up pass of EARS, then kEarsGuardSamples measured, then a whole pass of throughput roulette, dropped.
  expectPlan(r.step(policy), 8, PassKernels::Estimator, PassUse::Image);
  EXPECT_EQ(policy.phase(), Phase::MeasureEars);
  expectPlan(r.step(policy), kEarsGuardSamples, PassKernels::Estimator, PassUse::Image);
  EXPECT_EQ(policy.phase(), Phase::MeasureThroughput);
  const uint32_t before = r.nextSample;
  expectPlan(r.step(policy), 8, PassKernels::Throughput, PassUse::Measured);
  EXPECT_EQ(r.nextSample, before);
  // EARS's samples have a tenth of the variance at the same cost: EARS renders the rest, watched.
  EXPECT_EQ(policy.phase(), Phase::Ears);
  const EarsGuardOutcome& g = policy.outcome();
  EXPECT_TRUE(g.compared);
  EXPECT_FALSE(g.fellBack);
  EXPECT_TRUE(g.watched);
  EXPECT_EQ(g.fromSample, before);
  EXPECT_NEAR(g.ears.efficiency() / g.throughput.efficiency(), 10.0, 1e-6);
  expectPlan(r.step(policy), 8, PassKernels::Estimator, PassUse::Image);
}

TEST(EarsGuardPolicy, WatchedEarsFallingBehindHandsTheRestToThroughputRoulette) {
  FakeRenderer r;
  EarsGuardPolicy policy(settings(EarsFallback::Auto));
  while (!policy.outcome().compared) r.step(policy);
  ASSERT_TRUE(policy.outcome().watched);
  r.earsVariance = 10.0;              // the rare large samples a few samples a pixel missed
  const PassPlan p = r.step(policy);  // 8 samples: as many as throughput roulette's measure
  expectPlan(p, 8, PassKernels::Estimator, PassUse::Image);
  EXPECT_TRUE(policy.outcome().switchedLater);
  EXPECT_EQ(policy.outcome().switchedAt, r.nextSample);
  EXPECT_EQ(policy.phase(), Phase::Throughput);
  expectPlan(r.step(policy), 8, PassKernels::Throughput, PassUse::Image);
}

TEST(EarsGuardPolicy, FallsBackWhereThroughputRouletteIsMoreEfficient) {
  FakeRenderer r;
  r.earsVariance = 1.0, r.throughputVariance = 0.1;
  EarsGuardPolicy policy(settings(EarsFallback::Auto));
  EXPECT_TRUE(policy.learning());
  while (!policy.outcome().compared) r.step(policy);
  EXPECT_TRUE(policy.outcome().fellBack);
  EXPECT_FALSE(policy.learning()) << "a fold now uploads the film's own estimate, as without EARS";
  EXPECT_FALSE(policy.outcome().secondLook);  // a tenth: far below the second look's ratio
  EXPECT_FALSE(policy.outcome().watched);
  for (int i = 0; i < 3; ++i) {
    const PassPlan p = r.step(policy);
    expectPlan(p, 8, PassKernels::Throughput, PassUse::Image);
    EXPECT_FALSE(p.learns);
  }
}

TEST(EarsGuardPolicy, ACloseFirstLookIsTakenAgainOnALaterPass) {
  FakeRenderer r;
  r.earsVariance = 1.25;  // 0.8x throughput roulette's efficiency: between kEarsSecondLookRatio and the margin
  EarsGuardPolicy policy(settings(EarsFallback::Auto));
  while (policy.phase() != Phase::MeasureEarsAgain) {
    r.step(policy);
    ASSERT_FALSE(policy.outcome().compared);
  }
  EXPECT_TRUE(policy.outcome().secondLook);
  r.earsVariance = 0.2;  // the cache has learned since
  expectPlan(r.step(policy), kEarsGuardSamples, PassKernels::Estimator, PassUse::Image);
  EXPECT_TRUE(policy.outcome().compared);
  EXPECT_FALSE(policy.outcome().fellBack);
  EXPECT_NEAR(policy.outcome().firstEars.efficiency() / policy.outcome().throughput.efficiency(), 0.8, 1e-6);
  EXPECT_EQ(policy.phase(), Phase::Ears);
}

TEST(EarsGuardPolicy, AlwaysFallsBackAfterMeasuringAndNeverDoesNotCompare) {
  FakeRenderer r;
  EarsGuardPolicy always(settings(EarsFallback::Always));
  while (!always.outcome().compared) r.step(always);
  EXPECT_TRUE(always.outcome().fellBack);
  EXPECT_TRUE(always.outcome().secondLook);  // always looks twice, as auto's close calls do
  // Never: EARS throughout, its passes doubling from the training's sizes up to the largest pass.
  FakeRenderer n;
  n.passSamples = n.maxPassSamples = 32;
  EarsGuardPolicy never(settings(EarsFallback::Never, 0.0, 32));
  for (uint32_t expected : {1u, 2u, 4u}) EXPECT_EQ(n.step(never).samples, expected);
  for (uint32_t expected : {8u, 16u, 32u, 32u}) expectPlan(n.step(never), expected, PassKernels::Estimator, PassUse::Image);
  EXPECT_FALSE(never.outcome().compared);
}

TEST(EarsGuardPolicy, UnderABudgetTheFirstPassIsThroughputRoulettesAndASecondMeasuresTheOverhead) {
  FakeRenderer r;
  r.passOverhead = 0.01;
  EarsGuardPolicy policy(settings(EarsFallback::Auto, 100.0));
  expectPlan(r.step(policy), 1, PassKernels::Throughput, PassUse::Image);
  expectPlan(r.step(policy), 2, PassKernels::Throughput, PassUse::Image);
  // t = a + b n from 1 sample in 0.02 s and 2 in 0.03 s: a = 0.01.
  EXPECT_NEAR(policy.outcome().passOverhead, 0.01, 1e-9);
  expectPlan(r.step(policy), 2, PassKernels::EarsTraining, PassUse::Training);
  EXPECT_EQ(r.nextSample, 3u);
}

TEST(EarsGuardPolicy, ABudgetTooShortToLearnInRendersUncompared) {
  for (EarsFallback mode : {EarsFallback::Auto, EarsFallback::Never}) {  // never: EARS trained that far
    FakeRenderer r;
    r.throughputSeconds = r.earsSeconds = 0.5;  // one pass is half the budget
    EarsGuardPolicy policy(settings(mode, 1.0));
    r.step(policy);
    const bool fellBack = mode != EarsFallback::Never;
    EXPECT_EQ(policy.phase(), fellBack ? Phase::Throughput : Phase::Ears);
    EXPECT_TRUE(policy.outcome().outOfBudget);  // under never, training stops there
    EXPECT_EQ(policy.outcome().fellBack, fellBack);
    EXPECT_FALSE(policy.outcome().compared);
  }
}

TEST(EarsGuardPolicy, StopsAtTheTargetAndNeverPlansPastIt) {
  FakeRenderer r;
  r.spp = 12;
  EarsGuardPolicy policy(settings(EarsFallback::Auto));
  uint32_t passes = 0;
  while (!r.step(policy).stop()) ASSERT_LT(++passes, 100u);
  EXPECT_EQ(r.nextSample, 12u);
}

TEST(PassPolicies, UniformPassesAndShadowRoulettePacing) {
  PassContext c;
  c.spp = 10, c.passSamples = 4, c.maxPassSamples = 4;
  UniformPasses uniform;
  ShadowRoulettePacing paced;
  EXPECT_EQ(uniform.next(c).samples, 4u);
  EXPECT_EQ(paced.next(c).samples, 1u);
  c.nextSample = 1;
  EXPECT_EQ(paced.next(c).samples, 2u);
  c.nextSample = 8;
  EXPECT_EQ(uniform.next(c).samples, 2u);  // never past spp
  c.nextSample = 10;
  EXPECT_TRUE(uniform.next(c).stop());
  EXPECT_TRUE(paced.next(c).stop());
}
