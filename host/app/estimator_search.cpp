#include "app/estimator_search.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <numeric>
#include <random>

#include "../shaders/shared/rng.h"
#include "app/roulette_pilot.h"
#include "estimators/estimator_params.h"
#include "render/film.h"
#include "render/path_renderer.h"

namespace vkmc {

namespace {

// The pilots' seed: their own, so the render's samples are independent of what chose its estimator.
constexpr uint32_t kPilotSeedSalt = 0x5eed0a17u;

// One candidate's pilot: its renderer (its own pipelines), and its samples over the first pixels of the order.
class CandidatePilot {
 public:
  CandidatePilot(vk::Context& ctx, const GpuScene& scene, const RenderSettings& render, const EstimatorConfig& e,
                 EstimatorChoice& out)
      : settings_(render), film_(render.width, render.height) {
    settings_.estimator = e;
    settings_.estimator.replicates = 2;  // one sample in each: a variance per pixel (kChoicePilotSpp)
    settings_.seed = gpu::hashU32(render.seed ^ kPilotSeedSalt);
    settings_.sampleRuns = true, settings_.progress = false, settings_.timeBudget = 0.0;
    settings_.spp = kChoicePilotSpp;
    if (e.splitsPaths()) settings_.integrator = Integrator::Wavefront;  // splitting needs the path pool
    film_.replicates = 2, film_.replicateVariance = e.sampler != Sampler::Independent;
    if (e.rr == RouletteMode::Efficiency) {
      RoulettePilot pilot = runRoulettePilot(ctx, scene, settings_);
      out.pipelineSeconds += pilot.pipelineSeconds, out.seconds += pilot.seconds;
      roulette_ = pilot.table;
    }
    renderer_ = std::make_unique<PathRenderer>(ctx, scene, settings_);
    if (roulette_) renderer_->setRouletteScales(roulette_->scale);
    out.pipelineSeconds += renderer_->pipelineSeconds();
  }
  // Pixels order[from, to) at kChoicePilotSpp samples each.
  void render(const std::vector<uint32_t>& order, uint32_t from, uint32_t to) {
    std::vector<PathRenderer::PixelSamples> work;
    for (uint32_t i = from; i < to; ++i) work.push_back({order[i], 0, kChoicePilotSpp});
    const auto start = std::chrono::steady_clock::now();
    renderer_->renderSampleRuns(work, stats_, [&] {
      const std::vector<gpu::FilmPixel> batch = renderer_->takeBatch();
      film_.addBatch(batch.data());
      return true;
    });
    pixels_ = to;
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  // What the choice reads, over order[0, pixels): means, a sample's variances, and a sample's cost.
  PilotSamples samples(const std::vector<uint32_t>& order, uint32_t pixels, bool byTime) const {
    PilotSamples s;
    for (uint32_t i = 0; i < pixels; ++i) {
      const uint32_t p = order[i];
      glm::dvec3 mean, variance;
      for (int c = 0; c < 3; ++c)
        mean[c] = film_.mean(p, c), variance[c] = film_.varianceOfMean(p, c) * double(film_.count[p]);
      s.mean.push_back(mean), s.sampleVariance.push_back(variance);
    }
    const double pixelSamples = double(pixels_) * kChoicePilotSpp;
    s.cost = (byTime ? stats_.gpuSeconds : double(stats_.rays())) / pixelSamples;
    return s;
  }
  double gpuSeconds() const { return stats_.gpuSeconds; }
  double seconds() const { return seconds_; }  // the pilot's passes, wall time
  const std::optional<RouletteTable>& roulette() const { return roulette_; }
  void release() { renderer_.reset(); }

 private:
  RenderSettings settings_;
  Film film_;
  RenderStats stats_;
  std::unique_ptr<PathRenderer> renderer_;
  std::optional<RouletteTable> roulette_;
  uint32_t pixels_ = 0;
  double seconds_ = 0.0;
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

}  // namespace

EstimatorChoice chooseEstimator(vk::Context& ctx, const GpuScene& scene, const RenderSettings& settings,
                                const std::set<std::string>& pinned, double timeBudget) {
  EstimatorChoice out;
  const bool byTime = timeBudget > 0.0;
  out.costUnit = byTime ? "GPU seconds" : "rays";
  const SceneFeatures& f = settings.features;
  const std::vector<SearchStep> steps = estimatorSearchSteps(pinned, SearchScene{f.emitters(), f.lights()});
  uint32_t candidates = 1;
  for (const SearchStep& s : steps) candidates += uint32_t(s.values.size());
  const uint32_t imagePixels = settings.width * settings.height;
  const std::vector<uint32_t> order = pixelOrder(imagePixels, settings.seed);
  // The start, first on the fewest pixels; under a time budget its pace then sizes every pilot.
  std::vector<std::unique_ptr<CandidatePilot>> pilots;
  pilots.push_back(std::make_unique<CandidatePilot>(ctx, scene, settings, settings.estimator, out));
  uint32_t pixels = pilotPixels(0.0, candidates, imagePixels);
  pilots[0]->render(order, 0, pixels);
  const double planned = byTime ? timeBudget / std::max(pilots[0]->gpuSeconds() / (pixels * double(kChoicePilotSpp)), 1e-12)
                                : double(imagePixels) * settings.spp;
  const uint32_t more = pilotPixels(planned, candidates, imagePixels);
  if (more > pixels) pilots[0]->render(order, pixels, more), pixels = more;
  pilots[0]->release();
  out.candidates.push_back({"start", settings.estimator, {}, false});
  size_t best = 0;
  std::vector<PilotSamples> measured = {pilots[0]->samples(order, pixels, byTime)};
  const PilotPixels where{settings.width, settings.height, std::vector<uint32_t>(order.begin(), order.begin() + pixels)};
  for (const SearchStep& step : steps) {
    const size_t incumbent = best, first = out.candidates.size();
    for (double value : step.values) {
      EstimatorConfig e = out.candidates[incumbent].config;
      findEstimatorParam(step.key)->set(e, value);
      pilots.push_back(std::make_unique<CandidatePilot>(ctx, scene, settings, e, out));
      pilots.back()->render(order, 0, pixels);
      pilots.back()->release();
      measured.push_back(pilots.back()->samples(order, pixels, byTime));
      out.candidates.push_back({label(step.key, value), e, {}, false});
    }
    // Each decision reads every candidate against the means pooled so far.
    const std::vector<CandidateReading> readings = readCandidates(where, measured, kRelMseEpsilon);
    for (size_t c = first; c < readings.size(); ++c)
      if (beats(readings[c], readings[best])) best = c;
  }
  const std::vector<CandidateReading> readings = readCandidates(where, measured, kRelMseEpsilon);
  for (size_t c = 0; c < readings.size(); ++c) out.candidates[c].reading = readings[c];
  out.candidates[best].chosen = true;
  out.chosen = out.candidates[best].config;
  out.chosen.replicates = settings.estimator.replicates;
  out.roulette = pilots[best]->roulette();
  for (const auto& p : pilots) out.seconds += p->seconds();
  out.pilotPixels = pixels;
  out.share = double(pixels) * kChoicePilotSpp * double(pilots.size()) / planned;
  return out;
}

}  // namespace vkmc
