// `vkmc render SCENE`: options -> RenderOptions -> render -> EXR, PNG and report, all or none.
#include <CLI/CLI.hpp>

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

#include "app/commands.h"
#include "render/path_pool.h"
#include "app/render_job.h"
#include "error.h"
#include "estimators/estimator_params.h"
#include "app/render_options_json.h"
#include "dist/rank_group.h"
#include "analysis/image_checks.h"
#include "io/checkpoint.h"
#include "io/exr.h"
#include "io/file_lock.h"
#include "io/output_files.h"
#include "io/png.h"
#include "io/tone_map.h"
#include "scene/gltf_loader.h"
#include "scene/studio_environment.h"
#include "vk/context.h"

namespace vkmc {
namespace {
constexpr const char* kEstimatorAuto = "auto";          // --estimator auto (app/estimator_search.h)
constexpr const char* kEstimatorDefaults = "defaults";  // the fixed defaults, not chosen

struct RenderArgs {
  RenderOptions options;
  std::string out = "out.exr", png, efficiencyPng, report, lookFrom, lookAt, background, estimatorFile, filter = "box",
              filterRadius;
  std::map<std::string, std::string> estimatorValues;  // by key, as typed after the flag
  std::string exposure = "auto", toneMap = "neutral";
  bool quiet = false, noSpecialize = false, generalSpirv = false;
  int spp = kDefaultSpp;
  long long seed = 1;
  int width = -1, height = -1, cameraIndex = -1;
  std::string integrator = "auto", workgroup = "auto", wavefront = "auto", stageTimes = "auto";
  std::string checkpoint, resume, adaptive = "off";
  double checkpointEvery = 120.0;
};

// SIGINT and SIGTERM during a checkpointed render: the first asks the render to stop after the pass in flight
// (the handler only stores the signal), a second one kills as usual, output temporaries removed first. It is the
// process's one handler for them, whichever thread a signal lands in (lavapipe's workers too): a checkpoint or an
// output being written is finished, not cut (io/output_files.cpp keeps it).
std::atomic<int> stopSignal{0};
static_assert(std::atomic<int>::is_always_lock_free, "stored from a signal handler");
extern "C" void requestStop(int sig) {
  int none = 0;
  if (stopSignal.compare_exchange_strong(none, sig)) return;         // the first: a request (two at once: one wins)
  if (outputRenamesInFlight()) return deferSignalUntilRenamed(sig);  // the outputs' renames finish first
  removePendingTemporaries();
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

void catchStopSignals() {
  for (int sig : {SIGINT, SIGTERM}) {
    struct sigaction now {
    }, before{};
    sigaction(sig, nullptr, &before);
    if (before.sa_handler == SIG_IGN) continue;  // nohup and friends: stay ignored
    now.sa_handler = requestStop;
    now.sa_flags = SA_RESTART;  // as std::signal's: slow calls in other threads resume rather than fail with EINTR
    sigemptyset(&now.sa_mask);
    sigaction(sig, &now, nullptr);
  }
}

bool sameFile(const std::string& a, const std::string& b) {
  std::error_code ec;
  return std::filesystem::equivalent(a, b, ec) && !ec;
}

std::string absolutePath(const std::string& path) {
  return path.empty() ? path : std::filesystem::absolute(path).lexically_normal().string();
}

glm::vec3 parseVec3(const std::string& text, const char* flag) {
  glm::vec3 v;
  char extra;
  if (std::sscanf(text.c_str(), "%f,%f,%f%c", &v.x, &v.y, &v.z, &extra) != 3 || !std::isfinite(v.x) || !std::isfinite(v.y) ||
      !std::isfinite(v.z))
    throw Error(std::string(flag) + " expects three finite numbers x,y,z, got '" + text + "'");
  return v;
}

}  // namespace

uint32_t parseCountOrAuto(const std::string& text, const char* flag) {
  if (text == "auto") return 0;
  char* end = nullptr;
  errno = 0;
  unsigned long long v = std::strtoull(text.c_str(), &end, 10);
  if (text.empty() || text[0] == '-' || *end != '\0' || errno == ERANGE || v == 0 || v > 0xffffffffull)
    throw Error(std::string(flag) + " expects auto or a positive whole number, got '" + text + "'");
  return static_cast<uint32_t>(v);
}

std::optional<bool> parseOnOffAuto(const std::string& text, const char* flag) {
  if (text == "auto") return std::nullopt;
  if (text == "on") return true;
  if (text == "off") return false;
  throw Error(std::string(flag) + " expects on, off or auto, got '" + text + "'");
}

namespace {

// --filter-radius as typed: a finite number (the range is the filter's check).
double parseRadius(const std::string& text) {
  char* end = nullptr;
  double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v))
    throw Error("--filter-radius expects a number of pixels, got '" + text + "'");
  return v;
}

// A flag's text as its JSON value, so the flag and the estimator file's key go through the same checks.
void applyEstimatorFlag(EstimatorConfig& e, const EstimatorParam& p, const std::string& text) {
  nlohmann::json value = text;
  if (p.kind == ParamKind::Count || p.kind == ParamKind::Real) {
    char* end = nullptr;
    double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v)) throw Error(p.flag() + " expects a number, got '" + text + "'");
    value = v;
  }
  try {
    p.setFromJson(e, value);
  } catch (const Error& err) {
    // The key's own message names the key; the flag is what the user typed.
    std::string what = err.what();
    const std::string keyPrefix = std::string(p.key) + ": ";
    if (what.rfind(keyPrefix, 0) == 0) what.erase(0, keyPrefix.size());
    throw Error(p.flag() + ": " + what);
  }
}

