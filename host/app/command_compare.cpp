// `vkmc compare IMAGE REFERENCE`: error metrics of one EXR against another, printed and optionally written.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "analysis/error_metrics.h"
#include "app/commands.h"
#include "error.h"
#include "io/exr.h"
#include "io/png.h"
#include "io/output_files.h"

namespace vkmc {
namespace {

struct CompareArgs {
  std::string image, reference, json, heatmap, efficiencyPng;
};

int run(const CompareArgs& a) {
  checkOutputPaths({{"--json", a.json}, {"--heatmap", a.heatmap}, {"--efficiency-png", a.efficiencyPng}}, {a.image, a.reference});
  ExrImage img = readExr(a.image), ref = readExr(a.reference);
  if (!a.efficiencyPng.empty() && !img.channels.count("efficiency"))
    throw Error("--efficiency-png: '" + a.image + "' has no efficiency channel (a --replicates 1 render, or not this vkmc's)");
  ErrorMetrics e = compareImages(img, ref);
  nlohmann::json j = {{"image", a.image},
                      {"reference", a.reference},
                      {"width", img.width},
                      {"height", img.height},
                      {"mse", e.mse},
                      {"relmse", e.relmse},
                      {"relmse_epsilon", kRelMseEpsilon},
                      {"rmse", e.rmse},
                      {"mean_absolute_error", e.meanAbsoluteError},
                      {"mean_difference", e.meanDifference}};
  if (e.hasZTest) {
    j["ztest_pass_fraction"] = e.zTestPassFraction;
    j["ztest_threshold"] = e.zThreshold;
    j["ztest_student_t"] = e.studentT;
  }
  OutputSet outputs;
  if (!a.heatmap.empty()) outputs.add(a.heatmap, encodeExr(errorHeatmap(img, ref)));
  if (!a.json.empty()) outputs.add(a.json, j.dump(2) + "\n");
  if (!a.efficiencyPng.empty()) {
    const std::vector<float>& e = img.channels.at("efficiency");
    outputs.add(a.efficiencyPng, encodeEfficiencyPng(std::vector<double>(e.begin(), e.end()), img.width, img.height));
  }
  outputs.commit();
  std::printf("MSE %.6g  relMSE %.6g (epsilon %g)  RMSE %.6g  MAE %.6g  mean difference %.6g\n", e.mse, e.relmse, kRelMseEpsilon,
              e.rmse, e.meanAbsoluteError, e.meanDifference);
  if (!e.hasZTest)
    std::printf("no per-pixel test: %s has no variance channels (a --replicates 1 render, or not vkmc's)\n",
                img.channels.count("variance.R") ? "the reference" : "the image");
  else
    std::printf("per-pixel %s (Sidak, alpha 0.01%s%.2f): %.4f of pixels pass\n", e.studentT ? "Welch t-test" : "z-test",
                e.studentT ? ", the normal's |z| < " : ", |z| < ", e.zThreshold, e.zTestPassFraction);
  return 0;
}

}  // namespace

Command addCompareCommand(CLI::App& app) {
  auto a = std::make_shared<CompareArgs>();
  CLI::App* compare = app.add_subcommand("compare", "error metrics of an EXR against a reference EXR");
  compare->add_option("image", a->image, "image (EXR)")->required();
  compare->add_option("reference", a->reference, "reference (EXR)")->required();
  compare->add_option("--json", a->json, "write the metrics as JSON");
  compare->add_option("--heatmap", a->heatmap, "write per-pixel squared error (RGB) and relMSE (Y) as EXR");
  compare->add_option("--efficiency-png", a->efficiencyPng,
                      "write the image's efficiency channel in false colour (log scale: dark blue spends badly, yellow well)");
  return {compare, [a] { return run(*a); }};
}

}  // namespace vkmc
