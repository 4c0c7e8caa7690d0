// rr ears's passes (pass_policy.h): training, a warm-up pass, the guard's comparison with throughput roulette
// (ears_guard.h), and the rest with the policy it chose, watched under auto. A state machine with no GPU in it:
// tests/unit/ears_guard_policy_test.cpp drives it with made-up passes.
//
//   Training -> Ears (warm-up) -> MeasureEars -> MeasureThroughput -+-> Ears (the rest; watched under auto) -> Throughput
//                                                                   +-> MeasureEarsAgain (a close first look) -> Ears |
//                                                                   Throughput
//                                                                   +-> Throughput
//   Training -> Ears | Throughput, uncompared, where learning would not fit a time budget's share.
#pragma once
#include <cstdint>

#include "estimators/estimator_config.h"
#include "passes/ears_guard.h"
#include "passes/pass_policy.h"

namespace vkmc {

// The samples a pixel of EARS the guard measures (each look), and the fewest of throughput roulette (a sample
// variance needs two; a short render's budget should not go to the comparison).
constexpr uint32_t kEarsGuardSamples = 4;
// EARS's passes before the one the guard measures: the first after training decides from a cache that has learned
// from a few samples a pixel, and measured 0.6x the efficiency of later passes on two_rooms (docs/journal/ears.md).
constexpr uint32_t kEarsGuardWarmPasses = 1;
constexpr uint32_t kEarsTrainingPasses = 3;  // EARS's passes that train first (1, 2 and 4 spp)

struct EarsGuardSettings {
  EarsFallback fallback = EarsFallback::Auto;
  bool compares = true;     // the guard runs (EstimatorConfig::earsMayFallBack)
  double timeBudget = 0.0;  // seconds; 0: none
  uint32_t maxPassSamples = 1;
  double pixels = 1.0;
  // The pixel-samples that train in a pass of maxPassSamples over the whole image (tile by tile).
  double trainingPixelSamples = 1.0;
};

class EarsGuardPolicy : public PassPolicy {
 public:
  explicit EarsGuardPolicy(const EarsGuardSettings& s);
  PassPlan next(const PassContext& c) override;
  void record(const PassOutcome& o) override;
  void finish(const PassContext& c, uint32_t firstSample) override;
  bool learning() const override { return phase_ != Phase::Throughput; }
  const EarsGuardOutcome& outcome() const { return outcome_; }

  enum class Phase { Training, Ears, MeasureEars, MeasureThroughput, MeasureEarsAgain, Throughput };
  Phase phase() const { return phase_; }

 private:
  void recordTraining(const PassOutcome& o);
  void endTraining(bool outOfBudget, const PassOutcome& o);
  // Whether what learning still needs after training pass `pass` fits the budget's share (earsLearningFits).
  bool learningFits(uint32_t pass, double perSample, double elapsed) const;
  void recordMeasuredEars(const PassOutcome& o);
  void watch(const PassOutcome& o);
  void decide(const PassOutcome& o, bool secondLook);
  void decideFrom(const PolicyPass& ears, const PolicyPass& throughput, const PassOutcome& o);
  void addEarsPass(const PassOutcome& o);
  PolicyPass earsMeasure(const std::vector<glm::vec4>& scale) const;
  PolicyPass throughputMeasure(const std::vector<glm::vec4>& scale) const;

  EarsGuardSettings settings_;
  Phase phase_ = Phase::Training;
  // Training: the next training pass, its size, and under a budget the first pass's cost and a pass's overhead.
  uint32_t trainingPass_ = 0;
  uint32_t trainingSamples_ = 1;
  bool throughputFirst_ = false;  // under a budget, the first pass is throughput roulette's (no training yet)
  bool overheadDue_ = false;      // a second throughput pass measures a pass's overhead next
  double firstPassSeconds_ = 0.0, firstPerSample_ = 0.0;
  double overhead_ = -1.0;
  uint32_t spp_ = 0;
  uint32_t earsSamples_ = 1;  // EARS's next pass (they double)
  bool pending_ = false;      // the comparison is still to come
  uint32_t warmPasses_ = 0;
  PolicyTally earsTally_, throughputTally_;
  std::vector<glm::vec4> firstLookScale_;  // the first look's variances are relative to it
  EarsGuardOutcome outcome_;
};

}  // namespace vkmc
