#include "app/estimator_search.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <memory>
#include <numeric>
#include <random>

#include "../shaders/shared/rng.h"
#include "policy/efficiency_roulette_pilot.h"
#include "estimators/estimator_params.h"
#include "render/film.h"
#include "render/path_renderer.h"

namespace vkmc {

namespace {

// The pilots' seeds: each its own, so that every pilot's samples, and the render's, are independent of the others
// (with one seed the candidates' samples would share their random numbers, and the pilots' rounds in the image
// would weigh near-copies as if independent).
constexpr uint32_t kPilotSeedSalt = 0x5eed0a17u;

// A candidate pilot's settings: the render's with the candidate's estimator, its own seed (its index's), samples
// run by pixel.
RenderSettings candidateSettings(const RenderSettings& render, const EstimatorConfig& e, uint32_t index, uint32_t spp) {
  RenderSettings s = render;
  s.estimator = e;
  s.seed = gpu::hashU32(render.seed ^ kPilotSeedSalt ^ gpu::hashU32(index + 1u));
  s.sampleRuns = true, s.progress = false, s.timeBudget = 0.0;
  s.spp = spp;
  if (e.splitsPaths()) s.integrator = Integrator::Wavefront;  // splitting needs the path pool
  return s;
}

// rr efficiency's table for a pilot: learnt already (its roulette pilot's seconds counted with the pilot's), or
// reused at no cost (a confirmation tests the table that will render). Without one, the pilot learns its own.
struct GivenRoulette {
  RouletteTable table;
  double learntSeconds = 0.0;
};

// One candidate's pilot: its renderer (its own pipelines), and its samples over the first pixels of the order.
// learnOn: where rr efficiency learns its table without one given (the whole image where empty).
class CandidatePilot {
 public:
  CandidatePilot(vk::Context& ctx, const GpuScene& scene, const RenderSettings& render, const EstimatorConfig& e, uint32_t index,
                 EstimatorChoice& out, const std::optional<GivenRoulette>& given = std::nullopt,
                 uint32_t spp = kChoiceMaxPilotSpp, const std::vector<uint32_t>& learnOn = {})
      : settings_(candidateSettings(render, e, index, spp)), film_(render.width, render.height) {
    film_.replicates = e.replicates, film_.replicateVariance = e.sampler != Sampler::Independent;
    if (e.rr == RouletteMode::Efficiency && given) {
      roulette_ = given->table, seconds_ += given->learntSeconds;
    } else if (e.rr == RouletteMode::Efficiency) {
      RoulettePilot pilot = runRoulettePilot(ctx, scene, settings_, learnOn);
      out.pipelineSeconds += pilot.pipelineSeconds, seconds_ += pilot.seconds;
      roulette_ = pilot.table;
    }
    renderer_ = std::make_unique<PathRenderer>(ctx, scene, settings_);
    if (roulette_) renderer_->setRouletteScales(roulette_->scale);
    out.pipelineSeconds += renderer_->pipelineSeconds();
  }
  uint32_t pathsPerPass() const { return renderer_->pathsPerPass(); }
  // Pixels order[from, to) at spp samples each (the start's probe, then the rest of its pixels).
  void render(const std::vector<uint32_t>& order, uint32_t from, uint32_t to, uint32_t spp) {
    const auto start = std::chrono::steady_clock::now();
    run(order, from, to, spp);
    pixelSamples_ += double(to - from) * spp;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    passSeconds_ += seconds, seconds_ += seconds;
  }
  void releaseRenderer() { renderer_.reset(); }
  // What the choice reads, over order[0, pixels): means, a sample's variances, and a sample's GPU seconds.
  PilotSamples samples(const std::vector<uint32_t>& order, uint32_t pixels) const {
    PilotSamples s;
    for (uint32_t i = 0; i < pixels; ++i) {
      glm::dvec3 mean;
      for (int c = 0; c < 3; ++c) mean[c] = film_.mean(order[i], c);
      s.mean.push_back(mean);
    }
    s.sampleVariance = sampleVariances(order, pixels);
    s.cost = stats_.gpuSeconds / pixelSamples_;
    return s;
  }
  // The sampler's gain over independent samples at the pilot's samples a scrambling (stageScale in
  // estimator_choice.h): the replicates' variance of the mean over the samples' own, relative as relMSE weighs
  // each pixel, summed over order[0, pixels). 1 without replicates to read it from.
  double qmcGain(const std::vector<uint32_t>& order, uint32_t pixels) const {
    if (!film_.replicateVariance || film_.replicates < 2) return 1.0;
    double replicates = 0.0, independent = 0.0;
    for (uint32_t i = 0; i < pixels; ++i)
      for (int c = 0; c < 3; ++c) {
        const double m = film_.mean(order[i], c), w = 1.0 / (m * m + kRelMseEpsilon);
        replicates += w * film_.replicateVarianceOfMean(order[i], c), independent += w * film_.sampleVarianceOfMean(order[i], c);
      }
    return independent > 0.0 ? replicates / independent : 1.0;
  }
  const Film& film() const { return film_; }
  void releaseFilm() { film_ = Film(); }
  const RenderStats& stats() const { return stats_; }
  double seconds() const { return seconds_; }          // the pilot's passes, wall time
  double passSeconds() const { return passSeconds_; }  // its passes alone (without rr efficiency's own pilot)
  double secondsPerPixelSample() const { return passSeconds_ / pixelSamples_; }
  double secondsPerPixelSampleLearnt() const { return seconds_ / pixelSamples_; }  // rr efficiency's table's pilot too
  const std::optional<RouletteTable>& roulette() const { return roulette_; }

