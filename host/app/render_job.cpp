// Render job: the stages in order, each timed; the report and the human summary.
#include "app/render_job.h"

#include <bit>
#include <chrono>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "../shaders/shared/geometry.h"
#include "../shaders/shared/sampling.h"
#include "analysis/variance_reliability.h"
#include "app/malloc_tuning.h"
#include "app/render_options_json.h"
#include "policy/efficiency_roulette_pilot.h"
#include "bvh/bvh.h"
#include "bvh/seen_through_faces.h"
#include "error.h"
#include "io/checkpoint.h"
#include "io/environment_image.h"
#include "io/output_files.h"
#include "render/device_tuning.h"
#include "render/gpu_scene.h"
#include "render/render_kernels.h"
#include "scene/camera_rig.h"
#include "scene/framing.h"
#include "scene/studio_environment.h"
#include "scene/gltf_loader.h"
#include "scene/content_hash.h"
#include "scene/coordinate_precision.h"
#include "scene/scene_fingerprint.h"
#include "scene/thin_ribbons.h"
#include "vk/lavapipe_environment.h"

namespace vkmc {
namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
std::string formatNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", v);
  return text;
}
}  // namespace

void validateOptions(const RenderOptions& o) {
  if (o.spp == 0 || o.spp > kMaxSpp) throw Error("--spp must be between 1 and " + std::to_string(kMaxSpp));
  for (auto side : {o.width, o.height})
    if (side && (*side == 0 || *side > kMaxImageSide))
      throw Error("--width and --height must be between 1 and " + std::to_string(kMaxImageSide));
  o.estimator.validate();
  if (o.lookFrom.has_value() != o.lookAt.has_value()) throw Error("--look-from and --look-at go together");
  for (const auto& p : {o.lookFrom, o.lookAt})
    if (p && !glm::all(glm::lessThanEqual(glm::abs(*p), glm::vec3(gpu::kMaxSceneCoordinate))))
      throw Error("--look-from and --look-at must be finite and within +-" + formatNumber(gpu::kMaxSceneCoordinate) +
                  " (float ray tests overflow beyond)");
  if (!(o.fovDegrees > 0.0f && o.fovDegrees < 179.0f)) throw Error("--fov must be in (0, 179) degrees");
  for (int c = 0; c < 3 && o.background; ++c)
    if (!((*o.background)[c] >= 0.0f) || !std::isfinite((*o.background)[c]))
      throw Error("--background must be finite and non-negative");
  if (!(std::abs(o.environmentRotation) <= 360.0f))
    throw Error("--environment-rotation must be a number of degrees between -360 and 360");
  if (!(o.environmentStrength >= 0.0f && o.environmentStrength <= 1e9f))
    throw Error("--environment-strength must be between 0 and 1e9");
  if (o.environmentPath.empty() && o.background && (o.environmentRotation != 0.0f || o.environmentStrength != 1.0f))
    throw Error("--environment-rotation and --environment-strength need an environment, and --background replaces it");
  validatePixelFilter(o.filter);
  if (!(o.timeBudget >= 0.0) || o.timeBudget > 1e6) throw Error("--time-budget must be between 0 and 1e6 seconds");
  if (!(o.targetError >= 0.0 && o.targetError < 1e6)) throw Error("--target-error must be a relMSE above 0");
  if (o.adaptive || o.targetError > 0.0 || o.estimatorAuto) {
    const char* what = o.estimatorAuto ? "--estimator auto" : o.adaptive ? "--adaptive on" : "--target-error";
    if (o.estimator.rr == RouletteMode::Ears) throw Error(std::string(what) + " does not work with rr ears (its own passes) yet");
    if (o.estimator.sampler == Sampler::ZSobol)
      throw Error(std::string(what) + " needs the sobol or independent sampler (zsobol's index bounds a pixel's samples)");
    if (o.estimator.sampler != Sampler::Independent && o.estimator.replicates < 2)
      throw Error(std::string(what) + " needs a variance: --replicates 2 or more");
  }
}

namespace {
// What rr ears learned: the cache's size and use, and each depth's vertices by factor (untrained: throughput
// roulette; q < 1: roulette; q = 1; q > 1: splitting).
nlohmann::json earsJson(const EarsSummary& e) {
  auto byDepth = [](const auto& rows) {
    nlohmann::json depths = nlohmann::json::array();
    for (const auto& row : rows)
      depths.push_back({{"untrained", row[gpu::kEarsBinFallback]},
                        {"roulette", row[gpu::kEarsBinRoulette]},
                        {"kept", row[gpu::kEarsBinOne]},
                        {"split", row[gpu::kEarsBinSplit]}});
    return depths;
  };
  nlohmann::json j = {{"cells", e.cells},
                      {"occupied_cells", e.occupiedCells},
                      {"trusted_cells", e.trustedCells},
                      {"device_bytes", e.deviceBytes},
                      {"learning_passes", e.learningPasses},
                      {"training_spp", e.trainingSamples},
                      {"image_factor", e.imageFactor},
                      {"training_copies", e.copies},
                      {"mean_lr", {e.meanLr.x, e.meanLr.y, e.meanLr.z}},
                      {"mean_lr_squared", {e.meanLrSquared.x, e.meanLrSquared.y, e.meanLrSquared.z}},
                      {"mean_rays", e.meanRays},
                      {"factors_by_depth", byDepth(e.factors)},
                      {"learns_light_samples", e.learnsLight},
                      {"note", "the last depth row counts every deeper vertex"}};
  if (e.learnsLight) {
    j["light_cells"] = {{"occupied", e.occupiedLightCells}, {"trusted", e.trustedLightCells}};
    j["training_light_samples"] = e.lightSamples;
    j["mean_light_v"] = {e.meanV.x, e.meanV.y, e.meanV.z};
    j["mean_light_v_squared"] = {e.meanVSquared.x, e.meanVSquared.y, e.meanVSquared.z};
    j["mean_light_rays"] = e.meanLightRays;
    j["light_factors_by_depth"] = byDepth(e.lightFactors);
    j["light_note"] =
        "light factors count copies (untrained: light_samples as without ears; roulette: qL < 1, "
        "fewer shadow rays; split: qL > 1)";
  }
  return j;
}

// One line: the cache and the first vertices' decisions.
std::string earsLine(const EarsSummary& e) {
  char buf[640];
  const auto& r = e.factors[0];
  const auto& l = e.lightFactors[0];
  const double n = double(r[0] + r[1] + r[2] + r[3]), nl = double(l[0] + l[1] + l[2] + l[3]);
  auto pct = [&](uint64_t v) { return n > 0 ? 100.0 * double(v) / n : 0.0; };
  auto lightPct = [&](uint64_t v) { return nl > 0 ? 100.0 * double(v) / nl : 0.0; };
  char light[160] = "";
  if (e.learnsLight)
    std::snprintf(light, sizeof(light), "; their light samples: %.0f%% untrained, %.0f%% rouletted, %.0f%% split",
                  lightPct(l[gpu::kEarsBinFallback]), lightPct(l[gpu::kEarsBinRoulette]), lightPct(l[gpu::kEarsBinSplit]));
  std::snprintf(buf, sizeof(buf),
                "ears        %u spp of training passes (not in the image), %u learning passes; cells %u of %u used "
                "(%u trusted), %.1f MiB; first hits: %.0f%% untrained, %.0f%% rouletted, %.0f%% kept, %.0f%% split%s\n",
                e.trainingSamples, e.learningPasses, e.occupiedCells, e.cells, e.trustedCells, double(e.deviceBytes) / (1 << 20),
                pct(r[gpu::kEarsBinFallback]), pct(r[gpu::kEarsBinRoulette]), pct(r[gpu::kEarsBinOne]),
                pct(r[gpu::kEarsBinSplit]), light);
  return buf;
}
}  // namespace

