#include "policy/sample_rounds.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "analysis/error_metrics.h"
#include "policy/round_film.h"
#include "policy/sample_allocation.h"

namespace vkmc {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
uint32_t roundUp(double x, uint32_t multiple) { return uint32_t(std::ceil(std::max(x, 1.0) / multiple)) * multiple; }
}  // namespace

uint32_t nextRoundSpp(const SampleRoundsPlan& plan, uint32_t done, uint32_t multiple, const RelMseEstimate& estimate,
                      double secondsLeft, double secondsPerSpp) {
  multiple = std::lcm(std::max(multiple, 1u), std::max(plan.passSpp, 1u));
  // Under a time budget the first round is short (4 samples a pixel): its pace sizes the rest.
  const double firstSpp = plan.timeBudget > 0.0 ? 4.0 : std::max(4.0, std::min(double(plan.spp), 64.0) / 8.0);
  const uint32_t first = roundUp(firstSpp, multiple);
  double size = done == 0 ? first : std::max<double>(first, done);
  // At least a quarter of what is done: a round near the target costs a pass's tail however small it is.
  if (plan.targetError > 0.0 && done > 0 && std::isfinite(estimate.upper))
    size = std::min(size, std::max(double(done) * (estimate.upper / plan.targetError - 1.0) * 1.05, done / 4.0));
  if (plan.timeBudget > 0.0 && secondsPerSpp > 0.0) size = std::min(size, secondsLeft / secondsPerSpp);
  size = std::min(double(roundUp(size, multiple)), double(plan.spp - std::min(plan.spp, done)));
  return uint32_t(std::max(size, 0.0)) / multiple * multiple;
}

double plannedLaterSpp(const SampleRoundsPlan& plan, uint32_t done, uint32_t spp, const RelMseEstimate& before,
                       double secondsLeft, double secondsPerSpp) {
  double later = double(plan.spp) - double(done) - double(spp);
  if (plan.targetError > 0.0) {
    // relMSE falls as 1/samples: the samples it takes are upper * done / target; the first round guesses an eighth.
    // Never a planned last round, and never less than what is done: whether the target is met is known only after
    // a round, and a round that took most of what weight is left would leave later rounds little to improve on
    // (the weights are normalized by what they came to).
    const bool known = done > 0 && std::isfinite(before.upper);
    later =
        std::min(later, std::max(known ? before.upper * done / plan.targetError - done - spp : 7.0 * spp, double(done + spp)));
  }
  if (plan.timeBudget > 0.0 && secondsPerSpp > 0.0) later = std::min(later, secondsLeft / secondsPerSpp);
  return std::max(later, 0.0);
}

namespace {

// Each pixel's weight for the round just rendered, from what was planned before its values were seen: its count,
// and the samples the render plans after it (image-wide, from the sample count, the time left or the estimate
// before the round).
std::vector<double> roundWeights(const RoundFilm& film, const std::vector<uint32_t>& counts, uint32_t spp, double laterSpp) {
  std::vector<double> w(counts.size());
  for (size_t p = 0; p < counts.size(); ++p)
    w[p] = roundWeight(film.weightSoFar(p), counts[p], double(counts[p]) / spp * laterSpp, laterSpp <= 0.0);
  return w;
}

struct RoundRun {
  PathRenderer& renderer;
  RenderStats& stats;
  const RenderControl& control;
  std::vector<uint32_t> nextSample;  // per pixel: its next sample number
};

// One round of per-pixel counts into `round`, in chunks of at most samplesPerBatch() samples a pixel taken chunk
// by chunk over the image (a pixel's chunks far apart, so passes stay full), the device's batch folded after
// every pass. False when a stop request came first (the round is then incomplete and left out).
bool renderRound(RoundRun& run, const std::vector<uint32_t>& counts, Film& round) {
  const uint32_t perBatch = run.renderer.samplesPerBatch();
  const uint32_t most = *std::max_element(counts.begin(), counts.end());
  std::vector<PathRenderer::PixelSamples> work;
  for (uint32_t from = 0; from < most; from += perBatch)
    for (uint32_t p = 0; p < counts.size(); ++p)
      if (counts[p] > from) work.push_back({p, run.nextSample[p] + from, std::min(perBatch, counts[p] - from)});
  const bool finished = run.renderer.renderSampleRunsInto(round, work, run.stats,
                                                          [&] { return !(run.control.stop && run.control.stop->load() != 0); });
  if (finished)
    for (uint32_t p = 0; p < counts.size(); ++p) run.nextSample[p] += counts[p];
  return finished;
}

}  // namespace

