// --estimator auto: the render's first rounds are pilots of candidate configurations on a subset of the image's
// pixels, each with its own pipelines and seed; the choice between them (policy/estimator_choice.h) renders the rest.
// Every pilot is a round of the image (policy/round_film.h) whose per-pixel weights are fixed before its samples are
// seen, so the image stays unbiased whichever configuration its values chose.
#pragma once
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "estimators/efficiency_roulette.h"
#include "policy/estimator_choice.h"
#include "policy/round_film.h"
#include "render/gpu_scene.h"
#include "render/render_settings.h"
#include "vk/context.h"

namespace vkmc {

struct MeasuredCandidate {
  std::string label;  // "start", or the key and value it changed ("light_samples=4")
  EstimatorConfig config;
  CandidateReading reading;  // against the values pooled over every candidate (readCandidates)
  bool chosen = false;
  bool tooCostly = false;  // it beat the best so far, at a cost a sample-count render does not afford
  double seconds = 0.0;    // its pilot's passes (and rr efficiency's own pilot), wall time
};

// The search's winner against the start again, on fresh pilots of both nearer the render's stage of convergence
// (estimator_search.cpp, confirmWinner).
struct Confirmation {
  bool ran = false;        // false: the start won the search, or the share of the render's time left no room
  bool confirmed = false;  // the winner beat the start again (confirms); otherwise the start rendered
  std::string candidate;   // the winner's label
  PilotShape shape;        // its pilots' pixels and samples a pixel (confirmationShape)
  CandidateReading start, winner;
  Comparison vsStart;  // the winner's fresh reading against the start's (compare)
};

struct EstimatorChoice {
  EstimatorConfig chosen;
  std::vector<MeasuredCandidate> candidates;  // in the order measured
  std::optional<RouletteTable> roulette;      // rr efficiency chosen: its pilot's scales
  uint32_t pilotPixels = 0, pilotSpp = 0;     // the search's pilots (a prefix of the pass's pixels: pilotPixelsInShare)
  uint32_t passPixels = 0;                    // a pass's pixels at pilotSpp: where candidates that split paths run
  double seconds = 0.0;                       // the pilots' rendering (rr efficiency's own pilot included)
  double pipelineSeconds = 0.0;               // the candidates' kernels' set-up
  double pixelSamples = 0.0;                  // the pilots' samples, all in the image
  double share = 0.0;                         // their share of the render's planned pixel-samples
  bool cutShort = false;                      // the share of the render's time fitted no challenger: the start renders
  bool costCapped = false;                    // a sample count ends the render: kChoiceMaxCostAtSampleCount held
  std::vector<std::string> skippedForBudget;  // challengers left out because they would not fit it
  // rr efficiency's learnt table against the throughput rule, as predicted on its roulette pilot's paths
  // (RouletteTable::gainOverThroughput), where the search learnt one; a challenger it left out (kChoiceMinRoulettePrediction).
  std::optional<double> roulettePrediction;
  std::vector<std::string> skippedByPrediction;
  Confirmation confirmation;
  std::vector<RenderStats> stats;  // each pilot's counters (the report's rays include them)
};

// What ends the render, and so bounds the choosing. timeBudget > 0: the render's samples are planned from the start's
// pace. The pilots take at most kChoiceMaxShare of the render's samples, and of its seconds: the budget's, or with
// shareOfSeconds (the default's choosing, which must pay for itself on a short render) its samples' at the start
// pilot's pace. sampleCountEnds: no budget or target error, so a costly challenger must be affordable
// (affordableAtSampleCount).
struct ChoiceBounds {
  double timeBudget = 0.0;
  bool shareOfSeconds = false;
  bool sampleCountEnds = false;
};

// settings: the render's (its estimator the start, with the user's keys in `pinned`). The pilots' rounds go into
// `film` (the render's, empty).
EstimatorChoice chooseEstimator(vk::Context& ctx, const GpuScene& scene, const RenderSettings& settings,
                                const std::set<std::string>& pinned, const ChoiceBounds& bounds, RoundFilm& film);

}  // namespace vkmc
