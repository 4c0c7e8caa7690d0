// `vkmc render SCENE`: options -> RenderOptions -> render -> EXR, PNG and report, all or none.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

#include "app/commands.h"
#include "app/render_job.h"
#include "error.h"
#include "estimators/estimator_params.h"
#include "io/exr.h"
#include "io/output_files.h"
#include "io/png.h"
#include "vk/context.h"

namespace vkmc {
namespace {

struct RenderArgs {
  RenderOptions options;
  std::string out = "out.exr", png, report, lookFrom, lookAt, background, estimatorFile, filter = "box", filterRadius;
  std::map<std::string, std::string> estimatorValues;  // by key, as typed after the flag
  float exposure = 0.0f;
  bool quiet = false, noSpecialize = false;
  int spp = 64;
  long long seed = 1;
  int width = -1, height = -1, cameraIndex = -1;
  std::string integrator = "wavefront";
};

glm::vec3 parseVec3(const std::string& text, const char* flag) {
  glm::vec3 v;
  char extra;
  if (std::sscanf(text.c_str(), "%f,%f,%f%c", &v.x, &v.y, &v.z, &extra) != 3 || !std::isfinite(v.x) || !std::isfinite(v.y) ||
      !std::isfinite(v.z))
    throw Error(std::string(flag) + " expects three finite numbers x,y,z, got '" + text + "'");
  return v;
}

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
    throw Error(p.flag() + ": " + err.what());
  }
}

// The estimator file, then the flags over it. A file's name that flags changed says so ("name + rr_q=0.3"), so
// the report does not echo the file's name for a configuration that is not the file's.
EstimatorConfig estimatorFrom(const RenderArgs& a, const CLI::App& cmd) {
  EstimatorConfig e;
  if (!a.estimatorFile.empty()) e = loadEstimatorFile(a.estimatorFile);
  std::string overrides;
  for (const EstimatorParam& p : estimatorParams()) {
    if (!cmd.count(p.flag())) continue;
    applyEstimatorFlag(e, p, a.estimatorValues.at(p.key));
    overrides += (overrides.empty() ? "" : ", ") + std::string(p.key) + "=" + p.text(p.get(e));
  }
  if (!e.name.empty() && !overrides.empty()) e.name += " + " + overrides;
  return e;
}

// Conversions from the command line's types; the options themselves are validated by runRender.
void fillOptions(RenderArgs& a, const CLI::App& cmd) {
  RenderOptions& ro = a.options;
  if (a.spp <= 0) throw Error("--spp must be between 1 and 16777216");
  if ((cmd.count("--width") && a.width <= 0) || (cmd.count("--height") && a.height <= 0))
    throw Error("--width and --height must be between 1 and 16384");
  if (a.seed < 0 || a.seed > 0xffffffffLL) throw Error("--seed must be between 0 and 4294967295");
  if (cmd.count("--camera") && a.cameraIndex < 0) throw Error("--camera must be >= 0");
  ro.spp = static_cast<uint32_t>(a.spp);
  if (ro.timeBudget > 0.0 && !cmd.count("--spp")) ro.spp = 1u << 24;  // the budget decides
  ro.estimator = estimatorFrom(a, cmd);
  ro.seed = static_cast<uint32_t>(a.seed);
  if (a.width > 0) ro.width = static_cast<uint32_t>(a.width);
  if (a.height > 0) ro.height = static_cast<uint32_t>(a.height);
  if (a.cameraIndex >= 0) ro.cameraIndex = static_cast<uint32_t>(a.cameraIndex);
  if (!a.lookFrom.empty()) ro.lookFrom = parseVec3(a.lookFrom, "--look-from");
  if (!a.lookAt.empty()) ro.lookAt = parseVec3(a.lookAt, "--look-at");
  if (!a.background.empty()) ro.background = parseVec3(a.background, "--background");
  ro.filter = pixelFilterFromName(a.filter, a.filterRadius.empty() ? std::nullopt : std::optional<double>(parseRadius(a.filterRadius)));
  ro.progress = !a.quiet;
  ro.specialize = !a.noSpecialize;
  ro.integrator = integratorFromString(a.integrator);
  if (!std::isfinite(a.exposure) || std::abs(a.exposure) > 100.0f)
    throw Error("--exposure must be a finite number of stops in [-100, 100]");
}