 private:
  void run(const std::vector<uint32_t>& order, uint32_t from, uint32_t to, uint32_t samples) {
    if (samples == 0 || from >= to) return;
    std::vector<PathRenderer::PixelSamples> work;
    for (uint32_t i = from; i < to; ++i) work.push_back({order[i], 0u, samples});
    renderer_->renderSampleRunsInto(film_, work, stats_);
  }
  std::vector<glm::dvec3> sampleVariances(const std::vector<uint32_t>& order, uint32_t pixels) const {
    std::vector<glm::dvec3> v(pixels);
    for (uint32_t i = 0; i < pixels; ++i)
      for (int c = 0; c < 3; ++c) v[i][c] = film_.varianceOfMean(order[i], c) * double(film_.count[order[i]]);
    return v;
  }

  RenderSettings settings_;
  Film film_;
  RenderStats stats_;
  std::unique_ptr<PathRenderer> renderer_;
  std::optional<RouletteTable> roulette_;
  double pixelSamples_ = 0.0, seconds_ = 0.0, passSeconds_ = 0.0;
};

// A pixel order the pilots share (the same pixels for every candidate: a paired comparison), shuffled so any
// prefix spreads over the image.
std::vector<uint32_t> pixelOrder(uint32_t pixels, uint32_t seed) {
  std::vector<uint32_t> order(pixels);
  std::iota(order.begin(), order.end(), 0u);
  std::mt19937 rng(seed ^ kPilotSeedSalt);
  std::shuffle(order.begin(), order.end(), rng);
  return order;
}

std::string label(const std::string& key, double value) {
  const EstimatorParam* p = findEstimatorParam(key);
  return key + "=" + p->text(value);
}

// The image's share of each pilot: a round of the render (round_film.h) whose weights are fixed before its values
// are seen, from its samples and those planned after it (plannedSpp a pixel on average, from the render's samples
// or its time budget at the start's pace).
class PilotRounds {
 public:
  PilotRounds(RoundFilm& film, const std::vector<uint32_t>& order) : film_(film), order_(order), done_(order.size(), 0) {}
  void add(const Film& pilot, double plannedSpp, PilotShape shape) {
    std::vector<double> weight(order_.size(), 0.0);
    for (uint32_t i = 0; i < shape.pixels; ++i) {
      const uint32_t p = order_[i];
      const double later = std::max(plannedSpp - done_[p] - shape.spp, double(shape.spp));
      weight[p] = roundWeight(film_.weightSoFar(p), shape.spp, later, false);
      done_[p] += shape.spp;
    }
    film_.addRound(pilot, weight);
    pixelSamples_ += double(shape.pixels) * shape.spp;
  }
  double pixelSamples() const { return pixelSamples_; }

