// Rendering in rounds, deciding between them: adaptive sampling (--adaptive) and --target-error. Each round's
// per-pixel sample counts come from the rounds before it (sample_allocation.h), its samples are rendered as sample
// runs (PathRenderer::renderSampleRuns), and the rounds combine without bias (round_film.h). The render ends at
// its sample count, its time budget, a stop request, or once the estimated relMSE's upper bound is at the target.
#pragma once
#include <cstdint>

#include "policy/round_film.h"
#include "policy/target_error.h"
#include "render/path_renderer.h"
#include "render/render_state.h"

namespace vkmc {

struct SampleRoundsPlan {
  bool adaptive = false;     // rounds after the first follow each pixel's measured relative variance
  double targetError = 0.0;  // > 0: stop once the relMSE estimate's upper bound is at or under it
  uint32_t spp = 0;          // the most samples a pixel, on average
  double timeBudget = 0.0;   // seconds; > 0: rounds until it is spent
  uint32_t passSpp = 1;      // samples a pixel a full pass holds (PathRenderer::samplesPerPass): rounds fill passes
};

struct SampleRoundsOutcome {
  uint32_t rounds = 0;
  RelMseEstimate relMse;  // of the final image
  bool targetReached = false;
  uint32_t minPixelSamples = 0, maxPixelSamples = 0;
  double firstRoundSpp = 0.0;  // the first (uniform) round: what the allocation learned from
};

// Rounds rendered before these (--estimator auto's pilots, app/estimator_search.h): their combined film and the
// samples a pixel they hold on average.
struct EarlierRounds {
  RoundFilm film;
  double spp = 0.0;
};

// Renders into `state` from scratch (no resume) or after `earlier`; an interrupted render keeps its finished rounds.
SampleRoundsOutcome renderSampleRounds(PathRenderer& renderer, RenderState& state, const RenderControl& control,
                                       const RenderSettings& settings, const SampleRoundsPlan& plan,
                                       EarlierRounds* earlier = nullptr);

// The next round's samples a pixel (on average, a multiple of `multiple` and of plan.passSpp, so that its passes
// are full: a pass's cost is mostly its longest path), from what is done and known: the first
// round an eighth of the samples, at most 8 (the allocation starts early) and at least 4 (4 under a time budget,
// whose pace it measures), then rounds that double what is done; never past
// spp; under a target error no more than the estimate predicts (relMSE falls as 1/samples), but at least a quarter
// of what is done; under a time budget no
// more than the time left at the last round's pace.
uint32_t nextRoundSpp(const SampleRoundsPlan& plan, uint32_t done, uint32_t multiple, const RelMseEstimate& estimate,
                      double secondsLeft, double secondsPerSpp);

// The mean samples a pixel the render plans to take after a round of `spp` from `done`, as known without that round's
// values: to spp; under a target error what the estimate before it predicts (relMSE falls as 1/samples; the first
// round guesses an eighth of the render), and never less than what is done; under a time budget what fits in the time left
// at the round's pace (a function of its time, as every time-budgeted render's sample count is). 0: the round is the planned
// last.
double plannedLaterSpp(const SampleRoundsPlan& plan, uint32_t done, uint32_t spp, const RelMseEstimate& before,
                       double secondsLeft, double secondsPerSpp);

}  // namespace vkmc