int run(RenderArgs& a, const CLI::App& cmd) {
  fillOptions(a, cmd);
  const RenderOptions& ro = a.options;
  // Output folders are checked before rendering, so a bad path fails in a second, not after the render.
  checkOutputPaths({{"--output", a.out}, {"--png", a.png}, {"--report", a.report}},
                   {ro.scenePath, ro.referencePath, a.estimatorFile});

  vk::Context ctx;
  RenderOutcome result = runRender(ctx, ro);
  nlohmann::json j = makeReport(ro, result);
  j["output"] = a.out;
  // All outputs or none: the EXR is not replaced when the PNG or the report cannot be written.
  OutputSet outputs;
  outputs.add(a.out, encodeFilmExr(result.film));
  if (!a.png.empty()) outputs.add(a.png, encodeFilmPng(result.film, a.exposure));
  if (!a.report.empty()) outputs.add(a.report, j.dump(2) + "\n");
  outputs.commit();
  if (!a.quiet) std::cout << summaryText(ro, result) << "output      " << a.out << "\n";
  for (const auto& w : result.warnings)
    if (a.quiet) std::fprintf(stderr, "vkmc: warning: %s\n", w.c_str());
  return 0;
}

}  // namespace

Command addRenderCommand(CLI::App& app) {
  auto a = std::make_shared<RenderArgs>();
  RenderOptions& ro = a->options;
  CLI::App* render = app.add_subcommand("render", "render a glTF scene to OpenEXR and print the report");
  render->add_option("scene", ro.scenePath, "scene (.gltf or .glb)")->required();
  render->add_option("-o,--output", a->out, "OpenEXR output (mean, variance.*, samples)")->capture_default_str();
  render->add_option("--spp", a->spp, "samples per pixel")->capture_default_str();
  render->add_option("--width", a->width, "image width (default 256)");
  render->add_option("--height", a->height, "image height (default from the camera's aspect ratio)");
  // Flags override the file; both are the keys of host/estimators/estimator_params.cpp.
  render->add_option("--estimator", a->estimatorFile, "JSON estimator file (the keys of the flags below)");
  for (const EstimatorParam& p : estimatorParams()) render->add_option(p.flag(), a->estimatorValues[p.key], p.helpText());
  render->add_option("--seed", a->seed, "random seed")->capture_default_str();
  render->add_option("--camera", a->cameraIndex, "index of the glTF camera instance (default 0)");
  render->add_option("--look-from", a->lookFrom, "camera position x,y,z (overrides the file's camera)");
  render->add_option("--look-at", a->lookAt, "camera target x,y,z");
  render->add_option("--fov", ro.fovDegrees, "vertical field of view in degrees with --look-from")->capture_default_str();
  render->add_option("--background", a->background,
                     "uniform radiance r,g,b of escaped rays, reached by BSDF sampling only (default 0,0,0)");
  render->add_option("--environment", ro.environmentPath,
                     "environment light: equirectangular .hdr or .exr, +Y up, the image's centre along -Z (default: none; "
                     "a constant environment of radiance 1, with a warning, for a scene with no other light)");
  render->add_option("--environment-rotation", ro.environmentRotation, "rotation of the environment about +Y in degrees")
      ->capture_default_str();
  render->add_option("--environment-strength", ro.environmentStrength, "scale of the environment's radiance")
      ->capture_default_str();
  render->add_option("--filter", a->filter, pixelFilterHelp())->capture_default_str();
  render->add_option("--filter-radius", a->filterRadius, "the filter's radius in pixels, per axis (default: the filter's)");
  render->add_option("--report", a->report, "JSON report file");
  render->add_option("--png", a->png, "sRGB PNG preview");
  render->add_option("--exposure", a->exposure, "PNG exposure in stops")->capture_default_str();
  render->add_flag("-q,--quiet", a->quiet, "no summary on stdout, no progress line");
  render->add_option("--time-budget", ro.timeBudget, "render whole sample passes until this many seconds are spent (--spp caps)");
  render->add_option("--reference", ro.referencePath, "reference EXR: the report gains mse, relmse, efficiency");
  render->add_flag("--no-specialize", a->noSpecialize, "build general pipelines (every scene feature on), for comparison");
  render->add_option("--workgroup", ro.workgroupSize, "invocations per workgroup of every kernel: 32, 64, 128, 256")
      ->capture_default_str();
  render->add_option("--integrator", a->integrator, "wavefront (stage by stage) or megakernel (one dispatch per pass)")
      ->check(CLI::IsMember({"wavefront", "megakernel"}))
      ->capture_default_str();
  return {render, [a, render] { return run(*a, *render); }};
}

}  // namespace vkmc