// The estimator file, then the flags over it. A file's name that flags changed says so ("name + rr_q=0.3"), so
// the report does not echo the file's name for a configuration that is not the file's.
// `--estimator auto` starts from the defaults and pins the keys the flags give.
EstimatorConfig estimatorFrom(const RenderArgs& a, const CLI::App& cmd, std::set<std::string>& pinned) {
  EstimatorConfig e;
  if (!a.estimatorFile.empty() && a.estimatorFile != kEstimatorAuto && a.estimatorFile != kEstimatorDefaults)
    e = loadEstimatorFile(a.estimatorFile);
  std::string overrides;
  for (const EstimatorParam& p : estimatorParams()) {
    if (!cmd.count(p.flag())) continue;
    applyEstimatorFlag(e, p, a.estimatorValues.at(p.key));
    pinned.insert(p.key);
    overrides += (overrides.empty() ? "" : ", ") + std::string(p.key) + "=" + p.text(p.get(e));
  }
  if (!e.name.empty() && !overrides.empty()) e.name += " + " + overrides;
  return e;
}

// Conversions from the command line's types; the options themselves are validated by runRender.
void fillOptions(RenderArgs& a, const CLI::App& cmd) {
  RenderOptions& ro = a.options;
  if (a.spp <= 0) throw Error("--spp must be between 1 and " + std::to_string(kMaxSpp));
  if ((cmd.count("--width") && a.width <= 0) || (cmd.count("--height") && a.height <= 0))
    throw Error("--width and --height must be between 1 and " + std::to_string(kMaxImageSide));
  if (a.seed < 0 || a.seed > 0xffffffffLL) throw Error("--seed must be between 0 and 4294967295");
  if (cmd.count("--camera") && a.cameraIndex < 0) throw Error("--camera must be >= 0");
  ro.spp = static_cast<uint32_t>(a.spp);
  if ((ro.timeBudget > 0.0 || ro.targetError > 0.0) && !cmd.count("--spp")) ro.spp = kMaxSpp;  // the budget decides
  if (a.adaptive != "on" && a.adaptive != "off") throw Error("--adaptive must be on or off");
  ro.adaptive = a.adaptive == "on";
  ro.estimator = estimatorFrom(a, cmd, ro.pinnedKeys);
  ro.estimatorAuto = a.estimatorFile == kEstimatorAuto;
  ro.estimatorAutoWherePossible = a.estimatorFile.empty();
  if (!ro.estimatorAuto && !ro.estimatorAutoWherePossible) ro.pinnedKeys.clear();
  ro.seed = static_cast<uint32_t>(a.seed);
  if (a.width > 0) ro.width = static_cast<uint32_t>(a.width);
  if (a.height > 0) ro.height = static_cast<uint32_t>(a.height);
  if (a.cameraIndex >= 0) ro.cameraIndex = static_cast<uint32_t>(a.cameraIndex);
  if (!a.lookFrom.empty()) ro.lookFrom = parseVec3(a.lookFrom, "--look-from");
  if (!a.lookAt.empty()) ro.lookAt = parseVec3(a.lookAt, "--look-at");
  if (!a.background.empty()) ro.background = parseVec3(a.background, "--background");
  ro.filter =
      pixelFilterFromName(a.filter, a.filterRadius.empty() ? std::nullopt : std::optional<double>(parseRadius(a.filterRadius)));
  ro.progress = !a.quiet;
  ro.specialize = !a.noSpecialize;
  ro.prespecializedSpirv = !a.generalSpirv;
  ro.integrator = integratorFromString(a.integrator);
  ro.workgroupSize = parseCountOrAuto(a.workgroup, "--workgroup");
  ro.wavefrontPaths = parseCountOrAuto(a.wavefront, "--wavefront");
  ro.stageTimes = parseOnOffAuto(a.stageTimes, "--stage-times");
}

