// One render across a RankGroup's processes (mpirun -np N vkmc render ...), bit-identical to one process with
// the same seed and samples.
//
// The sample indices are cut into batches of renderer.samplesPerBatch() samples a pixel: the units one process
// sums in float on its device before folding them into its double film. Round k gives batch kN + r to rank r;
// each rank renders its batch in the same sample passes one process would, and rank 0 gathers the N batches and
// folds them in batch order: the same float sums, added to the same double film in the same order. Ranks take
// their sample passes in lockstep and agree after each (one small all-reduce) whether to stop; a stop abandons the
// round in flight. Rank 0 alone owns the film, writes checkpoints (at round ends) and the outputs.
//
// Not bit-identical (still unbiased): shadow roulette (--shadow-rr), whose per-pixel estimate a rank refreshes
// once a round instead of once a batch, time budgets (rounds of one pass per rank), ranks on different devices.
#pragma once
#include <string>
#include <vector>

#include "dist/rank_group.h"
#include "render/path_renderer.h"
#include "render/render_state.h"

namespace vkmc {

// What one rank did, for the report.
struct RankReport {
  uint32_t rank = 0;
  std::string host, device;
  uint64_t rays = 0;
  uint32_t batches = 0;
  double busySeconds = 0.0;  // wall time inside its sample passes
  double gpuSeconds = 0.0;
};

struct DistributedPlan {
  uint32_t spp = 0;                   // the target (the sample indices below it)
  double timeBudget = 0.0;            // seconds; > 0: rounds of one pass a rank until rank 0's clock says stop
  bool refreshPixelEstimate = false;  // shadow roulette reads the pixel estimate: share rank 0's every round
  std::string device;                 // this rank's device, for the report
  uint32_t width = 0, height = 0;     // the film's
  bool replicateVariance = false;     // Film::replicateVariance (QMC samplers)
  uint32_t replicates = 2;            // Film::replicates (the estimator's)
};

// Every rank calls it, in step. On rank 0 `state` is the render's (its film, the next sample, the counters of all
// ranks); on the others it holds only state.interrupted. Returns the ranks' reports on rank 0.
std::vector<RankReport> renderDistributed(PathRenderer& renderer, const RankGroup& group, RenderState& state,
                                          const RenderControl& control, const DistributedPlan& plan);

}  // namespace vkmc