AddedLight addedLight(const RenderOptions& options, const Scene& scene) {
  if (options.environmentPath == kStudioEnvironment) return AddedLight::Studio;
  if (!options.environmentPath.empty()) return AddedLight::Map;
  if (options.background) return AddedLight::None;
  switch (scene.world) {
    case World::LightsOnly: return AddedLight::None;
    case World::White: return AddedLight::White;
    case World::Studio: break;
  }
  return AddedLight::Studio;
}

namespace {
// The environment light: --environment's map or the studio, the file's world where neither --environment nor
// --background is given (the studio unless it declares another), importance sampled.
void addEnvironmentLight(const RenderOptions& options, Scene& scene, RenderOutcome& out, uint64_t maxTexels) {
  switch (addedLight(options, scene)) {
    case AddedLight::Studio:
      scene.environment = studioEnvironment();
      scene.environment->rotationDegrees = options.environmentRotation;
      for (glm::vec3& L : scene.environment->radiance) L *= options.environmentStrength;
      break;
    case AddedLight::Map:
      scene.environment =
          readEnvironmentMap(options.environmentPath, options.environmentRotation, options.environmentStrength, maxTexels);
      break;
    case AddedLight::White: scene.environment = EnvironmentMap::constant(glm::vec3(options.environmentStrength)); break;
    case AddedLight::None:
      if (options.environmentRotation != 0.0f || options.environmentStrength != 1.0f)
        throw Error("--environment-rotation and --environment-strength need an environment, and " + options.scenePath +
                    " declares its world lights-only (give --environment studio)");
      break;
  }
  out.environment = scene.environment ? scene.environment->source : "";
}

// The render itself, on options already validated by whichever runRender was called.
// Efficiency roulette's scales as bit patterns (+inf means no roulette at a depth; JSON has no inf).
nlohmann::json rouletteJson(const RouletteTable& t) {
  nlohmann::json bits = nlohmann::json::array();
  for (float k : t.scale) bits.push_back(std::bit_cast<uint32_t>(k));
  return bits;
}

RouletteTable rouletteFromJson(const nlohmann::json& j) {
  RouletteTable t;
  if (!j.is_array() || j.size() != t.scale.size()) throw Error("checkpoint: malformed efficiency roulette table");
  for (size_t d = 0; d < t.scale.size(); ++d) {
    if (!j[d].is_number_unsigned() || j[d].get<uint64_t>() > UINT32_MAX)
      throw Error("checkpoint: malformed efficiency roulette table");
    t.scale[d] = std::bit_cast<float>(uint32_t(j[d].get<uint64_t>()));
  }
  return t;
}

// What a checkpoint's film saw: the scene, the camera (an automatic one's framing follows vkmc's rules) and the
// backdrop, hashed field by field (no padding bytes).
ContentHash renderFingerprint(const Scene& scene, const RenderSettings& settings) {
  ContentHash fingerprint;
  fingerprint.addValue(sceneFingerprint(scene));
  for (const glm::vec3& v : {settings.camera.origin, settings.camera.forward, settings.camera.right, settings.camera.up})
    fingerprint.add(&v, sizeof(v));
  fingerprint.addValue(uint64_t(settings.camera.orthographic));
  fingerprint.add(&settings.backdrop, sizeof(settings.backdrop));
  return fingerprint;
}

// The checkpoint's configuration must be this render's: the same options (but the reference) and the same scene.
void checkResumable(const nlohmann::json& config, const nlohmann::json& options, const std::string& fingerprint) {
  std::string differ = differingRenderOptions(config.at("options"), options);
  if (!differ.empty()) throw Error("the checkpoint belongs to another render: it differs in " + differ);
  if (config.at("scene_fingerprint") != fingerprint)
    throw Error("the checkpoint belongs to another scene: '" + options.at("scene").get<std::string>() +
                "' (its geometry, materials, lights, environment or camera) changed since it was written");
}

// Writes a checkpoint atomically. A stop signal meanwhile only raises the render's stop flag (command_render.cpp's
// one handler), so the write completes and the render stops after it. Throws Error when it cannot be written.
void writeCheckpoint(const std::string& path, const std::string& bytes) { writeFileAtomically(path, bytes); }

// The camera the render looks through and the image's size.
struct Framing {
  Camera camera;
  std::optional<float> aspect;  // the scene camera's, where it has one
  uint32_t width = 0, height = 0;
};

// The scene's camera, or --look-from's (the automatic camera needs the image's size: frameScene sets it).
Framing pickCamera(const RenderOptions& options, const Scene& scene) {
  Framing f;
  if (options.lookFrom) {
    f.camera = lookAtCamera(*options.lookFrom, *options.lookAt, options.fovDegrees);
  } else if (options.cameraIndex || !scene.cameras.empty()) {
    uint32_t index = options.cameraIndex.value_or(0);
    if (index >= scene.cameras.size())
      throw Error("--camera " + std::to_string(index) + " out of range: the scene has " + std::to_string(scene.cameras.size()) +
                  " camera(s)");
    f.camera = scene.cameras[index];
    f.aspect = f.camera.aspectRatio;
    if (f.camera.name.empty()) f.camera.name = "camera " + std::to_string(index);
  }
  return f;
}

// Unset sides follow the camera's aspect ratio (square when it has none); kDefaultImageWidth wide by default.
Framing frameScene(const RenderOptions& options, const Scene& scene) {
  Framing f = pickCamera(options, scene);
  double a = f.aspect.value_or(1.0f);
  // The derived side in double, checked before it becomes an integer (an extreme aspect ratio would overflow).
  auto derivedSide = [&](double side) {
    side = std::max(1.0, std::round(side));
    if (!(side <= kMaxImageSide))
      throw Error("the camera's aspect ratio " + std::to_string(a) + " gives an image side of " + std::to_string(side) +
                  " pixels, over " + std::to_string(kMaxImageSide) + ": set both --width and --height");
    return static_cast<uint32_t>(side);
  };
  if (options.width && options.height) {
    f.width = *options.width, f.height = *options.height;
  } else if (options.height) {
    f.height = *options.height, f.width = derivedSide(f.height * a);
  } else {
    f.width = options.width.value_or(kDefaultImageWidth), f.height = derivedSide(f.width / a);
  }
  if (!options.lookFrom && scene.cameras.empty()) {
    const FramedBounds framed = framingBounds(scene);
    f.camera = autoCamera(framed.bounds, float(f.width) / float(f.height));
    if (framed.groundLeftOut) f.camera.name = "auto (framing the scene without its flat ground)";
  }
  // Ray origins within 10x the coordinate range keep the traversal's slab distances and triangle products finite
  // (an automatic camera for a scene at the range's edge, or at an extreme aspect ratio, could sit further out).
  if (!glm::all(glm::lessThanEqual(glm::abs(f.camera.position), glm::vec3(10.0f * gpu::kMaxSceneCoordinate))))
    throw Error("the camera would sit beyond +-" + formatNumber(10.0 * gpu::kMaxSceneCoordinate) +
                ", where float ray tests overflow: place it with --look-from");
  return f;
}

// What the renderer is asked for, but the device's choices (resolveDeviceChoices).
RenderSettings renderSettings(const RenderOptions& options, const Scene& scene, const BvhStats& bvh, const Framing& f) {
  RenderSettings settings;
  settings.width = f.width;
  settings.height = f.height;
  settings.spp = options.spp;
  // A time budget without --spp leaves the count open (kMaxSpp); ZSobol's Morton index bounds it by the image.
  if (options.timeBudget > 0.0 && options.spp == kMaxSpp && options.estimator.sampler == Sampler::ZSobol)
    if (uint32_t most = zsobolMaxSpp(f.width, f.height, options.estimator.replicates); most > 0)
      settings.spp = std::min(settings.spp, most);
  settings.estimator = options.estimator;
  // The independent sampler's samples do not depend on the replicates (sampler.h streamKey); they only group its
  // samples for the reliability figure, which needs two groups.
  if (settings.estimator.sampler == Sampler::Independent)
    settings.estimator.replicates = std::max(2u, settings.estimator.replicates);
  settings.features = pipelineFeatures(scanFeatures(scene), bvh, options.specialize);
  if (options.withoutTextures)  // anisotropy too: its direction is read with the texture coordinates' tangents
    settings.features.textures = settings.features.normalMaps = settings.features.alpha = settings.features.anisotropy = false;
  settings.seed = options.seed;
  settings.background = options.background.value_or(glm::vec3(0.0f));
  const AddedLight added = addedLight(options, scene);
  if (added == AddedLight::Studio || added == AddedLight::White) settings.backdrop = kDefaultBackdrop;
  settings.filter = options.filter;
  settings.camera = makeCameraRig(f.camera, f.width, f.height);
  settings.progress = options.progress;
  settings.timeBudget = options.timeBudget;
  settings.sampleRuns = options.adaptive || options.targetError > 0.0;
  return settings;
}

// auto (the integrator, workgroup and wavefront sizes) becomes the device's choice here, so the report and a
// checkpoint name what ran: a resume continues with its checkpoint's, and BSDF splitting keeps the wavefront (it
// needs the path pool). Returns the options with those choices made.
RenderOptions resolveDeviceChoices(vk::Context& ctx, const RenderOptions& options, const RunControl& run,
                                   RenderSettings& settings, RenderOutcome& out) {
  RenderOptions resolved = options;
  if (run.resumeConfig) {
    const RenderOptions was = renderOptionsFromJson(run.resumeConfig->at("options"));  // each value type-checked
    if (resolved.integrator == Integrator::Auto) resolved.integrator = was.integrator;
    if (resolved.workgroupSize == 0) resolved.workgroupSize = was.workgroupSize;
    if (resolved.wavefrontPaths == 0) resolved.wavefrontPaths = was.wavefrontPaths;
  }
  const DeviceTuning tuning = deviceTuning(ctx.deviceType(), ctx.subgroupSize());
  if (resolved.integrator == Integrator::Auto)
    resolved.integrator = options.estimator.splitsPaths() ? Integrator::Wavefront : tuning.integrator;
  if (resolved.workgroupSize == 0) resolved.workgroupSize = tuning.workgroupSize;
  if (resolved.wavefrontPaths == 0) resolved.wavefrontPaths = tuning.wavefrontPaths;
  settings.integrator = resolved.integrator;
  settings.workgroupSize = resolved.workgroupSize;
  settings.maxPathsPerPass = resolved.wavefrontPaths;
  settings.prespecializedSpirv = options.prespecializedSpirv;
  settings.stageTimes = options.stageTimes.value_or(tuning.stageTimes);
  out.spirvVariant = planKernels(settings).spirvVariant;
  out.integrator = resolved.integrator;
  RenderOutcome::Tuning& t = out.tuning;
  t.subgroupSize = ctx.subgroupSize();
  t.workgroupSize = resolved.workgroupSize;
  t.wavefrontPaths = resolved.wavefrontPaths;
  t.integratorAuto = options.integrator == Integrator::Auto;
  t.workgroupAuto = options.workgroupSize == 0;
  t.wavefrontAuto = options.wavefrontPaths == 0;
  t.stageTimes = settings.stageTimes;
  t.stageTimesAuto = !options.stageTimes.has_value();
  t.cpuVectorBits = ctx.cpuVectorBits();
  t.cpuVectorAuto = t.cpuVectorBits > 0 && vk::prepareLavapipeEnvironment().vectorChosen;
  return resolved;
}

// What a render learned before its passes (efficiency roulette's pilot), kept in its checkpoint.
struct LearnedBeforePasses {
  std::optional<RouletteTable> roulette;
  double pilotSeconds = 0.0;
  double choiceSeconds = 0.0;  // --estimator auto's pilots
};

// A new render's empty state, or the checkpoint's after checking that it is this render's.
RenderState startOrResume(const RunControl& run, const std::string& fingerprint, const Framing& f, RenderOutcome& out,
                          LearnedBeforePasses& learned) {
  RenderState state;
  if (!run.resumeConfig) return state;
  checkResumable(*run.resumeConfig, out.checkpointConfig.at("options"), fingerprint);
  state = std::move(*run.resumeState);
  if (state.film.width != f.width || state.film.height != f.height)
    throw Error("the checkpoint's film is " + std::to_string(state.film.width) + "x" + std::to_string(state.film.height) +
                ", the render is " + std::to_string(f.width) + "x" + std::to_string(f.height));
  out.resumed = true;
  if (run.resumeConfig->at("device") != out.device)
    out.warnings.push_back("resumed on '" + out.device + "', the checkpoint was written on '" +
                           run.resumeConfig->at("device").get<std::string>() +
                           "': the image stays unbiased, but is not bit-identical to an uninterrupted render");
  if (run.resumeConfig->contains("roulette")) {
    learned.roulette = rouletteFromJson(run.resumeConfig->at("roulette"));
    learned.pilotSeconds = run.resumeConfig->at("pilot_seconds");
  }
  return state;
}

// Efficiency roulette's pilot. Its time is part of the estimator's cost and counts as render time. Under mpirun
// rank 0 runs it and tells the others, so every rank renders with the same scales.
void runEfficiencyPilot(vk::Context& ctx, const GpuScene& gpuScene, const RenderSettings& settings, RenderOutcome& out,
                        LearnedBeforePasses& learned) {
  const RankGroup& group = RankGroup::world();
  std::string shared;
  if (group.isRoot()) {
    RoulettePilot pilot = runRoulettePilot(ctx, gpuScene, settings);
    out.setup.pipelines += pilot.pipelineSeconds;
    learned.roulette = pilot.table;
    learned.pilotSeconds = pilot.seconds;
    shared = nlohmann::json{{"roulette", rouletteJson(*learned.roulette)}, {"pilot_seconds", learned.pilotSeconds}}.dump();
  }
  group.broadcast(shared);
  if (!group.isRoot()) {
    nlohmann::json j = nlohmann::json::parse(shared);
    learned.roulette = rouletteFromJson(j.at("roulette"));
    learned.pilotSeconds = j.at("pilot_seconds");
  }
}

// The pilot's seconds come out of a time budget; a pilot that took most of it is worth a warning.
void chargePilotToBudget(const RenderOptions& options, const RenderState& state, const LearnedBeforePasses& learned,
                         RenderSettings& settings, RenderOutcome& out) {
  if (options.timeBudget <= 0.0) return;
  settings.timeBudget = std::max(1e-3, options.timeBudget - learned.pilotSeconds - learned.choiceSeconds - state.stats.seconds);
  if (learned.pilotSeconds > 0.5 * options.timeBudget) {
    char line[256];
    std::snprintf(line, sizeof(line),
                  "efficiency roulette's pilot took %.3g s of the %.3g s time budget, so few samples were left to the "
                  "render: give a longer budget, or --rr throughput",
                  learned.pilotSeconds, options.timeBudget);
    out.warnings.push_back(line);
  }
}

// A pilot's counters and GPU time into the render's (its wall time is the choice's, added to the render's seconds).
void addPilotStats(RenderStats& to, const RenderStats& s) {
  to.cameraRays += s.cameraRays, to.extensionRays += s.extensionRays, to.shadowRays += s.shadowRays;
  to.primaryRays += s.primaryRays, to.gpuSeconds += s.gpuSeconds, to.passes += s.passes;
  to.maxBounces = std::max(to.maxBounces, s.maxBounces);
  to.nonfiniteEmission += s.nonfiniteEmission, to.nonfiniteLightSamples += s.nonfiniteLightSamples;
  to.nonfiniteThroughput += s.nonfiniteThroughput, to.traversalsCut += s.traversalsCut;
  to.deepWalks += s.deepWalks, to.deepWalksTraced += s.deepWalksTraced, to.splitsRefused += s.splitsRefused;
  for (const auto& [stage, seconds] : s.stageSeconds) to.stageSeconds[stage] += seconds;
  to.stagesUntimed |= s.stagesUntimed;
}

// Where auto is the default, why this render keeps the fixed defaults (empty: auto runs). What --estimator auto
// refuses with an error (validateOptions) is said here instead, and so is a render too short to choose in.
std::string whyFixedEstimator(const vk::Context& ctx, const RenderOptions& o, const RunControl& run,
                              const RenderSettings& settings) {
  if (!o.estimatorAutoWherePossible || o.estimatorAuto) return "";
  if (o.estimator.rr == RouletteMode::Ears) return "rr ears runs passes of its own";
  if (o.estimator.sampler == Sampler::ZSobol) return "zsobol's index bounds a pixel's samples";
  if (o.estimator.sampler != Sampler::Independent && o.estimator.replicates < 2) return "one replicate measures no variance";
  if (!run.checkpointPath.empty() || run.resumeState) return "a checkpoint records one estimator";
  if (RankGroup::world().distributed()) return "under mpirun each rank would choose on its own";
  if (o.timeBudget > 0.0 && o.timeBudget < kChoiceMinBudgetSeconds)
    return "a time budget under " + formatNumber(kChoiceMinBudgetSeconds) + " s is too short to choose in";
  if (uint64_t(settings.width) * settings.height < kChoiceMinPilotPixels)
    return "the image is too small for its pilots (fewer than " + std::to_string(kChoiceMinPilotPixels) + " pixels)";
  // Under a budget without a sample cap, the share of its seconds decides what fits (cut_short).
  if (o.timeBudget > 0.0 && settings.spp == kMaxSpp) return "";
  const double spp = settings.spp == kMaxSpp ? double(kChoiceNominalSpp) : double(settings.spp);
  const uint32_t candidates =
      pilotsPlanned(estimatorSearchSteps(o.pinnedKeys, SearchScene{settings.features.lights(), ctx.hasFloatAtomics(),
                                                                   settings.features.glossy, settings.features.emitters()}));
  if (!renderFitsPilots(spp * settings.width * settings.height, candidates))
    return "the render is too small for its pilots (" + std::to_string(candidates) + " pilots of " +
           std::to_string(kChoiceMinPilotPixels) + " pixels at " + std::to_string(kChoiceMinPilotSpp) + " samples, in " +
           formatNumber(100.0 * kChoiceMaxShare) + "% of its samples)";
  return "";
}

// --estimator auto: the pilots choose, and are the render's first rounds (`earlier`); the render then runs the
// chosen configuration, its integrator the wavefront where it splits. The pilots' counters join the render's.
void chooseEstimatorFor(vk::Context& ctx, const GpuScene& gpuScene, const RenderOptions& options, RenderSettings& settings,
                        RenderOutcome& out, LearnedBeforePasses& learned, RenderState& state,
                        std::optional<EarlierRounds>& earlier) {
  if (!options.estimatorAuto && !(options.estimatorAutoWherePossible && out.choiceLeftOut.empty())) return;
  checkDeviceLimits(settings, ctx.properties().limits);  // before the pilots' films: an image too large is said so
  earlier.emplace(EarlierRounds{RoundFilm(settings.width, settings.height, settings.estimator.replicates,
                                          settings.estimator.sampler != Sampler::Independent)});
  // A megakernel the user named has no path pool: BSDF splitting is not offered (it would need the wavefront).
  std::set<std::string> pinned = options.pinnedKeys;
  if (options.integrator == Integrator::Megakernel) pinned.insert("bsdf_samples");
  const ChoiceBounds bounds{options.timeBudget, !options.estimatorAuto, options.timeBudget <= 0.0 && options.targetError <= 0.0};
  out.choice = chooseEstimator(ctx, gpuScene, settings, pinned, bounds, earlier->film);
  earlier->spp = out.choice->pixelSamples / (double(settings.width) * settings.height);
  // Without a time budget the pilots' samples count toward --spp (on average over the pixels); rounds count them
  // themselves (EarlierRounds::spp).
  if (options.timeBudget <= 0.0 && !settings.sampleRuns)
    settings.spp =
        std::max(settings.estimator.replicates, settings.spp - std::min(settings.spp, uint32_t(std::lround(earlier->spp))));
  out.setup.pipelines += out.choice->pipelineSeconds;
  settings.estimator = out.choice->chosen;
  learned.choiceSeconds = out.choice->seconds;
  learned.roulette = out.choice->roulette;
  if (settings.estimator.splitsPaths() && settings.integrator != Integrator::Wavefront)
    settings.integrator = out.integrator = Integrator::Wavefront;
  for (const RenderStats& s : out.choice->stats) addPilotStats(state.stats, s);
}

// Periodic checkpoints (rank 0's). One that cannot be written (a full disk) leaves the last one intact and the
// render going.
RenderControl renderControl(const RunControl& run, RenderOutcome& out) {
  RenderControl control;
  control.stop = run.stop;
  if (run.checkpointPath.empty() || !RankGroup::world().isRoot()) return control;
  control.checkpointEvery = run.checkpointEvery;
  control.checkpoint = [&run, &out, lastEnd = Clock::now(), lastWrite = 0.0, warned = false](const RenderState& now) mutable {
    if (run.checkpointShare > 0.0 && since(lastEnd) * run.checkpointShare < lastWrite) return;
    auto t = Clock::now();
    try {
      writeCheckpoint(run.checkpointPath, encodeCheckpoint({out.checkpointConfig, now}));
      ++out.checkpointsWritten;
      lastWrite = since(t);
      lastEnd = Clock::now();
      out.checkpointSeconds += lastWrite;
      if (run.afterCheckpoint) run.afterCheckpoint();
    } catch (const std::exception& e) {  // vkmc::Error, or bad_alloc for a large film: the render goes on
      if (warned) return;                // said once: a full disk stays full
      warned = true;
      std::fprintf(stderr, "vkmc: warning: %s (the render goes on; the last checkpoint is kept; later failures unsaid)\n",
                   e.what());
      out.warnings.push_back(std::string(e.what()) + " (the render went on)");
    }
  };
  return control;
}

// --estimator auto without rounds of its own: the chosen configuration renders the rest as a plain render (full
// passes, no sample runs), which joins the pilots' rounds as the last round, each pixel's weight what they left.
void renderAfterPilots(PathRenderer& renderer, RenderState& state, const RenderControl& control, EarlierRounds& earlier) {
  renderer.render(state, control);
  const Film rest = state.image();
  std::vector<double> weight(rest.pixels());
  for (size_t p = 0; p < rest.pixels(); ++p) {
    // A pixel whose every replicate has a sample takes the weight the pilots left; one the rest did not reach in
    // every replicate (a budget that ended inside the first pass) keeps the pilots' alone, normalized (a replicate
    // without samples would add 0 at the round's full weight).
    bool everyReplicate = true;
    for (uint32_t r = 0; r < rest.replicates; ++r) everyReplicate &= rest.replicateCount[p * gpu::kMaxSampleReplicates + r] > 0;
    weight[p] = everyReplicate ? roundWeight(earlier.film.weightSoFar(p), double(rest.count[p]), 0.0, true) : 0.0;
  }
  earlier.film.addRound(rest, weight);
  state.film = earlier.film.image();
  state.batch.clear(), state.batchSamples = 0;
  state.stats.samplesPerPixel += uint32_t(std::lround(earlier.spp));
}

// The sample passes: in this process, or in batches across the ranks of mpirun.
void renderPasses(PathRenderer& renderer, RenderState& state, const RenderControl& control, const RenderOptions& options,
                  const RenderSettings& settings, RenderOutcome& out, std::optional<EarlierRounds>& earlier) {
  const RankGroup& group = RankGroup::world();
  if (settings.sampleRuns) {
    if (group.distributed()) throw Error("--adaptive on, --target-error and --estimator auto do not run under mpirun yet");
    out.rounds = renderSampleRounds(
        renderer, state, control, settings,
        SampleRoundsPlan{options.adaptive, options.targetError, settings.spp, settings.timeBudget, renderer.samplesPerPass()},
        earlier ? &*earlier : nullptr);
    return;
  }
  if (group.distributed() && earlier)
    throw Error("--adaptive on, --target-error and --estimator auto do not run under mpirun yet");
  if (earlier) return renderAfterPilots(renderer, state, control, *earlier);
  if (!group.distributed()) return renderer.render(state, control);
  DistributedPlan plan;
  plan.spp = settings.spp;
  plan.timeBudget = settings.timeBudget;
  plan.refreshPixelEstimate = settings.estimator.shadowRrThreshold > 0.0f;
  plan.device = out.device;
  plan.width = settings.width, plan.height = settings.height;
  plan.replicateVariance = settings.estimator.sampler != Sampler::Independent;
  plan.replicates = settings.estimator.replicates;
  out.ranks = renderDistributed(renderer, group, state, control, plan);
}

RenderOutcome renderScene(vk::Context& ctx, const RenderOptions& options, Scene scene, const RunControl& run) {
  std::optional<ExrImage> reference;
  if (!options.referencePath.empty()) {
    reference = readExr(options.referencePath);
    requireFinite(*reference, ("reference '" + options.referencePath + "'").c_str());
  }
  RenderOutcome out;
  out.device = ctx.deviceName();
  out.degenerateTriangles = scene.degenerateTriangles;
  out.warnings = scene.warnings;
  if (std::optional<std::string> w = coordinatePrecisionWarning(scene)) out.warnings.push_back(*w);
  const Framing framing = frameScene(options, scene);
  if (reference && (uint32_t(reference->width) != framing.width || uint32_t(reference->height) != framing.height))
    throw Error("reference '" + options.referencePath + "' is " + std::to_string(reference->width) + "x" +
                std::to_string(reference->height) + ", the render is " + std::to_string(framing.width) + "x" +
                std::to_string(framing.height));
  out.cameraName = framing.camera.name, out.width = framing.width, out.height = framing.height;
  auto t = Clock::now();
  out.seenThroughTriangles = removeSeenThroughFaces(scene, framing.camera, framing.width, framing.height).triangles;
  out.setup.seenThrough = since(t);
  addThinRibbons(scene, framing.camera, framing.height);  // points and lines, one pixel wide for this camera and image
  // The map's texels are one storage buffer of vec4s (GpuScene): the device's range bounds them.
  addEnvironmentLight(options, scene, out, ctx.properties().limits.maxStorageBufferRange / sizeof(glm::vec4));
  t = Clock::now();
  Bvh bvh = buildBvh(scene.triangleBounds());
  out.setup.bvh = since(t);
  out.bvh = bvh.stats;
  t = Clock::now();
  GpuScene gpuScene(ctx, scene, bvh, options.estimator.lightSelect == LightSelect::Uniform);
  out.setup.upload = since(t);
  out.sceneInfo = gpuScene.info();
  RenderSettings settings = renderSettings(options, scene, bvh.stats, framing);
  out.features = settings.features, out.background = settings.background, out.backdrop = settings.backdrop;
  // What a checkpoint of this render records; a resumed render's must match it, and its learned state (the
  // efficiency pilot's scales) is used instead of a new pilot.
  const RenderOptions resolved = resolveDeviceChoices(ctx, options, run, settings, out);
  const ContentHash fingerprint = renderFingerprint(scene, settings);
  out.checkpointConfig = {{"options", renderOptionsJson(resolved)},
                          {"scene_fingerprint", fingerprint.hex()},
                          {"device", out.device},
                          {"outputs", run.outputs}};
  LearnedBeforePasses learned;
  out.choiceLeftOut = whyFixedEstimator(ctx, options, run, settings);
  if ((settings.sampleRuns || options.estimatorAuto) && (!run.checkpointPath.empty() || run.resumeState))
    throw Error("--adaptive on, --target-error and --estimator auto do not write or resume checkpoints yet");
  RenderState state = startOrResume(run, fingerprint.hex(), framing, out, learned);
  if (state.nextSample > settings.spp)
    throw Error("the checkpoint claims " + std::to_string(state.nextSample) + " samples a pixel of a " +
                std::to_string(settings.spp) + "-spp render");
  std::optional<EarlierRounds> earlier;
  chooseEstimatorFor(ctx, gpuScene, options, settings, out, learned, state, earlier);
  if (settings.estimator.rr == RouletteMode::Efficiency && !learned.roulette)
    runEfficiencyPilot(ctx, gpuScene, settings, out, learned);
  if (learned.roulette)
    out.checkpointConfig["roulette"] = rouletteJson(*learned.roulette),
    out.checkpointConfig["pilot_seconds"] = learned.pilotSeconds;
  chargePilotToBudget(options, state, learned, settings, out);
  PathRenderer renderer(ctx, gpuScene, settings);
  if (learned.roulette) renderer.setRouletteScales(learned.roulette->scale);
  out.setup.pipelines += renderer.pipelineSeconds();
  out.tuning.pathsPerPass = renderer.pathsPerPass();
  out.tuning.pathSlots = renderer.pathSlots();
  renderPasses(renderer, state, renderControl(run, out), options, settings, out, earlier);
  out.interrupted = state.interrupted;
  out.stopSignal = state.stopSignal;
  out.film = state.image();
  out.stats = state.stats;
  out.finalState = std::move(state);
  out.stats.seconds += learned.pilotSeconds + learned.choiceSeconds;
  out.pilotSeconds = learned.pilotSeconds;
  out.estimator = settings.estimator;
  out.roulette = learned.roulette;
  if (renderer.ears().enabled()) out.ears = renderer.ears().summary();
  out.earsGuard = renderer.earsGuard();
  if (run.inspect) run.inspect(renderer);
  if (reference) out.error = compareImages(filmToImage(out.film), *reference);
  return out;
}
}  // namespace