// --resume without a scene: the render's options and outputs come from the checkpoint; only the outputs and the
// checkpoint's own flags may be given.
void optionsFromCheckpoint(RenderArgs& a, const CLI::App& cmd, const nlohmann::json& config) {
  static const std::vector<std::string> allowed = {"--resume",           "--output",      "--png",    "--efficiency-png",
                                                   "--report",           "--exposure",    "--quiet",  "--checkpoint",
                                                   "--checkpoint-every", "--stage-times", "--tonemap"};
  for (const CLI::Option* opt : cmd.get_options()) {
    if (opt->count() == 0 || opt->get_positional()) continue;
    if (std::find(allowed.begin(), allowed.end(), opt->get_name()) == allowed.end())
      throw Error(opt->get_name() + " cannot change a resumed render: --resume alone takes the render's options from the " +
                  "checkpoint (give the scene and the same options to have them checked instead)");
  }
  a.options = renderOptionsFromJson(config.at("options"));
  a.options.progress = !a.quiet;
  a.options.stageTimes = parseOnOffAuto(a.stageTimes, "--stage-times");
  const nlohmann::json& outputs = config.at("outputs");
  if (!cmd.count("--output")) a.out = outputs.value("output", a.out);
  if (!cmd.count("--png")) a.png = outputs.value("png", a.png);
  if (!cmd.count("--report")) a.report = outputs.value("report", a.report);
  // Checkpoints before the automatic exposure stored the stops as a number.
  if (!cmd.count("--exposure") && outputs.contains("exposure"))
    a.exposure = outputs["exposure"].is_number() ? std::to_string(outputs["exposure"].get<double>())
                                                 : outputs.value("exposure", a.exposure);
  if (!cmd.count("--tonemap")) a.toneMap = outputs.value("tonemap", a.toneMap);
}

// Under mpirun rank 0 reads the checkpoint and tells the others (their hosts may not see the file).
std::optional<Checkpoint> readResume(const std::string& path) {
  if (path.empty()) return std::nullopt;
  const RankGroup& group = RankGroup::world();
  std::string bytes;
  if (group.isRoot()) bytes = encodeCheckpoint(readCheckpoint(path));
  group.broadcast(bytes);
  return decodeCheckpoint(bytes, path);
}

