// One render from options to outputs: load, BVH, upload, pipelines, passes. Shared by the CLI and tests.
#pragma once
#include <functional>
#include <glm/glm.hpp>

#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>

#include "analysis/error_metrics.h"
#include "app/estimator_search.h"
#include "dist/distributed_render.h"
#include "estimators/estimator_config.h"
#include "policy/sample_rounds.h"
#include "render/ears_cache.h"
#include "passes/ears_guard.h"
#include "render/film.h"
#include "render/path_renderer.h"
#include "render/pixel_filter.h"
#include "render/render_state.h"
#include "scene/scene.h"
#include "vk/context.h"

namespace vkmc {

// Defaults of a render's size, used by validation, the command line's help and the report (the limits:
// render_settings.h).
constexpr uint32_t kDefaultImageWidth = 256;
constexpr uint32_t kDefaultSpp = 64;

struct RenderOptions {
  std::string scenePath;
  std::optional<uint32_t> width, height;  // default 256 wide, height from the camera's aspect (else 256)
  uint32_t spp = kDefaultSpp;
  EstimatorConfig estimator;  // includes the depth cap (max_depth)
  uint32_t seed = 1;
  std::optional<uint32_t> cameraIndex;
  std::optional<glm::vec3> lookFrom, lookAt;
  float fovDegrees = 45.0f;
  // Radiance seen by escaped rays. Set, it replaces the file's world (addedLight below); unset, the world lights it.
  std::optional<glm::vec3> background;
  // An environment light (.hdr or .exr, equirectangular, +Y up, the image's centre along -Z), importance sampled
  // and combined with BSDF sampling by MIS; rotated about +Y by environmentRotation degrees, scaled by
  // environmentStrength; or "studio" (scene/studio_environment.h). Unset: the file's world (addedLight below).
  std::string environmentPath;
  float environmentRotation = 0.0f;
  float environmentStrength = 1.0f;
  PixelFilter filter;  // pixel reconstruction filter (--filter, --filter-radius; a study's "filter")
  bool progress = true;
  double timeBudget = 0.0;  // seconds; 0 = render spp samples
  // Rendering in rounds (policy/sample_rounds.h): each pixel's share of a round from its measured relative
  // variance (adaptive), and/or until the estimated relMSE's upper bound reaches targetError (> 0).
  bool adaptive = false;
  double targetError = 0.0;
  // --estimator auto: short pilots on the scene choose every estimator key not in pinnedKeys (the user's flags),
  // starting from `estimator` (app/estimator_search.h).
  bool estimatorAuto = false;
  // The command line's default: auto where it can run, the fixed defaults where it cannot (rr ears, zsobol, one
  // replicate, checkpoints, mpirun, a render too small for its pilots), the report saying which and why.
  bool estimatorAutoWherePossible = false;
  std::set<std::string> pinnedKeys;
  std::string referencePath;        // EXR to compare with: mse, relmse, efficiency in the report
  bool specialize = true;           // false: pipelines with every feature on (for comparison)
  bool prespecializedSpirv = true;  // false: the general SPIR-V even where a pre-specialized variant matches
  bool withoutTextures = false;     // textures, vertex colours and alpha compiled out: their cost, by comparison
  uint32_t workgroupSize = 0;       // invocations per workgroup of every kernel (32, 64, 128, 256); 0: the device's
  uint32_t wavefrontPaths = 0;      // paths in flight per pass at most; 0: the device's (device_tuning.h)
  Integrator integrator = Integrator::Auto;
  // Every stage's GPU time in the report (stage_gpu_seconds); unset: the device's (device_tuning.h). A
  // measurement, not part of the render: a checkpoint does not record it.
  std::optional<bool> stageTimes;
};

// How a render runs, besides what it renders: checkpoints, a stop flag, and the checkpoint it continues.
struct RunControl {
  std::string checkpointPath;      // periodic checkpoints go here ("": none)
  double checkpointEvery = 120.0;  // seconds of rendering between checkpoints
  // > 0: periodic checkpoints are spaced further, so that writing them takes at most this share of the time (the
  // default interval's promise; a film of 2 MP writes ~600 MB).
  double checkpointShare = 0.0;
  nlohmann::json outputs;                        // the outputs' paths, recorded in checkpoints for --resume
  const std::atomic<int>* stop = nullptr;        // raised (a signal number): stop after the pass in flight
  const nlohmann::json* resumeConfig = nullptr;  // a checkpoint's configuration, with...
  RenderState* resumeState = nullptr;            // ...its state, moved into the render
  // Called with the renderer once the render is done, before it is destroyed (tests: the device buffers it holds).
  std::function<void(PathRenderer&)> inspect;
  // Called after each checkpoint is written: a sync point where tests stop a render without racing it.
  std::function<void()> afterCheckpoint;
};

struct SetupTimes {
  double load = 0.0, bvh = 0.0, upload = 0.0, pipelines = 0.0;
  double seenThrough = 0.0;  // finding the single-sided faces the camera looks through (bvh/seen_through_faces.h)
  double total() const { return load + seenThrough + bvh + upload + pipelines; }
};

struct RenderOutcome {
  Film film;
  RenderStats stats;
  SetupTimes setup;
  BvhStats bvh;
  GpuSceneInfo sceneInfo;
  uint64_t degenerateTriangles = 0;
  uint64_t seenThroughTriangles = 0;  // single-sided faces the camera looks through (bvh/seen_through_faces.h)
  std::vector<std::string> warnings;
  std::string cameraName;
  std::string device;
  Integrator integrator = Integrator::Wavefront;  // the one that ran (auto resolved)
  // How the kernels ran on this device: chosen by device_tuning.h where the options said auto.
  struct Tuning {
    uint32_t subgroupSize = 0, workgroupSize = 0, wavefrontPaths = 0;
    uint32_t pathsPerPass = 0, pathSlots = 0;  // the path pool as sized (path_pool.h): camera paths, all slots
    bool stageTimes = false;
    bool integratorAuto = false, workgroupAuto = false, wavefrontAuto = false, stageTimesAuto = false;
    uint32_t cpuVectorBits = 0;  // lavapipe's SIMD width (0 on a GPU); chosen by vkmc or the environment
    bool cpuVectorAuto = false;
  } tuning;
  uint32_t width = 0, height = 0;
  std::optional<ErrorMetrics> error;  // against the reference, when one was given
  double pilotSeconds = 0.0;          // efficiency roulette's pilot, included in stats.seconds
  std::optional<EarsSummary> ears;    // what rr ears learned
  EarsGuardOutcome earsGuard;         // rr ears's guard: compared false where it did not run
  SceneFeatures features;             // what the pipelines were specialized for
  std::string spirvVariant;           // pre-specialized SPIR-V used for shading (KernelPlan::spirvVariant)
  std::optional<RouletteTable> roulette;
  glm::vec3 background{0.0f};  // what escaped rays saw besides the environment light
  float backdrop = 0.0f;       // the grey escaped camera rays saw instead (the studio's or a white world's), or 0
  std::string environment;     // the environment light: its file, "studio", "constant", or empty (none)
  // Checkpoints: the configuration they record, the state at the end (unfolded batch included: what a checkpoint
  // of this render holds), whether a stop request ended the render early, and what happened to the periodic ones.
  nlohmann::json checkpointConfig;
  RenderState finalState;
  bool interrupted = false;
  int stopSignal = 0;  // the signal that interrupted it (any rank's under mpirun)
  uint32_t checkpointsWritten = 0;
  double checkpointSeconds = 0.0;  // spent encoding and writing periodic checkpoints (inside `stats.seconds`)
  bool resumed = false;
  std::vector<RankReport> ranks;              // under mpirun: what each rank did (rank 0 only)
  std::optional<SampleRoundsOutcome> rounds;  // rendered in rounds (adaptive sampling, --target-error)
  EstimatorConfig estimator;                  // the one that rendered (--estimator auto's choice)
  std::optional<EstimatorChoice> choice;      // --estimator auto: what its pilots measured and chose
  std::string choiceLeftOut;                  // auto where possible, not possible here: why
};

// Throws vkmc::Error on bad options or input, before anything is written. Both runRender call it first, so
// their callers need not.
void validateOptions(const RenderOptions& options);
// The backdrop of the studio and the white world: the grey radiance camera rays see where they escape, a model
// viewer's neutral background (middle grey, what the PNG's automatic exposure keys on), while the environment lights
// the scene.
constexpr float kDefaultBackdrop = 0.18f;

// What lights a render besides the scene's own emitters and punctual lights: --environment's map or the studio;
// nothing under --background; else the world the file declares (scene.h's World: the studio unless it says
// lights-only or white).
enum class AddedLight { None, Map, Studio, White };
AddedLight addedLight(const RenderOptions& options, const Scene& scene);
RenderOutcome runRender(vk::Context& ctx, const RenderOptions& options, const RunControl& run = {});
// The same with a scene already in memory (options.scenePath only names it).
RenderOutcome runRender(vk::Context& ctx, const RenderOptions& options, Scene scene, const RunControl& run = {});
// The checkpoint of a render's end state (an interrupted render's, to resume it).
std::string encodeRenderCheckpoint(const RenderOutcome& outcome);
nlohmann::json makeReport(const RenderOptions& options, const RenderOutcome& outcome);
std::string summaryText(const RenderOptions& options, const RenderOutcome& outcome);

}  // namespace vkmc
