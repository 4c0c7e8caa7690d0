// vkmc command line: arguments -> scene -> renderer -> outputs. Exit 0 on success, 1 on an error, 2 on bad usage.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>

#include "app/bench_kernels.h"
#include "app/info.h"
#include "app/render_job.h"
#include "error.h"
#include "analysis/error_metrics.h"
#include "analysis/study.h"
#include <fstream>
#include "io/exr.h"
#include "io/output_files.h"
#include "io/png.h"
#include "vk/context.h"

namespace {

glm::vec3 parseVec3(const std::string& text, const char* flag) {
  glm::vec3 v;
  char extra;
  if (std::sscanf(text.c_str(), "%f,%f,%f%c", &v.x, &v.y, &v.z, &extra) != 3 || !std::isfinite(v.x) || !std::isfinite(v.y) ||
      !std::isfinite(v.z))
    throw vkmc::Error(std::string(flag) + " expects three finite numbers x,y,z, got '" + text + "'");
  return v;
}

// Output folders are checked before rendering, so a bad path fails in a second, not after the render.

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"vkmc: a Vulkan compute Monte Carlo path tracer whose efficiency is measured"};
  app.require_subcommand(1);

  vkmc::RenderOptions ro;
  std::string out = "out.exr", png, report, lookFrom, lookAt, background;
  float exposure = 0.0f;
  bool quiet = false;
  int spp = 64;
  long long seed = 1;
  int width = -1, height = -1, cameraIndex = -1;
  CLI::App* render = app.add_subcommand("render", "render a glTF scene to OpenEXR and print the report");
  render->add_option("scene", ro.scenePath, "scene (.gltf or .glb)")->required();
  render->add_option("-o,--output", out, "OpenEXR output (mean, variance.*, samples)")->capture_default_str();
  render->add_option("--spp", spp, "samples per pixel")->capture_default_str();
  render->add_option("--width", width, "image width (default 256)");
  render->add_option("--height", height, "image height (default from the camera's aspect ratio)");
  // Estimator flags: the keys of the JSON estimator file (host/estimators/estimator_config.h); flags override the file.
  struct EstimatorFlag {
    const char* flag;
    const char* key;
    bool numeric;
    const char* help;
  };
  const std::vector<EstimatorFlag> estimatorFlags = {
      {"--max-depth", "max_depth", true, "cap on scattering events (biased); 0 = no cap, Russian roulette only (default)"},
      {"--rr", "rr", false, "Russian roulette: none|fixed|throughput (default throughput)"},
      {"--rr-q", "rr_q", true, "fixed roulette: termination probability q (default 0.5)"},
      {"--rr-c", "rr_c", true, "fixed roulette: value c returned on termination (default 0)"},
      {"--rr-depth", "rr_depth", true, "first depth with roulette (default 3)"},
      {"--shadow-rr", "shadow_rr", true, "shadow-ray roulette threshold x pixel estimate (default 0 = off)"},
      {"--shadow-rr-q", "shadow_rr_q", true, "termination probability of tiny shadow rays (default 0.5)"},
      {"--camera-rr", "camera_rr", true, "camera-ray roulette termination probability (default 0 = off)"},
      {"--light-samples", "light_samples", true, "light samples per hit below --split-depth (default 1)"},
      {"--split-depth", "split_depth", true, "splitting applies at depths below this (default 1: first hit)"},
      {"--bsdf-samples", "bsdf_samples", true, "BSDF continuations per hit below --split-depth, each weighted 1/K (default 1)"},
      {"--bsdf-sampling", "bsdf_sampling", false, "uniform|cosine|bsdf (default bsdf)"},
      {"--light-sampling", "light_sampling", false, "area|solid-angle (default area)"},
      {"--light-select", "light_select", false, "uniform|power (default power)"},
      {"--nee", "nee", false, "next-event estimation on|off (default on)"},
      {"--mis", "mis", false, "none|balance|power (default power)"}};
  std::map<std::string, std::string> estimatorValues;
  std::string estimatorFile;
  render->add_option("--estimator", estimatorFile, "JSON estimator file (the keys of the flags below)");
  for (const auto& f : estimatorFlags) render->add_option(f.flag, estimatorValues[f.key], f.help);
  render->add_option("--seed", seed, "random seed")->capture_default_str();
  render->add_option("--camera", cameraIndex, "index of the glTF camera instance (default 0)");
  render->add_option("--look-from", lookFrom, "camera position x,y,z (overrides the file's camera)");
  render->add_option("--look-at", lookAt, "camera target x,y,z");
  render->add_option("--fov", ro.fovDegrees, "vertical field of view in degrees with --look-from")->capture_default_str();
  render->add_option("--background", background, "uniform radiance r,g,b of escaped rays (default 0,0,0)");
  render->add_option("--report", report, "JSON report file");
  render->add_option("--png", png, "sRGB PNG preview");
  render->add_option("--exposure", exposure, "PNG exposure in stops")->capture_default_str();
  render->add_flag("-q,--quiet", quiet, "no summary on stdout, no progress line");
  render->add_option("--time-budget", ro.timeBudget, "render whole sample passes until this many seconds are spent (--spp caps)");
  render->add_option("--reference", ro.referencePath, "reference EXR: the report gains mse, relmse, efficiency");
  bool noSpecialize = false;
  render->add_flag("--no-specialize", noSpecialize, "build general pipelines (every scene feature on), for comparison");
  render->add_option("--workgroup", ro.workgroupSize, "invocations per workgroup of every kernel: 32, 64, 128, 256")->capture_default_str();
  std::string integrator = "wavefront";
  render->add_option("--integrator", integrator, "wavefront (stage by stage) or megakernel (one dispatch per pass)")
      ->check(CLI::IsMember({"wavefront", "megakernel"}))->capture_default_str();

  vkmc::RenderOptions io;
  bool infoGeneral = false;
  CLI::App* info = app.add_subcommand("info", "scene features, kernels and specialization constants, BVH and memory");
  info->add_option("scene", io.scenePath, "scene (.gltf or .glb)")->required();
  info->add_flag("--no-specialize", infoGeneral, "show the general pipelines (every feature on)");

  std::string studyPath, studyOut;
  CLI::App* benchStudy = app.add_subcommand("bench", "error-against-time study: renders, results.csv/json, SVG plot, summary, images");
  benchStudy->add_option("study", studyPath, "study file (JSON; see host/analysis/study.h and scenes/studies/)")->required();
  benchStudy->add_option("-o,--output", studyOut, "output folder (default bench-<study name>)");

  std::string cmpImage, cmpReference, cmpJson, cmpHeatmap;
  CLI::App* compare = app.add_subcommand("compare", "error metrics of an EXR against a reference EXR");
  compare->add_option("image", cmpImage, "image (EXR)")->required();
  compare->add_option("reference", cmpReference, "reference (EXR)")->required();
  compare->add_option("--json", cmpJson, "write the metrics as JSON");
  compare->add_option("--heatmap", cmpHeatmap, "write per-pixel squared error (RGB) and relMSE (Y) as EXR");

  vkmc::BenchOptions bo;
  CLI::App* bench = app.add_subcommand("bench-kernels", "set-up split, samples/s and Mrays/s per scene (medians)");
  bench->add_option("scenes", bo.scenes, "scenes (default: the Cornell box and ../shared/scenes benchmark models)");
  bench->add_option("--runs", bo.runs, "timed runs per scene")->capture_default_str();
  bench->add_option("--spp", bo.spp, "samples per pixel per run")->capture_default_str();
  bench->add_option("--width", bo.width, "image width")->capture_default_str();
  bench->add_option("--height", bo.height, "image height")->capture_default_str();
  bench->add_option("--json", bo.jsonPath, "write the results as JSON");
  bench->add_flag("--specialization", bo.specialization, "compare specialized with general (all-features) pipelines");
  bench->add_option("--workgroup", bo.workgroupSize, "invocations per workgroup of every kernel: 32, 64, 128, 256")->capture_default_str();
  bench->add_flag("--sah", bo.sah, "BVH quality: SAH cost of the binned build against a full sweep build");
  bench->add_option("--integrator", bo.integrators, "wavefront, megakernel or both (interleaved, side by side)")
      ->check(CLI::IsMember({"wavefront", "megakernel"}))->expected(1, 2);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    std::fprintf(stderr, "vkmc: error: %s (see vkmc --help)\n", msg.c_str());
    return 2;
  }

  try {
    if (render->parsed()) {
      if (spp <= 0) throw vkmc::Error("--spp must be between 1 and 16777216");
      if ((render->count("--width") && width <= 0) || (render->count("--height") && height <= 0))
        throw vkmc::Error("--width and --height must be between 1 and 16384");
      if (seed < 0 || seed > 0xffffffffLL) throw vkmc::Error("--seed must be between 0 and 4294967295");
      if (render->count("--camera") && cameraIndex < 0) throw vkmc::Error("--camera must be >= 0");
      ro.spp = static_cast<uint32_t>(spp);
      if (ro.timeBudget > 0.0 && !render->count("--spp")) ro.spp = 1u << 24;  // the budget decides
      if (!estimatorFile.empty()) ro.estimator = vkmc::loadEstimatorFile(estimatorFile);
      for (const auto& f : estimatorFlags) {
        if (!render->count(f.flag)) continue;
        const std::string& text = estimatorValues[f.key];
        nlohmann::json one = nlohmann::json::object();
        if (f.numeric) {
          char* end = nullptr;
          double v = std::strtod(text.c_str(), &end);
          if (text.empty() || *end != '\0' || !std::isfinite(v)) throw vkmc::Error(std::string(f.flag) + " expects a number, got '" + text + "'");
          one[f.key] = v;
        } else {
          one[f.key] = text;
        }
        try {
          ro.estimator.applyJson(one);
        } catch (const vkmc::Error& e) {
          throw vkmc::Error(std::string(f.flag) + ": " + e.what());
        }
      }
      ro.seed = static_cast<uint32_t>(seed);
      if (width > 0) ro.width = static_cast<uint32_t>(width);
      if (height > 0) ro.height = static_cast<uint32_t>(height);
      if (cameraIndex >= 0) ro.cameraIndex = static_cast<uint32_t>(cameraIndex);
      if (!lookFrom.empty()) ro.lookFrom = parseVec3(lookFrom, "--look-from");
      if (!lookAt.empty()) ro.lookAt = parseVec3(lookAt, "--look-at");
      if (!background.empty()) ro.background = parseVec3(background, "--background");
      ro.progress = !quiet;
      ro.specialize = !noSpecialize;
      ro.integrator = vkmc::integratorFromString(integrator);
      vkmc::validateOptions(ro);
      if (!std::isfinite(exposure) || std::abs(exposure) > 100.0f) throw vkmc::Error("--exposure must be a finite number of stops in [-100, 100]");
      vkmc::checkOutputPaths({{"--output", out}, {"--png", png}, {"--report", report}},
                             {ro.scenePath, ro.referencePath, estimatorFile});

      vkmc::vk::Context ctx;
      vkmc::RenderOutcome result = vkmc::runRender(ctx, ro);
      nlohmann::json j = vkmc::makeReport(ro, result);
      j["output"] = out;
      // All outputs or none: the EXR is not replaced when the PNG or the report cannot be written.
      vkmc::OutputSet outputs;
      outputs.add(out, vkmc::encodeFilmExr(result.film));
      if (!png.empty()) outputs.add(png, vkmc::encodeFilmPng(result.film, exposure));
      if (!report.empty()) outputs.add(report, j.dump(2) + "\n");
      outputs.commit();
      if (!quiet) std::cout << vkmc::summaryText(ro, result) << "output      " << out << "\n";
      for (const auto& w : result.warnings)
        if (quiet) std::fprintf(stderr, "vkmc: warning: %s\n", w.c_str());
      return 0;
    }
    if (bench->parsed()) return vkmc::runBenchKernels(bo);
    if (info->parsed()) {
      io.specialize = !infoGeneral;
      return vkmc::runInfo(io);
    }
    if (benchStudy->parsed()) {
      vkmc::Study study = vkmc::loadStudy(studyPath);
      std::string dir = studyOut.empty() ? "bench-" + study.name : studyOut;
      vkmc::runStudy(study, dir);
      std::ifstream summary(dir + "/summary.md");
      std::cout << summary.rdbuf() << "wrote " << dir << "/{results.csv,results.json,error_vs_time.svg,summary.md,equal_time.png}\n";
      return 0;
    }
    if (compare->parsed()) {
      vkmc::checkOutputPaths({{"--json", cmpJson}, {"--heatmap", cmpHeatmap}}, {cmpImage, cmpReference});
      vkmc::ExrImage a = vkmc::readExr(cmpImage), b = vkmc::readExr(cmpReference);
      vkmc::ErrorMetrics e = vkmc::compareImages(a, b);
      nlohmann::json j = {{"image", cmpImage}, {"reference", cmpReference}, {"width", a.width}, {"height", a.height},
                          {"mse", e.mse}, {"relmse", e.relmse}, {"relmse_epsilon", vkmc::kRelMseEpsilon}, {"rmse", e.rmse},
                          {"mean_absolute_error", e.meanAbsoluteError}, {"mean_difference", e.meanDifference}};
      if (e.hasZTest) {
        j["ztest_pass_fraction"] = e.zTestPassFraction;
        j["ztest_threshold"] = e.zThreshold;
      }
      vkmc::OutputSet outputs;
      if (!cmpHeatmap.empty()) outputs.add(cmpHeatmap, vkmc::encodeExr(vkmc::errorHeatmap(a, b)));
      if (!cmpJson.empty()) outputs.add(cmpJson, j.dump(2) + "\n");
      outputs.commit();
      std::printf("MSE %.6g  relMSE %.6g (epsilon %g)  RMSE %.6g  MAE %.6g  mean difference %.6g\n", e.mse, e.relmse,
                  vkmc::kRelMseEpsilon, e.rmse, e.meanAbsoluteError, e.meanDifference);
      if (e.hasZTest)
        std::printf("per-pixel z-test (Sidak, alpha 0.01, |z| < %.2f): %.4f of pixels pass\n", e.zThreshold, e.zTestPassFraction);
      return 0;
    }
  } catch (const vkmc::Error& e) {
    std::fprintf(stderr, "vkmc: error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vkmc: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