SampleRoundsOutcome renderSampleRounds(PathRenderer& renderer, RenderState& state, const RenderControl& control,
                                       const RenderSettings& settings, const SampleRoundsPlan& plan, EarlierRounds* earlier) {
  const uint32_t width = settings.width, height = settings.height, pixels = width * height;
  const uint32_t replicates = settings.estimator.replicates;
  const bool replicateVariance = settings.estimator.sampler != Sampler::Independent;
  RoundFilm combined = earlier ? std::move(earlier->film) : RoundFilm(width, height, replicates, replicateVariance);
  RenderStats& stats = state.stats;
  const RenderStats before = stats;
  RoundRun run{renderer, stats, control, std::vector<uint32_t>(pixels, 0)};
  SampleRoundsOutcome out;
  const auto start = Clock::now();
  const bool progress = settings.progress && isatty(STDERR_FILENO);
  // The render's own rounds are sized from its own samples (the earlier rounds come on top of plan.spp, their
  // weights already taken), the first of them uniform: the earlier rounds covered a subset of the pixels.
  uint32_t done = 0, ownRounds = 0;
  if (combined.rounds() > 0) out.relMse = estimateRelMse(combined.image(), kRelMseEpsilon);
  double secondsPerSpp = 0.0;
  while (true) {
    const double elapsed = since(start);
    if (plan.timeBudget > 0.0 && done > 0 && elapsed >= plan.timeBudget) break;
    const uint32_t spp = nextRoundSpp(plan, done, replicates, out.relMse, plan.timeBudget - elapsed, secondsPerSpp);
    if (spp == 0) break;
    const uint64_t budget = uint64_t(spp) * pixels;
    std::vector<uint32_t> counts(pixels, spp);
    if (plan.adaptive && ownRounds > 0)
      counts =
          allocateSamples(smoothedRelativeVariance(combined.means(), combined.sampleVariances(), width, height, kRelMseEpsilon),
                          combined.costs(), budget, AllocationLimits{replicates, replicates});
    Film round(width, height);
    round.replicates = replicates, round.replicateVariance = replicateVariance;
    const auto roundStart = Clock::now();
    if (!renderRound(run, counts, round)) {
      state.interrupted = true, state.stopSignal = control.stop->load();
      break;
    }
    secondsPerSpp = since(roundStart) / spp;
    const double later = plannedLaterSpp(plan, done, spp, out.relMse, plan.timeBudget - since(start), secondsPerSpp);
    combined.addRound(round, roundWeights(combined, counts, spp, later));
    if (++ownRounds == 1) out.firstRoundSpp = spp;
    done += spp;
    const Film image = combined.image();
    out.relMse = estimateRelMse(image, kRelMseEpsilon);
    if (settings.estimator.shadowRrThreshold > 0.0f) renderer.uploadPixelEstimate(image);
    if (progress)
      std::fprintf(stderr, "\rvkmc: round %u, %u spp, relMSE %.3g (upper %.3g)   ", combined.rounds(), done, out.relMse.value,
                   out.relMse.upper);
    if (plan.targetError > 0.0 && out.relMse.upper <= plan.targetError) {
      out.targetReached = true;
      break;
    }
  }
  if (progress) std::fprintf(stderr, "\n");
  out.rounds = combined.rounds();
  state.film = combined.image();
  state.nextSample = done;
  if (!run.nextSample.empty()) {
    out.minPixelSamples = *std::min_element(run.nextSample.begin(), run.nextSample.end());
    out.maxPixelSamples = *std::max_element(run.nextSample.begin(), run.nextSample.end());
  }
  stats.seconds = before.seconds + since(start);
  stats.samplesPerPixel = done + (earlier ? uint32_t(std::lround(earlier->spp)) : 0u);
  renderer.finishStats(stats, before);
  return out;
}

}  // namespace vkmc