 private:
  RoundFilm& film_;
  const std::vector<uint32_t>& order_;
  std::vector<uint32_t> done_;
  double pixelSamples_ = 0.0;
};

SearchScene searchScene(const SceneFeatures& f, vk::Context& ctx) {
  return SearchScene{f.lights(), ctx.hasFloatAtomics(), f.glossy, f.emitters()};
}

// The pilots as they run: each a round of the image, its reading kept; the shapes and pixel order they share.
struct PilotRun {
  vk::Context& ctx;
  const GpuScene& scene;
  const RenderSettings& settings;
  const std::vector<uint32_t>& order;
  PilotShape pass;   // a pass of the render's size (pilotShape)
  PilotShape shape;  // the search's: the pass's first pixels, as many as the share fits (pilotPixelsInShare)
  PilotRounds& rounds;
  EstimatorChoice& out;
  std::vector<std::unique_ptr<CandidatePilot>> pilots;
  double plannedSpp = 0.0;
  std::unique_ptr<CandidatePilot> pending;  // the start's, made before the shape (which its pass size sets)

  // Where a configuration's search pilot runs: the search's pixels, or the whole pass where it splits paths (its
  // cost a path depends on the pass's size).
  PilotShape shapeFor(const EstimatorConfig& e) const { return e.splitsPaths() ? pass : shape; }
  // Where rr efficiency learns a challenger's table.
  std::vector<uint32_t> learnPixels() const {
    const size_t n = std::min<size_t>(order.size(), size_t(kChoiceRoulettePilotPixels) * shape.pixels);
    return std::vector<uint32_t>(order.begin(), order.begin() + n);
  }
  // A pilot's expected seconds at `at` from pilot k's pace (learnt: with its roulette table's pilot).
  double secondsAt(size_t k, PilotShape at, bool learnt = false) const {
    const CandidatePilot& p = *pilots[k];
    return (learnt ? p.secondsPerPixelSampleLearnt() : p.secondsPerPixelSample()) * double(at.pixels) * at.spp;
  }