// Output folders are checked before rendering, so a bad path fails in a second, not after the render (by rank 0,
// which writes them). A checkpoint path that holds something else (a user's file) is not vkmc's to overwrite, nor
// later to remove.
void checkOutputs(const RenderArgs& a, const std::string& checkpoint) {
  if (!RankGroup::world().isRoot()) return;
  const RenderOptions& ro = a.options;
  std::vector<std::string> inputs = gltfInputFiles(ro.scenePath);
  inputs.insert(inputs.end(), {ro.referencePath, ro.estimatorAuto || a.estimatorFile == kEstimatorDefaults ? "" : a.estimatorFile,
                               ro.environmentPath == kStudioEnvironment ? "" : ro.environmentPath});
  checkOutputPaths({{"--output", a.out},
                    {"--png", a.png},
                    {"--efficiency-png", a.efficiencyPng},
                    {"--report", a.report},
                    {"--checkpoint", checkpoint},
                    {"--checkpoint's lock", checkpoint.empty() ? "" : checkpoint + ".lock"}},
                   inputs);
  // The checkpoint being resumed is an input too, though the render goes on checkpointing to it.
  for (const auto& [flag, path] :
       {std::pair{"--output", a.out}, {"--png", a.png}, {"--efficiency-png", a.efficiencyPng}, {"--report", a.report}})
    if (!path.empty() && !a.resume.empty() && sameFile(path, a.resume))
      throw Error(std::string(flag) + ": '" + path + "' is the checkpoint being resumed; it would be overwritten");
  std::error_code ec;
  const auto status = std::filesystem::symlink_status(checkpoint, ec);
  if (checkpoint.empty() || !std::filesystem::exists(status) || (!a.resume.empty() && sameFile(checkpoint, a.resume))) return;
  if (!std::filesystem::is_regular_file(std::filesystem::status(checkpoint, ec)))
    throw Error("--checkpoint '" + checkpoint + "' is not a regular file");  // a FIFO would block, a device lose it
  if (!startsLikeCheckpoint(checkpoint))
    throw Error("--checkpoint '" + checkpoint + "' exists and is not a vkmc checkpoint: vkmc will not overwrite it");
}

RunControl runControl(const RenderArgs& a, const CLI::App& cmd, std::optional<Checkpoint>& resume,
                      const std::string& checkpoint) {
  RunControl control;
  control.checkpointPath = checkpoint;
  control.checkpointEvery = a.checkpointEvery;
  if (!cmd.count("--checkpoint-every")) control.checkpointShare = 0.02;  // the default promises at most 2% of the time
  control.outputs = {{"output", absolutePath(a.out)},
                     {"png", absolutePath(a.png)},
                     {"report", absolutePath(a.report)},
                     {"exposure", a.exposure},
                     {"tonemap", a.toneMap}};
  if (resume) control.resumeConfig = &resume->config, control.resumeState = &resume->state;
  if (checkpoint.empty()) return control;
  control.stop = &stopSignal;
  catchStopSignals();
  // For tests of the graceful stop: after the first checkpoint, announce it and wait for SIGINT or SIGTERM, so the
  // signal lands in a render that is certainly still running.
  if (std::getenv("VKMC_HOLD_AFTER_CHECKPOINT"))
    control.afterCheckpoint = [] {
      std::fprintf(stderr, "vkmc: checkpoint written; holding until SIGINT or SIGTERM (VKMC_HOLD_AFTER_CHECKPOINT)\n");
      while (stopSignal.load() == 0) ::usleep(10000);
    };
  return control;
}

// An interrupted render's checkpoint, written before the other outputs: one that cannot be written (a full disk, a
// read-only folder) costs the resume, never the samples done, and the report says so. Returns whether it was written.
bool writeFinalCheckpoint(const RenderArgs& a, RenderOutcome& result, const std::string& checkpoint) {
  if (!result.interrupted) return false;
  try {
    writeFileAtomically(checkpoint, encodeRenderCheckpoint(result));
    return true;
  } catch (const std::exception& e) {  // vkmc::Error, or bad_alloc: the samples done are written regardless
    result.warnings.push_back(std::string(e.what()) + ": the samples done are in '" + a.out +
                              "', but the render cannot be resumed from a checkpoint");
    return false;
  }
}

PreviewLook previewLook(const RenderArgs& a) { return {parseToneMap(a.toneMap), parseExposure(a.exposure)}; }