RenderOutcome runRender(vk::Context& ctx, const RenderOptions& options, const RunControl& run) {
  validateOptions(options);
  auto t = Clock::now();
  Scene scene = loadGltf(options.scenePath, deviceLoadLimits(ctx));
  double load = since(t);
  RenderOutcome out = renderScene(ctx, options, std::move(scene), run);
  out.setup.load = load;
  return out;
}

RenderOutcome runRender(vk::Context& ctx, const RenderOptions& options, Scene scene, const RunControl& run) {
  validateOptions(options);
  return renderScene(ctx, options, std::move(scene), run);
}

std::string encodeRenderCheckpoint(const RenderOutcome& outcome) {
  return encodeCheckpoint({outcome.checkpointConfig, outcome.finalState});
}

namespace {
using nlohmann::json;

json finiteOrNull(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

// The rays, the time and the samples: what the render did.
void addRunFields(json& j, const RenderOutcome& r) {
  const RenderStats& s = r.stats;
  j["spp"] = s.samplesPerPixel;  // reached; equals the request unless a time budget ended the render
  j["spp_reached"] = s.samplesPerPixel;
  j["seconds"] = s.seconds;
  j["setup_seconds"] = r.setup.total();
  j["setup"] = {{"load", r.setup.load},
                {"seen_through", r.setup.seenThrough},
                {"bvh", r.setup.bvh},
                {"upload", r.setup.upload},
                {"pipelines", r.setup.pipelines}};
  j["gpu_seconds"] = s.gpuSeconds;
  // null where any part of the render (a resumed one's earlier part, another rank) ran without stage timestamps
  // (--stage-times off, the default on lavapipe: device_tuning.h)
  j["stage_gpu_seconds"] = s.stagesUntimed ? json(nullptr) : json(s.stageSeconds);
  j["rays"] = s.rays();
  j["ray_counts"] = {{"camera", s.cameraRays},
                     {"extension", s.extensionRays},
                     {"shadow", s.shadowRays},
                     {"deep_walks", s.deepWalks},  // rays whose walk outgrew the register stack (deep pass)
                     // vertices whose split (BSDF splitting, EARS) found the path pool full and went on whole
                     {"splits_refused", s.splitsRefused}};
  j["mrays_per_second"] = s.seconds > 0.0 ? static_cast<double>(s.rays()) / s.seconds * 1e-6 : 0.0;
  j["nonfinite_samples"] = r.film.totalNonfinite();
  j["nonfinite_by_stage"] = {{"shade_emission", s.nonfiniteEmission},
                             {"shade_light_samples", s.nonfiniteLightSamples},
                             {"shade_continuation", s.nonfiniteThroughput},
                             {"traversal_cut_by_loop_limit", s.traversalsCut},
                             {"accumulate_excluded_samples", r.film.totalNonfinite()}};
  // Finite samples too bright for float squares (a channel >= 2^56): counted apart, and kept (scaled sums).
  j["high_range_samples"] = r.film.totalHighRange();
  j["samples"] = r.film.totalSamples();
  j["max_bounces"] = s.maxBounces;
}

json deviceTuningJson(const RenderOutcome::Tuning& t) {
  return {{"subgroup_size", t.subgroupSize},
          {"workgroup_size", t.workgroupSize},
          {"wavefront_paths", t.wavefrontPaths},
          {"paths_per_pass", t.pathsPerPass},
          {"path_slots", t.pathSlots},
          {"stage_times", t.stageTimes},
          {"cpu_vector_bits", t.cpuVectorBits > 0 ? json(t.cpuVectorBits) : json(nullptr)},
          {"malloc_tunables", mallocTunablesAdded().empty() ? json(nullptr) : json(mallocTunablesAdded())},
          {"chosen_by_device",
           {{"integrator", t.integratorAuto},
            {"workgroup", t.workgroupAuto},
            {"wavefront", t.wavefrontAuto},
            {"stage_times", t.stageTimesAuto},
            {"cpu_vector", t.cpuVectorAuto}}}};
}

// The EARS guard's comparison (or that it had no budget for one); null where it did neither.
json earsGuardJson(const EarsGuardOutcome& g) {
  auto pass = [](const PolicyPass& p) {
    return json{{"samples_measured", p.samples},
                {"relative_variance_per_sample", p.relativeVariance},
                {"seconds_per_sample", p.secondsPerSample},
                {"efficiency", finiteOrNull(p.efficiency())}};
  };
  json j = {
      {"rest_rendered_by", g.fellBack ? "throughput" : "ears"},       {"from_sample", g.fromSample},
      {"pass_overhead_seconds", finiteOrNull(g.passOverhead)},        {"decided_at_seconds", finiteOrNull(g.decidedAtSeconds)},
      {"learning_cost_seconds", finiteOrNull(g.learningCostSeconds)}, {"out_of_budget", !g.compared}};
  if (!g.compared) return g.outOfBudget ? j : json(nullptr);
  j["ears"] = pass(g.ears);
  j["throughput"] = pass(g.throughput);
  j["ears_first_look"] = g.secondLook ? pass(g.firstEars) : json(nullptr);
  j["watched"] = g.watched;
  j["watched_ears"] = g.watched && g.watchedEars.samples > 0 ? pass(g.watchedEars) : json(nullptr);
  j["switched_later"] = g.switchedLater;
  j["switched_at"] = g.switchedLater ? json(g.switchedAt) : json(nullptr);
  return j;
}

// What the estimator learned before or during the passes: efficiency roulette's scales, EARS's cache and guard.
void addLearnedFields(json& j, const RenderOutcome& r) {
  if (r.roulette) {
    json scales = json::array();
    for (float k : r.roulette->scale) scales.push_back(std::isfinite(k) ? json(k) : json("none"));
    j["efficiency_roulette"] = {
        {"pilot_seconds", r.pilotSeconds},
        {"scale_per_depth", scales},
        {"formula", "survival = min(scale[depth] * max(throughput), " + formatNumber(gpu::kRouletteMaxSurvival) + ")"}};
  }
  if (!r.ears) return;
  j["ears"] = earsJson(*r.ears);
  if (json guard = earsGuardJson(r.earsGuard); !guard.is_null()) j["ears"]["guard"] = guard;
}

json ratioInterval(double value, double logSe) {
  return json::array({value / std::exp(1.96 * logSe), value * std::exp(1.96 * logSe)});
}

// The winner against the start on fresh pilots: what it measured, and whether it held.
json confirmationJson(const EstimatorChoice& c) {
  const Confirmation& k = c.confirmation;
  if (!k.ran) {
    const char* why = c.cutShort ? "no challenger fitted the pilots' share of the render's time"
                      : c.candidates.front().chosen
                          ? "the start won the search"
                          : "the pilots' share of the render's time fitted no more: the winner renders unconfirmed";
    return {{"ran", false}, {"why", why}};
  }
  const Comparison& vs = k.vsStart;
  const double ratio = vs.measured ? std::exp(vs.logRatio) : 0.0;
  return {{"ran", true},
          {"candidate", k.candidate},
          {"confirmed", k.confirmed},
          {"vs_start", ratio},
          {"vs_start_95", ratioInterval(ratio, vs.se)},
          {"pilot_pixels", k.shape.pixels},
          {"pilot_spp", k.shape.spp},
          {"start_efficiency", k.start.efficiency()},
          {"winner_efficiency", k.winner.efficiency()}};
}

// --estimator auto: every candidate's measurement (efficiency with a 95% interval, relative to the start's), the
// choice, its confirmation, and what choosing cost.
json choiceJson(const EstimatorChoice& c) {
  json candidates = json::array();
  const CandidateReading& start = c.candidates.front().reading;
  for (const MeasuredCandidate& m : c.candidates) {
    const CandidateReading& r = m.reading;
    const Comparison vsStart = compare(r, start);
    const double ratio = vsStart.measured ? std::exp(vsStart.logRatio) : 0.0;
    candidates.push_back({{"candidate", m.label},
                          {"chosen", m.chosen},
                          {"too_costly_for_sample_count", m.tooCostly},
                          {"seconds", m.seconds},
                          {"rel_variance_per_sample", r.relVariance},
                          {"rel_variance_standard_error", r.relVarianceSe},
                          {"stage_scale", r.stageScale},
                          {"cost_per_sample", r.cost},
                          {"efficiency", r.efficiency()},
                          {"efficiency_95", ratioInterval(r.efficiency(), r.relativeSe())},
                          {"vs_start", ratio},
                          {"vs_start_95", ratioInterval(ratio, vsStart.se)}});
  }
  return {{"chosen", c.chosen.toJson()},
          {"candidates", candidates},
          {"cost_unit", "GPU seconds"},
          {"cut_short", c.cutShort},
          {"skipped_for_budget", c.skippedForBudget},
          {"roulette_predicted_gain", c.roulettePrediction ? json(*c.roulettePrediction) : json(nullptr)},
          {"skipped_by_prediction", c.skippedByPrediction},
          {"confirmation", confirmationJson(c)},
          {"pilot_pixel_samples", c.pixelSamples},
          {"pilot_pixels", c.pilotPixels},
          {"pass_pixels", c.passPixels},
          {"pilot_spp", c.pilotSpp},
          {"seconds", c.seconds},
          {"pipeline_seconds", c.pipelineSeconds},
          {"share_of_samples", c.share},
          {"margin", kChoiceMargin},
          {"max_cost_at_sample_count", c.costCapped ? json(kChoiceMaxCostAtSampleCount) : json(nullptr)},
          {"note",
           "the pilots are the render's first rounds, weighted per pixel by weights fixed before their samples were "
           "seen (round_film.h): unbiased whichever configuration they chose"}};
}

std::string confirmationNote(const EstimatorChoice& c) {
  const Confirmation& k = c.confirmation;
  if (!k.ran) return c.candidates.front().chosen ? "" : "; unconfirmed (the pilots' share fitted no more)";
  const Comparison& vs = k.vsStart;
  const std::string ratio = vs.measured ? formatNumber(std::round(100.0 * std::exp(vs.logRatio)) / 100.0) + "x" : "unmeasured";
  return k.confirmed ? "; confirmed on fresh pilots (" + ratio + ")"
                     : "; " + k.candidate + " won the search but not on fresh pilots (" + ratio + "), so the start renders";
}

std::string choiceLine(const EstimatorChoice& c) {
  // What the choice changed from the start, key by key.
  const json start = c.candidates.front().config.toJson(), chosen = c.chosen.toJson();
  std::string changed;
  for (const auto& [key, value] : chosen.items())
    if (key != "name" && key != "replicates" && start.value(key, json()) != value)
      changed += (changed.empty() ? "" : ", ") + key + "=" + (value.is_string() ? value.get<std::string>() : value.dump());
  double startEfficiency = c.candidates.front().reading.efficiency(), chosenEfficiency = startEfficiency;
  std::string tooCostly;
  for (const MeasuredCandidate& m : c.candidates) {
    if (m.chosen) chosenEfficiency = m.reading.efficiency();
    if (m.tooCostly)
      tooCostly += "; " + m.label + " measured more efficient but costs " +
                   formatNumber(std::round(100.0 * m.reading.cost / c.candidates.front().reading.cost) / 100.0) +
                   "x the start a sample, over the " + formatNumber(kChoiceMaxCostAtSampleCount) +
                   "x a render of a sample count allows";
  }
  char buf[512];
  std::snprintf(buf, sizeof(buf),
                "choice      %s, of %zu candidates%s (%.2fx the start's measured efficiency); pilots %.3f s, %.1f%% of "
                "the samples (in the image); their kernels %.3f s",
                changed.empty() ? "the defaults" : changed.c_str(), c.candidates.size(),
                c.skippedForBudget.empty() ? "" : " (the pilots' share of the render's time fitted no more)",
                startEfficiency > 0.0 ? chosenEfficiency / startEfficiency : 0.0, c.seconds, 100.0 * c.share, c.pipelineSeconds);
  return buf + tooCostly + confirmationNote(c) + "\n";
}

json mpiJson(const std::vector<RankReport>& ranks) {
  json perRank = json::array();
  for (const RankReport& k : ranks)
    perRank.push_back({{"rank", k.rank},
                       {"host", k.host},
                       {"device", k.device},
                       {"rays", k.rays},
                       {"batches", k.batches},
                       {"busy_seconds", k.busySeconds},
                       {"gpu_seconds", k.gpuSeconds}});
  return {{"ranks", ranks.size()}, {"per_rank", perRank}};
}

// The variance, the efficiency it gives, and whether to trust it; the error against a reference.
void addErrorFields(json& j, const RenderOptions& o, const RenderOutcome& r) {
  const RenderStats& s = r.stats;
  // null where no variance is estimated (one scrambling a pixel: Film::estimatesVariance), never a made-up 0.
  const bool estimated = r.film.estimatesVariance();
  const glm::dvec3 var = r.film.imageMeanVarianceOfMean();
  j["mean_variance"] = estimated ? json{var.x, var.y, var.z} : json(nullptr);
  // Without a reference: relative variance (per-pixel variance of the mean over mean^2 + epsilon, averaged
  // over pixels and channels) is the expected relMSE of an unbiased render, so it gives an efficiency too.
  const double relVar = r.film.meanRelativeVariance(kRelMseEpsilon);
  auto inverse = [&](double cost) { return relVar > 0.0 && cost > 0.0 ? 1.0 / (relVar * cost) : 0.0; };
  j["mean_relvariance"] = estimated ? json(relVar) : json(nullptr);
  j["estimated_efficiency"] = estimated ? json(inverse(s.seconds)) : json(nullptr);
  // The same efficiency against each cost: wall time, GPU time (kernel timestamps), rays per pixel (a cost that
  // does not depend on the machine's load); and where the variance came from (sampler.h replicates or samples).
  const double raysPerPixel = double(s.rays()) / double(std::max<size_t>(1, r.film.pixels()));
  j["estimated_efficiency_by_cost"] = !estimated ? json(nullptr)
                                                 : json{{"wall_seconds", inverse(s.seconds)},
                                                        {"gpu_seconds", inverse(s.gpuSeconds)},
                                                        {"rays_per_pixel", inverse(raysPerPixel)}};
  j["variance_from"] = !estimated ? "none" : r.film.replicateVariance ? "replicates" : "samples";
  // Whether that variance, and so the efficiency, can be trusted (analysis/variance_reliability.h).
  const VarianceReliability reliability = assessVarianceReliability(r.film);
  j["variance_reliability"] =
      !estimated
          ? json(nullptr)
          : json{{"relative_standard_error",
                  std::isfinite(reliability.relativeStandardError) ? json(reliability.relativeStandardError) : json("unknown")},
                 {"reliable_below", VarianceReliability::kReliableBelow},
                 {"largest_pixel_share", reliability.largestPixelShare},
                 {"pixels_assessed", reliability.pixelsAssessed}};
  j["estimated_efficiency_reliable"] = reliability.reliable();
  if (!r.error) return;
  j["reference"] = o.referencePath;
  j["mse"] = r.error->mse;
  j["relmse"] = r.error->relmse;
  j["efficiency"] = r.error->relmse > 0.0 && s.seconds > 0.0 ? 1.0 / (r.error->relmse * s.seconds) : 0.0;
}

// Rendering in rounds: what adaptive sampling spent where, and the target error's estimate.
void addRoundFields(json& j, const RenderOptions& o, const SampleRoundsOutcome& r) {
  j["sample_rounds"] = {{"adaptive", o.adaptive},
                        {"rounds", r.rounds},
                        {"first_round_spp", r.firstRoundSpp},
                        {"pixel_spp_min", r.minPixelSamples},
                        {"pixel_spp_max", r.maxPixelSamples},
                        {"relmse_estimate", finiteOrNull(r.relMse.value)},
                        {"relmse_upper_95", finiteOrNull(r.relMse.upper)}};
  if (o.targetError > 0.0)
    j["sample_rounds"]["target_error"] = o.targetError, j["sample_rounds"]["target_reached"] = r.targetReached;
}

// The scene as the device holds it: its size, its BVH and the features its kernels were specialized for.
void addSceneFields(json& j, const RenderOptions& o, const RenderOutcome& r) {
  j["scene_info"] = {{"triangles", r.sceneInfo.triangles},
                     {"emissive_triangles", r.sceneInfo.emissiveTriangles},
                     {"materials", r.sceneInfo.materials},
                     {"punctual_lights", r.sceneInfo.punctualLights},
                     {"degenerate_triangles_skipped", r.degenerateTriangles},
                     {"seen_through_triangles_removed", r.seenThroughTriangles}};
  j["bvh"] = {{"inner_nodes", r.bvh.innerNodes},
              {"leaves", r.bvh.leaves},
              {"max_depth", r.bvh.maxDepth},
              {"max_leaf_size", r.bvh.maxLeafSize},
              {"sah_cost", r.bvh.sahCost},
              {"wide_sah_cost", r.bvh.wideSahCost},
              {"wide_max_depth", r.bvh.wideMaxDepth},
              {"wide_max_pending", r.bvh.wideMaxPending},
              {"register_stack_entries", r.features.registerStackEntries},
              {"deep_walk_passes", r.features.deepWalks},
              {"build_seconds", r.bvh.buildSeconds},
              {"build_threads", r.bvh.buildThreads}};
  j["specialized_for"] = {{"emitters", r.features.emitters()},     {"punctual_lights", r.features.punctualLights > 0},
                          {"environment", r.features.environment}, {"glossy", r.features.glossy},
                          {"specialized", o.specialize},           {"prespecialized_spirv", r.spirvVariant}};
}

}  // namespace

nlohmann::json makeReport(const RenderOptions& o, const RenderOutcome& r) {
  json j;
  j["scene"] = o.scenePath;
  j["width"] = r.width;
  j["height"] = r.height;
  if (o.timeBudget == 0.0) j["spp_requested"] = o.spp;
  if (o.timeBudget > 0.0) j["time_budget"] = o.timeBudget;
  j["seed"] = o.seed;
  j["camera"] = r.cameraName;
  const glm::dvec3 mean = r.film.imageMean();
  j["mean"] = {mean.x, mean.y, mean.z};
  j["device"] = r.device;
  j["integrator"] = toString(r.integrator);
  j["device_tuning"] = deviceTuningJson(r.tuning);
  addRunFields(j, r);
  addLearnedFields(j, r);
  addErrorFields(j, o, r);
  if (r.rounds) addRoundFields(j, o, *r.rounds);
  addSceneFields(j, o, r);
  // Checkpoints: a resumed render's counters and seconds include the runs before it (pass time only).
  j["resumed"] = r.resumed;
  j["interrupted"] = r.interrupted;
  j["checkpoints_written"] = r.checkpointsWritten;
  j["checkpoint_seconds"] = r.checkpointSeconds;
  if (!r.ranks.empty()) j["mpi"] = mpiJson(r.ranks);
  const EstimatorConfig& e = r.estimator;
  j["estimator"] = e.toJson();
  j["estimator"]["unbiased"] = e.unbiased();
  if (r.choice) j["estimator_choice"] = choiceJson(*r.choice);
  if (!r.choiceLeftOut.empty()) j["estimator_choice"] = {{"chosen", nullptr}, {"left_out", r.choiceLeftOut}};
  j["estimator"]["bias"] = e.unbiased() ? "none: paths end by Russian roulette only"
                                        : "truncation: paths are cut after " + std::to_string(e.maxDepth) +
                                              " scattering events, so the image is biased low";
  j["background"] = {r.background.x, r.background.y, r.background.z};
  if (r.backdrop > 0.0f) j["backdrop"] = r.backdrop;
  j["filter"] = pixelFilterJson(o.filter);
  j["environment"] = r.environment;
  j["warnings"] = r.warnings;
  return j;
}

std::string summaryText(const RenderOptions& o, const RenderOutcome& r) {
  const RenderStats& s = r.stats;
  glm::dvec3 mean = r.film.imageMean();
  glm::dvec3 var = r.film.imageMeanVarianceOfMean();
  char buf[2048];
  std::snprintf(buf, sizeof(buf), "%.3g %.3g %.3g (image mean of the per-pixel variance of the mean)", var.x, var.y, var.z);
  const std::string varianceText = r.film.estimatesVariance()
                                       ? std::string(buf)
                                       : "not estimated: one scrambling a pixel (--replicates 1) has no unbiased estimate of "
                                         "its variance (--replicates 2 or more gives one)";
  std::snprintf(buf, sizeof(buf),
                "scene       %s (%u triangles, %u emissive)\n"
                "device      %s\n"
                "image       %ux%u, %u spp, camera: %s, filter: %s\n"
                "estimator   %s\n"
                "time        %.3f s render (GPU %.3f s), set-up %.3f s (load %.3f, faces seen through %.3f, BVH %.3f, upload "
                "%.3f, pipelines %.3f)\n"
                "rays        %llu (camera %llu, extension %llu, shadow %llu; %llu deep walks): %.2f Mrays/s\n"
                "mean        %.6g %.6g %.6g\n"
                "variance    %s\n"
                "non-finite  %llu samples excluded (%llu finite samples above 2^56 kept in the scaled sums)\n",
                o.scenePath.c_str(), r.sceneInfo.triangles, r.sceneInfo.emissiveTriangles, r.device.c_str(), r.width, r.height,
                s.samplesPerPixel, r.cameraName.c_str(), pixelFilterSummary(o.filter).c_str(), r.estimator.summary().c_str(),
                s.seconds, s.gpuSeconds, r.setup.total(), r.setup.load, r.setup.seenThrough, r.setup.bvh, r.setup.upload,
                r.setup.pipelines, (unsigned long long)s.rays(), (unsigned long long)s.cameraRays,
                (unsigned long long)s.extensionRays, (unsigned long long)s.shadowRays, (unsigned long long)s.deepWalks,
                s.seconds > 0 ? s.rays() / s.seconds * 1e-6 : 0.0, mean.x, mean.y, mean.z, varianceText.c_str(),
                (unsigned long long)r.film.totalNonfinite(), (unsigned long long)r.film.totalHighRange());
  std::string text = buf;
  if (o.environmentPath.empty() && !o.background && r.environment == kStudioEnvironment)
    text +=
        "world       the studio environment, the file's own lights on top (the file declares no other world; "
        "--background 0,0,0 renders its own lights alone)\n";
  if (s.splitsRefused > 0)
    text += "splits      " + std::to_string(s.splitsRefused) +
            " vertices found the path pool full and went on unsplit (unbiased: q = 1 there; fewer splits than asked)\n";
  if (r.ears) text += earsLine(*r.ears) + earsGuardLine(r.earsGuard);
  if (r.choice) text += choiceLine(*r.choice);
  if (!r.choiceLeftOut.empty()) text += "choice      the defaults, not chosen: " + r.choiceLeftOut + "\n";
  if (r.error)
    text += "error       relMSE " + std::to_string(r.error->relmse) + ", MSE " + std::to_string(r.error->mse) +
            ", efficiency 1/(relMSE x s) " + std::to_string(r.error->relmse > 0 ? 1.0 / (r.error->relmse * s.seconds) : 0.0) +
            "\n";
  const VarianceReliability reliability = assessVarianceReliability(r.film);
  if (!r.film.estimatesVariance()) {
    text +=
        "reliability no variance estimate, so no estimated efficiency (compare against a reference: "
        "--reference)\n";
  } else if (reliability.pixelsAssessed == 0) {
    text += "reliability fewer samples than the " + std::to_string(r.film.replicates) +
            " replicates in every pixel: the variance estimate cannot be assessed, so the estimated efficiency is "
            "unreliable\n";
  } else if (!std::isfinite(reliability.relativeStandardError)) {
    text +=
        "reliability no pixel's samples varied, so nothing measures the variance (a contribution too rare to "
        "have been met?): the estimated efficiency is unreliable\n";
  } else if (!reliability.reliable()) {
    std::snprintf(buf, sizeof(buf),
                  "reliability the variance estimate is uncertain by %.0f%% (one pixel holds %.0f%% of it: heavy tails or "
                  "too few samples), so the estimated efficiency is unreliable\n",
                  100.0 * reliability.relativeStandardError, 100.0 * reliability.largestPixelShare);
    text += buf;
  }
  return text;
}

}  // namespace vkmc
