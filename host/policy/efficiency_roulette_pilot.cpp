// Efficiency-roulette pilot: render, weigh each path by its pixel's relative error, optimize the scales.
#include "policy/efficiency_roulette_pilot.h"

#include <algorithm>
#include <chrono>

#include "../shaders/shared/rng.h"
#include "../shaders/shared/sampling.h"
#include "analysis/error_metrics.h"
#include "render/path_renderer.h"

namespace vkmc {

namespace {
constexpr uint32_t kRoulettePilotSeedSalt = 0x9e3779b9u;

// The pilot's samples of `pixels` alone, as sample runs (each pixel's samples from 0, as a render's would be).
Film renderPixels(PathRenderer& pilot, const RenderSettings& settings, const std::vector<uint32_t>& pixels, RenderStats& stats) {
  Film film(settings.width, settings.height);
  film.replicates = settings.estimator.replicates, film.replicateVariance = settings.estimator.sampler != Sampler::Independent;
  std::vector<PathRenderer::PixelSamples> work;
  for (uint32_t p : pixels) work.push_back({p, 0u, settings.spp});
  const auto start = std::chrono::steady_clock::now();
  pilot.renderSampleRunsInto(film, work, stats);
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return film;
}
}  // namespace

RoulettePilot runRoulettePilot(vk::Context& ctx, const GpuScene& scene, const RenderSettings& settings,
                               const std::vector<uint32_t>& pixels) {
  // No roulette, no splitting, a depth cap (its truncation only shortens the statistics), a few samples per pixel.
  const EstimatorConfig& est = settings.estimator;
  RenderSettings pilotSettings = settings;
  pilotSettings.estimator.rr = RouletteMode::None;
  pilotSettings.estimator.maxDepth = est.maxDepth ? std::min(est.maxDepth, 24u) : 24u;
  pilotSettings.estimator.bsdfSamples = 1.0f;
  pilotSettings.estimator.splitDepth = 1;
  pilotSettings.spp = std::min<uint32_t>(4, settings.spp);
  pilotSettings.estimator.replicates = std::max(2u, est.replicates);  // the weights below need a variance
  // Its own samples: with the render's seed its first samples a pixel would be the render's, and the scales would
  // depend on the very samples they weigh.
  pilotSettings.seed = gpu::hashU32(settings.seed ^ kRoulettePilotSeedSalt);
  pilotSettings.timeBudget = 0.0;
  pilotSettings.progress = false;
  pilotSettings.recordDepthStats = true;
  pilotSettings.integrator = Integrator::Wavefront;  // the shade stage records the pilot's statistics
  pilotSettings.sampleRuns = !pixels.empty();
  PathRenderer pilot(ctx, scene, pilotSettings);
  RoulettePilot out;
  out.pipelineSeconds = pilot.pipelineSeconds();
  RenderStats stats;
  Film film = pixels.empty() ? pilot.render(stats) : renderPixels(pilot, pilotSettings, pixels, stats);
  // Relative to each pixel's mean, as relMSE is.
  std::vector<double> weight(film.pixels());
  double variance = 0.0;
  size_t rendered = 0;
  for (size_t p = 0; p < film.pixels(); ++p) {
    if (film.count[p] == 0) continue;  // outside the subset
    ++rendered;
    double m = gpu::luminance(glm::vec3(film.mean(p, 0), film.mean(p, 1), film.mean(p, 2)));
    weight[p] = 1.0 / (m * m + kRelMseEpsilon);
    for (int c = 0; c < 3; ++c) variance += film.varianceOfMean(p, c) * double(film.count[p]) * weight[p];
  }
  variance /= 3.0 * std::max<size_t>(1, rendered);
  std::vector<PilotPath> paths = pilot.pilot();
  for (PilotPath& pp : paths) pp.weight = static_cast<float>(weight[std::min<size_t>(pp.pixel, weight.size() - 1)]);
  double raysPerVertex = double(stats.extensionRays + stats.shadowRays) / std::max(1.0, double(stats.extensionRays));
  // Roulette acts at the decision of vertex d when d + 1 >= rr_depth.
  out.table = optimizeRouletteScales(paths, variance, raysPerVertex, std::max(est.rrDepth, 1u) - 1u);
  out.seconds = stats.seconds;
  return out;
}

}  // namespace vkmc