// All outputs or none: the EXR is not replaced when the PNG or the report cannot be written. The report gains the
// PNG's exposure and tone map.
void writeOutputs(const RenderArgs& a, const RenderOutcome& result, nlohmann::json report, std::vector<std::string>& warnings) {
  OutputSet outputs;
  outputs.add(a.out, encodeFilmExr(result.film));
  if (!a.png.empty()) {
    const PreviewLook look = previewLook(a);
    FilmPreview preview = encodeFilmPng(result.film, look, result.backdrop);
    report["png"] = {{"path", a.png},
                     {"exposure_stops", preview.stops},
                     {"backdrop_share", preview.backdropShare},
                     {"exposure", look.exposureStops ? "fixed" : "auto"},
                     {"tonemap", toneMapName(look.toneMap)}};
    if (auto w = clippedPreviewWarning(preview.clippedShare, preview.stops, !look.exposureStops)) {
      warnings.push_back(*w);
      report["warnings"].push_back(*w);
    }
    outputs.add(a.png, std::move(preview.png));
  }
  if (!a.efficiencyPng.empty()) outputs.add(a.efficiencyPng, encodeEfficiencyPng(result.film));
  // Paths are bytes, not always UTF-8: invalid sequences are replaced in the report rather than failing it.
  if (!a.report.empty()) outputs.add(a.report, report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  outputs.commit();
}

// A finished render needs its checkpoint no more (its outputs hold everything): removed where vkmc wrote it (this
// run, or the run it resumed from that path), and never a file that is not a checkpoint.
void removeFinishedCheckpoint(const RenderArgs& a, const RenderOutcome& result, const std::string& checkpoint) {
  std::error_code ec;
  const bool ours = result.checkpointsWritten > 0 || (!a.resume.empty() && sameFile(checkpoint, a.resume));
  if (ours && std::filesystem::is_regular_file(std::filesystem::symlink_status(checkpoint, ec)) &&
      startsLikeCheckpoint(checkpoint))
    std::filesystem::remove(checkpoint, ec);
}

int run(RenderArgs& a, const CLI::App& cmd) {
  std::optional<Checkpoint> resume = readResume(a.resume);
  if (a.options.scenePath.empty()) {
    if (!resume) throw Error("render needs a scene (or --resume CHECKPOINT)");
    optionsFromCheckpoint(a, cmd, resume->config);
  } else {
    fillOptions(a, cmd);
  }
  const RenderOptions& ro = a.options;
  previewLook(a);  // --exposure and --tonemap checked before the render
  // A resumed render goes on writing checkpoints where it was resumed from, unless told otherwise.
  const std::string checkpoint = !a.checkpoint.empty() ? a.checkpoint : a.resume;
  if (!(a.checkpointEvery > 0.0 && a.checkpointEvery <= 1e6))
    throw Error("--checkpoint-every must be a number of seconds in (0, 1e6]");
  checkOutputs(a, checkpoint);
  // Two renders naming one checkpoint would overwrite each other's: rank 0, which writes it, holds its lock.
  std::optional<FileLock> checkpointLock;
  if (!checkpoint.empty() && RankGroup::world().isRoot()) checkpointLock.emplace(checkpoint, "checkpoint");
  RunControl control = runControl(a, cmd, resume, checkpoint);
  vk::Context ctx;
  RenderOutcome result = runRender(ctx, ro, control);
  if (!RankGroup::world().isRoot()) return 0;  // rank 0 holds the film and writes every output
  const bool checkpointWritten = writeFinalCheckpoint(a, result, checkpoint);
  if (auto w = blackImageWarning(result.film)) result.warnings.push_back(*w);
  nlohmann::json j = makeReport(ro, result);
  j["output"] = a.out;
  if (!checkpoint.empty() && (checkpointWritten || !result.interrupted)) j["checkpoint"] = checkpoint;
  writeOutputs(a, result, j, result.warnings);
  if (!a.quiet) std::cout << summaryText(ro, result) << "output      " << a.out << "\n";
  for (const auto& w : result.warnings) std::fprintf(stderr, "vkmc: warning: %s\n", w.c_str());
  if (!result.interrupted) {
    removeFinishedCheckpoint(a, result, checkpoint);
    return 0;
  }
  // What stopped it: this process's signal, or under mpirun another rank's, relayed.
  const int sig = result.stopSignal ? result.stopSignal : stopSignal.load();
  const std::string name = sig == SIGTERM ? "SIGTERM" : sig == SIGINT ? "SIGINT" : "signal " + std::to_string(sig);
  if (checkpointWritten)
    std::fprintf(stderr,
                 "vkmc: interrupted by %s after %u of %u spp: wrote '%s' and the checkpoint '%s' (resume with: vkmc render "
                 "--resume %s)\n",
                 name.c_str(), result.stats.samplesPerPixel, ro.spp, a.out.c_str(), checkpoint.c_str(), checkpoint.c_str());
  else
    std::fprintf(stderr, "vkmc: interrupted by %s after %u of %u spp: wrote '%s' (no checkpoint: see the warning above)\n",
                 name.c_str(), result.stats.samplesPerPixel, ro.spp, a.out.c_str());
  return 128 + sig;
}

}  // namespace