  // A pilot of `e`, its seed its index's. The start's (the first) sets the plan's pace under a time budget, and
  // where `share` is given it renders a probe first, whose pace sets the search's pixels (share: the seconds of the
  // share at a sample's pace). `at`: the confirmation's shape; `given`: its roulette table.
  PilotSamples run(const EstimatorConfig& e, double timeBudget, uint32_t imagePixels,
                   const std::optional<GivenRoulette>& given = std::nullopt, std::optional<PilotShape> at = std::nullopt,
                   const std::function<double(double)>& share = nullptr) {
    // A search pilot's settings as the start's (made before the shape); a confirming one's its own samples a pixel.
    const uint32_t spp = at ? at->spp : kChoiceMaxPilotSpp;
    if (!pending) {
      const bool learns = e.rr == RouletteMode::Efficiency && !given;
      pending = std::make_unique<CandidatePilot>(ctx, scene, settings, e, uint32_t(pilots.size()), out, given, spp,
                                                 learns ? learnPixels() : std::vector<uint32_t>{});
    }
    pilots.push_back(std::move(pending));
    CandidatePilot& pilot = *pilots.back();
    uint32_t done = 0;
    if (share) {
      done = probePixels(shape);
      pilot.render(order, 0, done, spp);
      const double rate = pilot.secondsPerPixelSample();
      shape.pixels = std::max(done, pilotPixelsInShare(shape, share(rate), rate * spp));
    }
    const PilotShape here = at.value_or(shapeFor(e));
    pilot.render(order, done, here.pixels, here.spp);
    pilot.releaseRenderer();
    // Its round's weight from the plan as it stood before it ran: the start's own pace (its GPU time, which follows
    // its paths' lengths and so its values) may set only the later rounds' weights. Under a budget with no sample
    // cap the start's round then weighs next to nothing, about 3% of its pixels' samples set aside.
    rounds.add(pilot.film(), plannedSpp, here);
    if (timeBudget > 0.0 && pilots.size() == 1)
      plannedSpp = std::min(plannedSpp, timeBudget / (pilots[0]->secondsPerPixelSample() * imagePixels));
    PilotSamples samples = pilot.samples(order, here.pixels);
    const double replicates = std::max(1u, settings.estimator.replicates);
    samples.stageScale = stageScale(pilot.qmcGain(order, here.pixels), here.spp / replicates, plannedSpp / replicates);
    pilot.releaseFilm();  // a full image's sums, of which the rounds and the reading keep what they need
    return samples;
  }
};

// rr efficiency's table for a challenger that turns it on, learnt before its kernels are built. Where the table
// predicts at most kChoiceMinRoulettePrediction of the throughput rule's efficiency, its pilot is not rendered
// and its learning pass is counted in the pilots' seconds alone.
struct ChallengerRoulette {
  std::optional<GivenRoulette> given;
  bool predictsNoGain = false;
};
ChallengerRoulette learnChallengerRoulette(PilotRun& run, const EstimatorConfig& e, const EstimatorConfig& incumbent,
                                           double& pilotSeconds) {
  ChallengerRoulette r;
  if (e.rr != RouletteMode::Efficiency || incumbent.rr == RouletteMode::Efficiency) return r;
  const RenderSettings at = candidateSettings(run.settings, e, uint32_t(run.pilots.size()), kChoiceMaxPilotSpp);
  const RoulettePilot pilot = runRoulettePilot(run.ctx, run.scene, at, run.learnPixels());
  run.out.pipelineSeconds += pilot.pipelineSeconds;
  run.out.roulettePrediction = pilot.table.gainOverThroughput;
  if (pilot.table.gainOverThroughput > kChoiceMinRoulettePrediction) {
    r.given = GivenRoulette{pilot.table, pilot.seconds};
  } else {
    r.predictsNoGain = true;
    pilotSeconds += pilot.seconds, run.out.seconds += pilot.seconds;
  }
  return r;
}

// The winner against the start again, on fresh pilots of both (their own seeds, a prefix of the search's pixels at
// more samples each: confirmationShape): the search's readings chose it from several comparisons, so its lead there
// reads high (the winner's curse), and at 64 samples a pixel, earlier in the convergence than the render. Where its
// fresh reading is not ahead by the margin (confirms), the start renders.
bool confirmWinner(PilotRun& run, size_t best, double& pilotSeconds, double budget, const ChoiceBounds& bounds,
                   uint32_t imagePixels, const std::vector<glm::dvec3>& searchValues) {
  Confirmation& c = run.out.confirmation;
  const PilotShape shape =
      confirmationShape(run.shapeFor(run.out.candidates[best].config), run.plannedSpp, run.settings.estimator.replicates);
  const double expected = run.secondsAt(0, shape) + run.secondsAt(best, shape);
  if (!pilotFitsBudget(pilotSeconds, expected, budget)) return true;  // unconfirmed, as the report says
  c.shape = shape;
  std::vector<PilotSamples> again;
  for (size_t candidate : {size_t(0), best}) {
    // Each with the roulette table its search pilot learnt: the configuration that will render, table and all.
    const std::optional<RouletteTable>& table = run.pilots[candidate]->roulette();
    again.push_back(run.run(run.out.candidates[candidate].config, bounds.timeBudget, imagePixels,
                            table ? std::optional<GivenRoulette>(GivenRoulette{*table}) : std::nullopt, c.shape));
    pilotSeconds += run.pilots.back()->seconds();
  }
  // The value each pixel's variance is relative to: the search's pilots', independent of both confirming ones.
  const std::vector<glm::dvec3> values(searchValues.begin(),
                                       searchValues.begin() + std::min<size_t>(c.shape.pixels, searchValues.size()));
  const std::vector<CandidateReading> readings = readAgainst(values, again, kRelMseEpsilon);
  c.ran = true, c.candidate = run.out.candidates[best].label;
  c.start = readings[0], c.winner = readings[1], c.vsStart = compare(readings[1], readings[0]);
  c.confirmed =
      confirms(readings[1], readings[0]) && (!bounds.sampleCountEnds || affordableAtSampleCount(readings[1], readings[0]));
  return c.confirmed;
}

void finishChoice(EstimatorChoice& out, const PilotRun& run, size_t best, const ChoiceBounds& bounds) {
  out.costCapped = bounds.sampleCountEnds;
  out.cutShort = out.candidates.size() == 1 && !out.skippedForBudget.empty();
  out.candidates[best].chosen = true;
  out.chosen = out.candidates[best].config;
  out.roulette = run.pilots[best]->roulette();
  for (const auto& p : run.pilots) out.seconds += p->seconds(), out.stats.push_back(p->stats());
  out.pilotPixels = run.shape.pixels, out.pilotSpp = run.shape.spp, out.passPixels = run.pass.pixels;
  out.pixelSamples = run.rounds.pixelSamples();
  out.share = run.rounds.pixelSamples() / (run.plannedSpp * run.settings.width * run.settings.height);
}

// The search as it goes: every candidate's samples over the search's pixels, the best so far, the share's seconds.
struct Search {
  PilotRun& run;
  const ChoiceBounds& bounds;
  uint32_t imagePixels = 0;
  double budget = 0.0;  // the seconds the share is of (0: none)
  std::vector<PilotSamples> measured;
  PilotPixels where;
  size_t best = 0;
  double pilotSeconds = 0.0;

