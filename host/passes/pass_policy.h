// The one place that decides between passes. PathRenderer::render asks its PassPolicy, before each pass, what the
// pass runs (how many samples a pixel, which roulette kernels, whether it is an image pass or one that is measured
// and dropped) or whether to stop, and tells it afterwards what the pass measured. The renderer carries plans out
// (kernels, seeds, batches, the pixel estimate); the policy decides from earlier passes only, so no pass's samples
// choose their own weight in the image: unbiased.
//
// Implementations: UniformPasses and ShadowRoulettePacing (pass_policies.h), EarsGuardPolicy (ears_guard_policy.h).
// The decisions made before or around the passes live beside them: efficiency roulette's pilot
// (host/policy/efficiency_roulette_pilot.h), --estimator auto's choice (host/policy/estimator_choice.h) and adaptive sampling's
// rounds (host/policy/sample_rounds.h).
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include "passes/ears_image_statistics.h"

namespace vkmc {

// Which roulette kernels a pass runs.
enum class PassKernels : uint8_t {
  Estimator,     // the estimator's own (under rr ears: EARS's, a pass's first samples training the cache)
  EarsTraining,  // EARS's, every sample training the cache
  Throughput,    // throughput roulette's (rr ears's guard and fallback)
};

// What becomes of a pass's samples.
enum class PassUse : uint8_t {
  Image,     // kept: the render's seed, from its next sample
  Training,  // dropped once training ends; their own seed and sample sequence
  Measured,  // measured on a batch of their own, then dropped; their own seed
};

struct PassPlan {
  uint32_t samples = 0;  // a pixel; 0: stop
  PassKernels kernels = PassKernels::Estimator;
  PassUse use = PassUse::Image;
  bool learns = false;  // EARS's image statistics and estimate learn from it (else the plain pixel estimate)
  bool stop() const { return samples == 0; }
};

// What the renderer knows before a pass.
struct PassContext {
  uint32_t nextSample = 0;      // the image's next sample
  uint32_t spp = 0;             // the render's target
  uint32_t passSamples = 1;     // the size the renderer would give a pass now (a time budget's, or the largest)
  uint32_t maxPassSamples = 1;  // the largest pass that fits the path pool
  double elapsed = 0.0;         // seconds since the passes began
};

// What the renderer measured in a pass. sums and scale are set where the plan learns or is measured: the pass's
// per-pixel sums and the smoothed pixel estimate with its samples.
struct PassOutcome {
  PassPlan plan;
  uint32_t nextSample = 0;  // after it
  double seconds = 0.0;
  double elapsed = 0.0;  // since the passes began, at its end
  const std::vector<PixelSums>* sums = nullptr;
  const std::vector<glm::vec4>* scale = nullptr;
  // Under EARS: the seconds and pixel-samples of its training part and of the rest.
  double trainSeconds = 0.0, leanSeconds = 0.0, trainPixelSamples = 0.0, leanPixelSamples = 0.0;
};

class PassPolicy {
 public:
  virtual ~PassPolicy() = default;
  virtual PassPlan next(const PassContext& c) = 0;
  virtual void record(const PassOutcome&) {}
  // Whether the passes to come still learn (EARS's statistics and its smoothed estimate in use), as of now.
  virtual bool learning() const { return false; }
  // After the last pass, from the render's first sample (firstSample) to c.nextSample.
  virtual void finish(const PassContext&, uint32_t /*firstSample*/) {}
};

}  // namespace vkmc