namespace {

// The option groups of `vkmc render --help`, by what a user is deciding.
constexpr const char* kOutputGroup = "Output";
constexpr const char* kSamplingGroup = "Sampling";
constexpr const char* kCameraGroup = "Camera";
constexpr const char* kLightsGroup = "Lights and environment";
constexpr const char* kEstimatorGroup = "Estimators (each flag is also a key of an --estimator file)";
constexpr const char* kLongRenderGroup = "Long renders";
constexpr const char* kDeveloperGroup = "Developer switches (measurements and comparisons)";

void addOutputOptions(CLI::App* render, RenderArgs& a) {
  RenderOptions& ro = a.options;
  render->add_option("-o,--output", a.out, "OpenEXR output (mean, variance.*, samples)")
      ->capture_default_str()
      ->group(kOutputGroup);
  render->add_option("--report", a.report, "JSON report file")->group(kOutputGroup);
  render->add_option("--png", a.png, "sRGB PNG preview")->group(kOutputGroup);
  render
      ->add_option("--efficiency-png", a.efficiencyPng,
                   "false-colour PNG of the efficiency channel (log scale: dark blue spends badly, yellow well)")
      ->group(kOutputGroup);
  render
      ->add_option("--exposure", a.exposure,
                   "the PNG's exposure: auto (the log-average luminance at middle grey) or stops; the EXR is never scaled")
      ->capture_default_str()
      ->group(kOutputGroup);
  render->add_option("--tonemap", a.toneMap, "the PNG's tone map: neutral (Khronos PBR Neutral) or clamp")
      ->capture_default_str()
      ->group(kOutputGroup);
  render->add_option("--reference", ro.referencePath, "reference EXR: the report gains mse, relmse, efficiency")
      ->group(kOutputGroup);
  render->add_flag("-q,--quiet", a.quiet, "no summary on stdout, no progress line on stderr")->group(kOutputGroup);
}

void addSamplingOptions(CLI::App* render, RenderArgs& a) {
  RenderOptions& ro = a.options;
  render->add_option("--spp", a.spp, "samples per pixel")->capture_default_str()->group(kSamplingGroup);
  render->add_option("--width", a.width, "image width (default " + std::to_string(kDefaultImageWidth) + ")")
      ->group(kSamplingGroup);
  render->add_option("--height", a.height, "image height (default from the camera's aspect ratio)")->group(kSamplingGroup);
  render->add_option("--seed", a.seed, "random seed")->capture_default_str()->group(kSamplingGroup);
  render->add_option("--filter", a.filter, pixelFilterHelp())->capture_default_str()->group(kSamplingGroup);
  render->add_option("--filter-radius", a.filterRadius, "the filter's radius in pixels, per axis (default: the filter's)")
      ->group(kSamplingGroup);
  render->add_option("--time-budget", ro.timeBudget, "render whole sample passes until this many seconds are spent (--spp caps)")
      ->group(kSamplingGroup);
  render
      ->add_option("--adaptive", a.adaptive,
                   "on: after a uniform first round, each pixel's samples follow its measured relative variance (unbiased)")
      ->capture_default_str()
      ->group(kSamplingGroup);
  render
      ->add_option("--target-error", ro.targetError,
                   "render until the estimated relMSE's 95% upper bound is at most this (--spp and --time-budget cap)")
      ->group(kSamplingGroup);
}

void addCameraAndLightOptions(CLI::App* render, RenderArgs& a) {
  RenderOptions& ro = a.options;
  render->add_option("--camera", a.cameraIndex, "index of the glTF camera instance (default: the first)")->group(kCameraGroup);
  render->add_option("--look-from", a.lookFrom, "camera position x,y,z (overrides the file's camera)")->group(kCameraGroup);
  render->add_option("--look-at", a.lookAt, "camera target x,y,z")->group(kCameraGroup);
  render->add_option("--fov", ro.fovDegrees, "vertical field of view in degrees with --look-from")
      ->capture_default_str()
      ->group(kCameraGroup);
  render
      ->add_option("--background", a.background,
                   "uniform radiance r,g,b of escaped rays, reached by BSDF sampling only; replaces the file's world "
                   "(0,0,0: black, the file's own lights alone)")
      ->group(kLightsGroup);
  render
      ->add_option("--environment", ro.environmentPath,
                   "environment light: equirectangular .hdr or .exr, +Y up, the image's centre along -Z, or studio (a "
                   "built-in softbox studio); default: the file's world, the studio unless its scene's extras.vkmc_world says "
                   "lights-only or white")
      ->group(kLightsGroup);
  render->add_option("--environment-rotation", ro.environmentRotation, "rotation of the environment about +Y in degrees")
      ->capture_default_str()
      ->group(kLightsGroup);
  render->add_option("--environment-strength", ro.environmentStrength, "scale of the environment's radiance")
      ->capture_default_str()
      ->group(kLightsGroup);
}

void addLongRenderOptions(CLI::App* render, RenderArgs& a) {
  render
      ->add_option("--checkpoint", a.checkpoint,
                   "write the render's state here every --checkpoint-every seconds and on SIGINT/SIGTERM (with the "
                   "outputs of the samples done); removed when the render finishes")
      ->group(kLongRenderGroup);
  render->add_option("--checkpoint-every", a.checkpointEvery, "seconds of rendering between checkpoints")
      ->capture_default_str()
      ->group(kLongRenderGroup);
  render
      ->add_option("--resume", a.resume,
                   "continue the render a checkpoint holds, to its original target (alone, or with the same scene and "
                   "options, which are then checked)")
      ->group(kLongRenderGroup);
}

void addDeveloperOptions(CLI::App* render, RenderArgs& a) {
  render->add_flag("--no-specialize", a.noSpecialize, "build general pipelines (every scene feature on), for comparison")
      ->group(kDeveloperGroup);
  render
      ->add_flag("--general-spirv", a.generalSpirv,
                 "create pipelines from the general SPIR-V even where a pre-specialized variant matches (set-up comparisons)")
      ->group(kDeveloperGroup);
  render
      ->add_option("--workgroup", a.workgroup,
                   "invocations per workgroup of every kernel: " + workgroupSizesText() + ", or auto (the device's)")
      ->capture_default_str()
      ->group(kDeveloperGroup);
  render
      ->add_option("--stage-times", a.stageTimes,
                   "time every kernel stage (the report's stage_gpu_seconds): on, off, or auto (off on lavapipe, where "
                   "each timestamp costs about a small dispatch; on on GPUs)")
      ->capture_default_str()
      ->group(kDeveloperGroup);
  render
      ->add_option("--wavefront", a.wavefront,
                   "paths in flight per pass at most (" + wavefrontRangeText() + "), or auto (the device's)")
      ->capture_default_str()
      ->group(kDeveloperGroup);
  render
      ->add_option("--integrator", a.integrator,
                   "auto (megakernel on a discrete GPU, wavefront elsewhere), wavefront (stage by stage) or "
                   "megakernel (one dispatch per pass)")
      ->check(CLI::IsMember({"auto", "wavefront", "megakernel"}))
      ->capture_default_str()
      ->group(kDeveloperGroup);
}

}  // namespace

