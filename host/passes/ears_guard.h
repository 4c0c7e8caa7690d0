// rr ears's guard: after the training passes and a warm-up pass of EARS, 4 samples a pixel of EARS
// (kEarsGuardSamples, path_renderer.cpp) and a pass of throughput roulette as large as its later ones (at least
// 4 samples, in more passes where passes are smaller) are measured, each by its
// efficiency per sample, 1 / (relative variance of a sample x seconds of a sample); EARS renders the rest where it
// reads above kEarsGuardMargin (estimator_config.h) times throughput roulette's, else throughput roulette
// (ears_fallback auto). The measured passes are in the image, and the choice depends on earlier passes only:
// unbiased.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "estimators/estimator_config.h"
#include "passes/ears_image_statistics.h"

namespace vkmc {

// One policy's measurement: the relative variance of one sample (relativeSampleVariance) and the seconds one sample
// (a whole image's worth) takes.
struct PolicyPass {
  double relativeVariance = 0.0;
  double secondsPerSample = 0.0;
  uint32_t samples = 0;       // a pixel, measured
  double efficiency() const;  // 1 / (variance x seconds); +inf for a noiseless pass, 0 for a non-finite one
};

// The mean over pixels (with at least two samples in the pass) of their samples' unbiased variance relative to
// scale^2 + epsilon, averaged over the channels; NaN where no pixel has two. Nothing is left out: a firefly
// counts as it does in the image's error. Under sobol a pixel's samples are stratified, so this is a little above
// the variance of one sample, for either policy alike. Throws on a size mismatch.
double relativeSampleVariance(const std::vector<PixelSums>& pass, const std::vector<glm::vec4>& scale, double epsilon);

// What one policy's measured passes added up to.
struct PolicyTally {
  std::vector<PixelSums> sums;  // per pixel
  uint32_t samples = 0;         // a pixel
  double seconds = 0.0;         // of the whole passes
  // EARS's passes in two parts: the training (its wavefront and the cache's update) and the rest, in seconds and
  // pixel-samples.
  double trainSeconds = 0.0, leanSeconds = 0.0;
  double trainPixelSamples = 0.0, leanPixelSamples = 0.0;
  void addPass(const std::vector<PixelSums>& pass, uint32_t passSamples, double passSeconds);
};

// EARS's seconds a sample in a later pass of the whole image (`pixels`) in which trainingPixelSamples of
// pixels x passSamples train: the measured seconds of a training and of a lean pixel-sample, mixed in that pass's
// proportion (a training pass's share shrinks as passes grow). Where nothing lean was measured, a lean sample is
// costed as a training one; where nothing was split, the whole passes' seconds a sample.
double earsSecondsPerSample(const PolicyTally& t, double pixels, double passSamples, double trainingPixelSamples);

// Under a time budget, EARS's learning (its training passes) and the guard's comparison may take at most this share
// of it. Where what is left of them would not fit, training stops there, and under auto and always throughput
// roulette renders the rest without a comparison: learning that cannot pay back within the budget is not done
// (the stiff furnace at 96x96 spends about a second a sample). The choice depends on time alone: unbiased. A
// twentieth: where EARS then loses the comparison, --rr ears stays within about 5% of throughput roulette (with a
// quarter, the glossy room's comparison cost it 8-10% of a 16-s render; docs/journal/ears.md).
constexpr double kEarsLearningBudgetShare = 0.05;

// The seconds EARS's learning still needs: `trainingSamples` more samples a pixel of training passes and
// `earsSamples` of EARS passes before the choice at earsSecondsPerSample (the last training pass's), and
// throughput roulette's measured passes, `throughputSeconds` (earsThroughputPassSeconds).
double earsLearningSecondsLeft(uint32_t trainingSamples, uint32_t earsSamples, double earsSecondsPerSample,
                               double throughputSeconds);
// Throughput roulette's measured passes (`passes` of `samples` a pixel in all), costed from the first training pass
// (throughput roulette's, `firstSamples` a pixel in `firstSeconds`): each pass's fixed overhead (its bounces'
// dispatches and round trips, `overhead` seconds a pass) and the rest in proportion to samples. Overhead 0 costs
// each sample at the first pass's seconds a sample (an upper bound: on dark_room at 96x96 a 1-spp pass took 0.0375
// s a sample, a 28-spp one 0.0085); overhead = firstSeconds costs each pass as one first pass (a lower bound).
double earsThroughputPassSeconds(double firstSeconds, uint32_t firstSamples, double overhead, uint32_t passes, uint32_t samples);
// A pass's fixed overhead from two passes of one policy (t = a + b n): a, clamped to [0, cap]; 0 where the two
// passes are the same size (nothing to tell overhead from samples).
double earsPassOverhead(double seconds, uint32_t samples, double laterSeconds, uint32_t laterSamples, double cap);
// Whether it fits in the budget's share (kEarsLearningBudgetShare) after `elapsed` seconds; always without a budget.
bool earsLearningFits(double budget, double elapsed, double secondsLeft);

// The guard's outcome, for the report.
struct EarsGuardOutcome {
  bool compared = false;     // both passes ran
  bool outOfBudget = false;  // the learning and the comparison did not fit the time budget (earsLearningFits)
  // Under a time budget: throughput roulette's fixed seconds a pass, from its first two passes (earsPassOverhead);
  // NaN where they did not both run.
  double passOverhead = std::numeric_limits<double>::quiet_NaN();
  bool fellBack = false;    // throughput roulette rendered the rest
  uint32_t fromSample = 0;  // the first sample after the comparison
  PolicyPass ears, throughput;
  bool secondLook = false;  // EARS was measured again, on a later pass (earsGuardLooksAgain)
  PolicyPass firstEars;     // then: its first measure
  // Where auto chose EARS, its passes after the choice go on being measured, together, against throughput
  // roulette's pass (earsGuardWatches): a few samples a pixel of a heavy-tailed scene can miss the rare large
  // samples that make EARS the worse (veach_mis: chosen in one of three 4-s renders, then 0.41-0.48x). Where
  // EARS falls behind, throughput roulette renders the rest from that pass on.
  bool watched = false;        // EARS chosen under auto: its later passes measured
  PolicyPass watchedEars;      // their measure when the guard last looked
  bool switchedLater = false;  // throughput roulette took over while watching
  uint32_t switchedAt = 0;     // then: from this sample (EARS from fromSample until it)
  // What choosing cost, measured in the render itself (earsLearningCostSeconds): the seconds of this render's passes
  // when the rest's policy was fixed (compared or out of budget), and those seconds less what the samples kept by
  // then would have taken at the rest's seconds a sample. NaN where nothing was decided or nothing followed.
  double decidedAtSeconds = std::numeric_limits<double>::quiet_NaN();
  double learningCostSeconds = std::numeric_limits<double>::quiet_NaN();
};

// The guard's cost: `decidedAt` seconds into the render, `samplesBefore` samples a pixel were in the image; the
// rest, `samplesAfter` of them, took until `endSeconds`. The training passes, the dropped throughput pass and the
// dearer EARS samples are what decidedAt holds beyond samplesBefore at the rest's rate. Measured within one render,
// so this machine's swings between processes (±30%) do not enter it, as they do an equal-time comparison of two
// renders. NaN without samples after (no rate to cost by). Negative where the kept samples were cheaper than the
// rest's (EARS chosen and dearer a sample).
double earsLearningCostSeconds(double decidedAt, uint32_t samplesBefore, double endSeconds, uint32_t samplesAfter);

// EARS's cache keeps learning after its first measured samples: on two_rooms a pass's efficiency rose from about
// 0.6x throughput roulette's at the first measure to 1.1-1.2x in later passes (docs/journal/ears.md, "The guard").
// So a first measure of EARS at kEarsSecondLookRatio or more of throughput roulette's efficiency, but below the
// margin (kEarsGuardMargin) times it, is taken again on a later EARS pass (throughput roulette's measure is kept)
// before the choice.
constexpr double kEarsSecondLookRatio = 0.6;

// Whether EARS is measured again before the choice: under auto where the first measure was close (above), and
// always under always, which then still switches (so its tests take the same path); never under never.
bool earsGuardLooksAgain(EarsFallback mode, const PolicyPass& ears, const PolicyPass& throughput);

// Whether throughput roulette renders the rest: Always, or under Auto unless EARS's efficiency is above
// kEarsGuardMargin times its own (at the margin the choice goes to the cheaper kernels). Never: false.
bool earsFallsBack(EarsFallback mode, const PolicyPass& ears, const PolicyPass& throughput);

// Whether EARS, once chosen, is watched (EarsGuardOutcome::watched): under auto only (always has switched; never
// does not compare).
bool earsGuardWatches(EarsFallback mode);

// One line for the report: what was measured and chosen.
std::string earsGuardLine(const EarsGuardOutcome& g);

}  // namespace vkmc
