// rr ears's pass policy (ears_guard_policy.h).
#include "passes/ears_guard_policy.h"

#include <algorithm>
#include <cmath>

#include "../shaders/shared/ears.h"
#include "error.h"

namespace vkmc {

EarsGuardPolicy::EarsGuardPolicy(const EarsGuardSettings& s)
    : settings_(s), throughputFirst_(s.timeBudget > 0.0 && s.compares), pending_(s.compares) {}

PassPlan EarsGuardPolicy::next(const PassContext& c) {
  spp_ = c.spp;
  if (c.nextSample >= c.spp) return {};
  const uint32_t left = c.spp - c.nextSample;
  switch (phase_) {
    case Phase::Training:
      // The first pass learns from nothing, so it decides everywhere as throughput roulette does: it is an image
      // pass and stays; the later ones decide from what it taught and are dropped, so the image holds no sample
      // whose decisions came from a barely trained cache. Under a budget the first pass is throughput roulette's
      // own (its lean kernels): what it costs says whether learning fits before any training kernel has run.
      if (overheadDue_) return {2, PassKernels::Throughput, PassUse::Image, true};
      if (trainingPass_ == 0)
        return {1, throughputFirst_ ? PassKernels::Throughput : PassKernels::EarsTraining, PassUse::Image, true};
      return {trainingSamples_, PassKernels::EarsTraining, PassUse::Training, true};
    case Phase::Ears: return {std::min({c.passSamples, earsSamples_, left}), PassKernels::Estimator, PassUse::Image, true};
    case Phase::MeasureEars:
    case Phase::MeasureEarsAgain:
      // Passes no larger than the others: the cache learns from a pass's first samples only (earsTrainingSamples),
      // so a larger look learns no more.
      return {std::min({c.passSamples, kEarsGuardSamples - earsTally_.samples, left}), PassKernels::Estimator, PassUse::Image,
              true};
    case Phase::MeasureThroughput:
      // As large as throughput roulette's later passes, whose per-pass overhead (a pass's bounces, most nearly
      // empty) it then shares as they will: on veach_mis a 4-sample pass took twice the seconds a sample of a
      // 28-sample one. Measured and dropped (had it stayed, an image that EARS goes on to render would hold samples
      // of the policy that lost: on two_rooms 28 of them in 173 made a 4-s image 0.79x as efficient).
      return {c.maxPassSamples, PassKernels::Throughput, PassUse::Measured, false};
    case Phase::Throughput: return {std::min(c.passSamples, left), PassKernels::Throughput, PassUse::Image, false};
  }
  throw Error("internal error: an unknown EARS phase");
}

void EarsGuardPolicy::record(const PassOutcome& o) {
  if (o.plan.kernels == PassKernels::Estimator) earsSamples_ = std::min(2 * earsSamples_, settings_.maxPassSamples);
  switch (phase_) {
    case Phase::Training: return recordTraining(o);
    case Phase::Ears:
      if (outcome_.watched && !outcome_.fellBack) watch(o);
      if (pending_ && ++warmPasses_ >= kEarsGuardWarmPasses) phase_ = Phase::MeasureEars;
      return;
    case Phase::MeasureEars:
    case Phase::MeasureEarsAgain: return recordMeasuredEars(o);
    case Phase::MeasureThroughput:
      throughputTally_.addPass(*o.sums, o.plan.samples, o.seconds);
      // What both policies' variances are relative to: the smoothed estimate with this pass's samples too (from
      // the few samples before it, pixels near veach_mis's small lamps read near 0, and V in the hundreds).
      firstLookScale_ = *o.scale;
      if (throughputTally_.samples >= kEarsGuardSamples) decide(o, false);
      return;
    case Phase::Throughput: return;
  }
}

// Training passes of 1, 2, 4 ... samples. Under a time budget, training stops where it and the guard's comparison
// would not fit the budget's share (earsLearningFits); a second pass of throughput roulette's, after the first,
// tells a pass's fixed overhead from its cost a sample (t = a + b n: a 1-spp pass is mostly overhead).
void EarsGuardPolicy::recordTraining(const PassOutcome& o) {
  if (overheadDue_) {
    overheadDue_ = false;
    overhead_ = earsPassOverhead(firstPassSeconds_, 1, o.seconds, 2, firstPassSeconds_);
    outcome_.passOverhead = overhead_;
    if (!learningFits(0, firstPerSample_, o.elapsed)) endTraining(true, o);
    return;
  }
  const uint32_t pass = trainingPass_++;
  const double perSample = o.seconds / std::max(o.plan.samples, 1u);
  if (pass == 0) firstPassSeconds_ = o.seconds, firstPerSample_ = perSample;
  trainingSamples_ = std::min(2 * trainingSamples_, settings_.maxPassSamples);
  if (!learningFits(pass, perSample, o.elapsed)) return endTraining(true, o);
  if (pass == 0 && throughputFirst_ && pending_ && settings_.maxPassSamples >= 2 && o.nextSample + 2 <= spp_) {
    overheadDue_ = true;
    return;
  }
  if (trainingPass_ == kEarsTrainingPasses) endTraining(false, o);
}

void EarsGuardPolicy::endTraining(bool outOfBudget, const PassOutcome& o) {
  earsSamples_ = trainingSamples_;
  phase_ = pending_ && kEarsGuardWarmPasses == 0 ? Phase::MeasureEars : Phase::Ears;
  if (!outOfBudget) return;
  // No comparison: throughput roulette where the guard may fall back, else EARS as trained so far.
  pending_ = false;
  outcome_.outOfBudget = true;
  outcome_.fromSample = o.nextSample;
  outcome_.decidedAtSeconds = o.elapsed;
  outcome_.fellBack = settings_.fallback != EarsFallback::Never;
  phase_ = outcome_.fellBack ? Phase::Throughput : Phase::Ears;
}

// What learning still needs after training pass `pass` at perSample seconds a sample: the training passes left and,
// where the guard will compare, the warm-up, two looks of EARS and throughput roulette's measured passes (whole
// passes, costed from the first: its fixed overhead a pass, once measured, else each pass as one first pass, which is
// optimistic; every check counts what has elapsed, so the budget's share holds).
bool EarsGuardPolicy::learningFits(uint32_t pass, double perSample, double elapsed) const {
  const uint32_t maxPass = settings_.maxPassSamples;
  uint32_t trainingLeft = 0;
  for (uint32_t later = pass + 1, n = trainingSamples_; later < kEarsTrainingPasses; ++later, n = std::min(2 * n, maxPass))
    trainingLeft += n;
  if (trainingLeft == 0 && !pending_) return true;
  const uint32_t throughputPasses = (kEarsGuardSamples + maxPass - 1) / maxPass;
  const double overhead = overhead_ >= 0.0 ? overhead_ : firstPassSeconds_;
  const double throughputSeconds =
      pending_ ? earsThroughputPassSeconds(firstPassSeconds_, 1u, overhead, throughputPasses, throughputPasses * maxPass) : 0.0;
  const double left = earsLearningSecondsLeft(trainingLeft, pending_ ? kEarsGuardWarmPasses + 2 * kEarsGuardSamples : 0u,
                                              perSample, throughputSeconds);
  return earsLearningFits(settings_.timeBudget, elapsed, left);
}

void EarsGuardPolicy::addEarsPass(const PassOutcome& o) {
  earsTally_.addPass(*o.sums, o.plan.samples, o.seconds);
  earsTally_.trainSeconds += o.trainSeconds;
  earsTally_.leanSeconds += o.leanSeconds;
  earsTally_.trainPixelSamples += o.trainPixelSamples;
  earsTally_.leanPixelSamples += o.leanPixelSamples;
}

void EarsGuardPolicy::recordMeasuredEars(const PassOutcome& o) {
  addEarsPass(o);
  if (earsTally_.samples < kEarsGuardSamples) return;
  if (phase_ == Phase::MeasureEars)
    phase_ = Phase::MeasureThroughput;
  else
    decide(o, true);
}

// Each policy's measure from its tally, its variances relative to `scale`: EARS's seconds a sample as in a pass of
// its later size.
PolicyPass EarsGuardPolicy::earsMeasure(const std::vector<glm::vec4>& scale) const {
  return {relativeSampleVariance(earsTally_.sums, scale, gpu::kEarsEpsilon),
          earsSecondsPerSample(earsTally_, settings_.pixels, settings_.maxPassSamples, settings_.trainingPixelSamples),
          earsTally_.samples};
}
PolicyPass EarsGuardPolicy::throughputMeasure(const std::vector<glm::vec4>& scale) const {
  return {relativeSampleVariance(throughputTally_.sums, scale, gpu::kEarsEpsilon),
          throughputTally_.seconds / throughputTally_.samples, throughputTally_.samples};
}

// EARS's passes after auto chose it, measured together against throughput roulette's pass, both relative to the
// latest estimate: where EARS falls behind, throughput roulette renders the rest (EarsGuardOutcome::watched).
void EarsGuardPolicy::watch(const PassOutcome& o) {
  addEarsPass(o);
  // Judged on no fewer samples a pixel than throughput roulette's measure, nor than the choice's.
  if (earsTally_.samples < std::max(kEarsGuardSamples, throughputTally_.samples)) return;
  const PolicyPass ears = earsMeasure(*o.scale), throughput = throughputMeasure(*o.scale);
  if (!(std::isfinite(ears.relativeVariance) && std::isfinite(throughput.relativeVariance))) return;
  outcome_.watchedEars = ears;
  if (!earsFallsBack(EarsFallback::Auto, ears, throughput)) return;
  outcome_.fellBack = outcome_.switchedLater = true;
  outcome_.switchedAt = o.nextSample;
  phase_ = Phase::Throughput;
  earsTally_ = throughputTally_ = PolicyTally{};
}

// The choice at the first look (against the throughput pass's estimate) or the second (against the estimate after
// EARS's latest pass, which holds as many samples as the first look's or more).
void EarsGuardPolicy::decide(const PassOutcome& o, bool secondLook) {
  phase_ = Phase::Ears;
  const std::vector<glm::vec4>& scale = secondLook ? *o.scale : firstLookScale_;
  const PolicyPass ears = earsMeasure(scale), throughput = throughputMeasure(scale);
  const bool comparable = std::isfinite(ears.relativeVariance) && std::isfinite(throughput.relativeVariance);
  if (comparable && !secondLook && earsGuardLooksAgain(settings_.fallback, ears, throughput)) {
    outcome_.secondLook = true;
    outcome_.firstEars = ears;
    outcome_.throughput = throughput;
    earsTally_ = PolicyTally{};  // throughput roulette's tally stays, measured against the later estimate
    phase_ = Phase::MeasureEarsAgain;
    return;
  }
  if (comparable) {
    outcome_.ears = ears;
    outcome_.throughput = throughput;
    decideFrom(ears, throughput, o);
  } else if (secondLook) {
    // Nothing to compare (no pixel with two samples) after a first look that EARS lost: that look's verdict.
    outcome_.ears = outcome_.firstEars;
    outcome_.fellBack = true;
    decideFrom(ears, throughput, o);
  }  // else nothing to compare at the first look: EARS as chosen
  pending_ = false;
  earsTally_ = PolicyTally{};
  // Chosen under auto, EARS is watched from here on against throughput roulette's pass, which stays.
  outcome_.watched = outcome_.compared && !outcome_.fellBack && earsGuardWatches(settings_.fallback);
  if (!outcome_.watched) throughputTally_ = PolicyTally{};
}

void EarsGuardPolicy::decideFrom(const PolicyPass& ears, const PolicyPass& throughput, const PassOutcome& o) {
  outcome_.compared = true;
  if (!outcome_.fellBack) outcome_.fellBack = earsFallsBack(settings_.fallback, ears, throughput);
  outcome_.fromSample = o.nextSample;
  outcome_.decidedAtSeconds = o.elapsed;
  if (outcome_.fellBack) phase_ = Phase::Throughput;
}

void EarsGuardPolicy::finish(const PassContext& c, uint32_t firstSample) {
  if (!std::isfinite(outcome_.decidedAtSeconds) || outcome_.fromSample < firstSample) return;
  outcome_.learningCostSeconds = earsLearningCostSeconds(outcome_.decidedAtSeconds, outcome_.fromSample - firstSample, c.elapsed,
                                                         c.nextSample - outcome_.fromSample);
}

}  // namespace vkmc