  void measure(const std::string& label, const EstimatorConfig& e, const std::optional<GivenRoulette>& given,
               const std::function<double(double)>& share = nullptr) {
    measured.push_back(run.run(e, bounds.timeBudget, imagePixels, given, std::nullopt, share));
    MeasuredCandidate m;
    m.label = label, m.config = e, m.seconds = run.pilots.back()->seconds();
    run.out.candidates.push_back(m);
    pilotSeconds += m.seconds;
  }
  // Whether the challenger's pilot fits the share. After the first challenger, room is kept for the confirmation of
  // whichever wins (the start again and the winner again at the winner's shape: a confirmation reuses rr efficiency's
  // table, so the passes alone, and the challenger's expected seconds, its own roulette pilot included, to be safe).
  // The first is measured wherever it fits alone: on a loaded machine the per-depth roulette pilot and a confirmation
  // after it do not fit 5% of 24 s, and its 4-6x on the dark interiors renders unconfirmed rather than not at all.
  bool fits(const SearchStep& step, double value, const EstimatorConfig& e) const {
    const EstimatorConfig& incumbent = run.out.candidates[best].config;
    const double factor = expectedPilotCost(step.key, value, findEstimatorParam(step.key)->get(incumbent));
    const PilotShape at = run.shapeFor(e), bestAt = run.shapeFor(incumbent);
    const double expected = run.secondsAt(best, at, true) * factor;
    const PilotShape widest = double(at.pixels) * at.spp > double(bestAt.pixels) * bestAt.spp ? at : bestAt;
    const double confirming =
        run.out.candidates.size() == 1 ? 0.0 : run.secondsAt(0, widest) + std::max(expected, run.secondsAt(best, bestAt));
    return pilotFitsBudget(pilotSeconds, expected + confirming, budget);
  }
  // One key's values against the best so far, each read against the values pooled so far; the next value only
  // where this one won (or lost: nextWhereLost). Under a time budget, only what fits its share (the next key may).
  void step(const SearchStep& step) {
    EstimatorChoice& out = run.out;
    for (double value : step.values) {
      EstimatorConfig e = out.candidates[best].config;
      findEstimatorParam(step.key)->set(e, value);
      if (!fits(step, value, e)) {
        out.skippedForBudget.push_back(label(step.key, value));
        if (step.nextWhereLost) continue;  // the next value is cheaper: it may fit
        break;
      }
      const ChallengerRoulette roulette = learnChallengerRoulette(run, e, out.candidates[best].config, pilotSeconds);
      if (roulette.predictsNoGain) {
        out.skippedByPrediction.push_back(label(step.key, value));
        break;
      }
      measure(label(step.key, value), e, roulette.given);
      const std::vector<CandidateReading> readings = readCandidates(where, measured, kRelMseEpsilon);
      bool won = beats(readings.back(), readings[best]);
      if (won && bounds.sampleCountEnds && !affordableAtSampleCount(readings.back(), readings[0]))
        out.candidates.back().tooCostly = true, won = false;  // lost: with nextWhereLost a cheaper value may be affordable
      if (won) best = readings.size() - 1;
      if (won == step.nextWhereLost) break;
    }
  }
};

}  // namespace

EstimatorChoice chooseEstimator(vk::Context& ctx, const GpuScene& scene, const RenderSettings& settings,
                                const std::set<std::string>& pinned, const ChoiceBounds& bounds, RoundFilm& film) {
  EstimatorChoice out;
  const double timeBudget = bounds.timeBudget;
  const std::vector<SearchStep> steps = estimatorSearchSteps(pinned, searchScene(settings.features, ctx));
  const uint32_t imagePixels = settings.width * settings.height;
  const std::vector<uint32_t> order = pixelOrder(imagePixels, settings.seed);
  // Without a sample count (--target-error alone) the pilots plan for kChoiceNominalSpp.
  const bool noCount = settings.spp == kMaxSpp && timeBudget <= 0.0;
  const double renderSpp = noCount ? double(kChoiceNominalSpp) : double(settings.spp);
  // A budget with --spp as its cap plans for the cap at most.
  const double plannedPixelSamples = timeBudget > 0.0 && settings.spp == kMaxSpp ? 1e300 : renderSpp * imagePixels;
  PilotRounds rounds(film, order);
  PilotRun run{ctx, scene, settings, order, PilotShape{}, PilotShape{}, rounds, out, {}, renderSpp};
  run.pending = std::make_unique<CandidatePilot>(ctx, scene, settings, settings.estimator, 0u, out);
  run.pass = run.shape = pilotShape(run.pending->pathsPerPass(), plannedPixelSamples, pilotsPlanned(steps), imagePixels,
                                    settings.estimator.replicates);
  Search search{run, bounds, imagePixels};
  // The pilots' share is of the render's seconds: its budget, or (where asked) its samples at the start's pace
  // (a sample's seconds, from the start's probe). Their kernels are set-up, reported apart: Mesa's shader cache keeps
  // them for the next render (counted, they left the basement's per-depth pilot out of a 24-s budget on a loaded
  // machine, and its 4.7x with it).
  auto share = [&](double secondsPerSample) {
    search.budget = timeBudget > 0.0 ? timeBudget : bounds.shareOfSeconds ? secondsPerSample * renderSpp * imagePixels : 0.0;
    return kChoiceMaxShare * search.budget;
  };
  search.measure("start", settings.estimator, std::nullopt, share);
  search.where =
      PilotPixels{settings.width, settings.height, std::vector<uint32_t>(order.begin(), order.begin() + run.shape.pixels)};
  for (const SearchStep& step : steps) search.step(step);
  const std::vector<CandidateReading> readings = readCandidates(search.where, search.measured, kRelMseEpsilon);
  for (size_t c = 0; c < readings.size(); ++c) out.candidates[c].reading = readings[c];
  size_t best = search.best;
  if (best != 0 && !confirmWinner(run, best, search.pilotSeconds, search.budget, bounds, imagePixels,
                                  pooledValues(search.where, search.measured)))
    best = 0;
  finishChoice(out, run, best, bounds);
  return out;
}

}  // namespace vkmc