Command addRenderCommand(CLI::App& app) {
  auto a = std::make_shared<RenderArgs>();
  CLI::App* render = app.add_subcommand("render", "render a glTF scene to OpenEXR and print the report");
  render->add_option("scene", a->options.scenePath, "scene (.gltf or .glb); optional with --resume");
  addOutputOptions(render, *a);
  addSamplingOptions(render, *a);
  addCameraAndLightOptions(render, *a);
  // Flags override the file; both are the keys of host/estimators/estimator_params.cpp.
  render
      ->add_option(
          "--estimator", a->estimatorFile,
          "JSON estimator file (the keys of the flags below), defaults (fixed), or auto: short pilots on the "
          "scene (at most 5% of a time budget) choose roulette, light and BSDF samples, MIS and light sampling by measured "
          "efficiency; flags pin their keys. Unset: auto where it can run, the defaults elsewhere (the report says why)")
      ->group(kEstimatorGroup);
  for (const EstimatorParam& p : estimatorParams())
    render->add_option(p.flag(), a->estimatorValues[p.key], p.helpText())->group(kEstimatorGroup);
  addLongRenderOptions(render, *a);
  addDeveloperOptions(render, *a);
  return {render, [a, render] { return run(*a, *render); }};
}

}  // namespace vkmc
