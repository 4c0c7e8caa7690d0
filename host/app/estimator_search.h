// --estimator auto: before the render, pilots of candidate configurations on a subset of the image's pixels, each
// with its own pipelines and seed, and the choice between them (policy/estimator_choice.h). The pilots' samples are
// left out of the image: a weight fixed at 0 before they are seen, so the render stays unbiased whatever they chose.
#pragma once
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "estimators/efficiency_roulette.h"
#include "policy/estimator_choice.h"
#include "render/gpu_scene.h"
#include "render/render_settings.h"
#include "vk/context.h"

namespace vkmc {

struct MeasuredCandidate {
  std::string label;  // "start", or the key and value it changed ("light_samples=4")
  EstimatorConfig config;
  CandidateReading reading;  // against the means pooled over every candidate (readCandidates)
  bool chosen = false;
};

struct EstimatorChoice {
  EstimatorConfig chosen;
  std::vector<MeasuredCandidate> candidates;  // in the order measured
  std::optional<RouletteTable> roulette;      // rr efficiency chosen: its pilot's scales
  std::string costUnit;                       // "rays" (no time budget: reproducible) or "GPU seconds"
  uint32_t pilotPixels = 0;
  double seconds = 0.0;          // the pilots' rendering (rr efficiency's own pilot included)
  double pipelineSeconds = 0.0;  // the candidates' kernels' set-up
  double share = 0.0;            // the pilots' pixel-samples over the render's planned ones
};

// settings: the render's (its estimator the start, with the user's keys in `pinned`); timeBudget > 0 sizes the
// pilots from their measured pace.
EstimatorChoice chooseEstimator(vk::Context& ctx, const GpuScene& scene, const RenderSettings& settings,
                                const std::set<std::string>& pinned, double timeBudget);

}  // namespace vkmc
