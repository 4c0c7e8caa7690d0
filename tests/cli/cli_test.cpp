// The vkmc binary end to end: a render with its report, and every bad input ending in one clear line on
// stderr, a non-zero exit and no output file (a good existing output is never clobbered).
#include <gtest/gtest.h>
#include <gnu/libc-version.h>
#include <sys/wait.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "estimators/estimator_params.h"
#include "io/exr.h"
#include "vk/lavapipe_environment.h"
#include "support/lab_world.h"
#include "support/cli_run.h"
#include "support/test_scenes.h"

namespace fs = std::filesystem;
using vkmc::test::cornell;
using vkmc::test::RunResult;
using vkmc::test::runVkmc;
using vkmc::test::slurp;
using vkmc::test::workDir;

TEST(Cli, RenderWritesExrPngAndAConsistentReport) {
  fs::path exr = workDir() / "ok.exr", png = workDir() / "ok.png", report = workDir() / "ok.json";
  RunResult r = runVkmc("render " + cornell() + " --width 40 --height 30 --spp 4 -o " + exr.string() + " --png " + png.string() +
                        " --report " + report.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("Mrays/s"), std::string::npos);
  ASSERT_TRUE(fs::exists(exr));
  ASSERT_TRUE(fs::exists(png));
  vkmc::ExrImage img = vkmc::readExr(exr.string());
  EXPECT_EQ(img.width, 40);
  EXPECT_EQ(img.height, 30);
  EXPECT_EQ(img.channels.count("variance.G"), 1u);
  EXPECT_EQ(img.channels["samples"][0], 4.0f);

  auto j = nlohmann::json::parse(slurp(report));
  for (const char* key : {"scene", "width", "height", "spp", "seconds", "setup_seconds", "gpu_seconds", "rays",
                          "mrays_per_second", "nonfinite_samples", "mean", "mean_variance", "device"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["width"], 40);
  EXPECT_EQ(j["spp"], 4);
  EXPECT_EQ(j["nonfinite_samples"], 0);
  double rays = j["rays"], seconds = j["seconds"], mrays = j["mrays_per_second"];
  EXPECT_NEAR(rays / seconds * 1e-6, mrays, 1e-9 * mrays);
  EXPECT_EQ(rays, double(j["ray_counts"]["camera"]) + double(j["ray_counts"]["extension"]) + double(j["ray_counts"]["shadow"]));
  EXPECT_EQ(j["ray_counts"]["camera"], 40 * 30 * 4);
  EXPECT_GT(double(j["gpu_seconds"]), 0.0);
  EXPECT_LE(double(j["gpu_seconds"]), seconds * 1.05);
  EXPECT_TRUE(j["estimator"]["unbiased"]);
  EXPECT_GT(double(j["mean"][0]), 0.0);
  // One efficiency per cost: 1 / (mean_relvariance x cost).
  double relVar = j["mean_relvariance"];
  const auto& byCost = j["estimated_efficiency_by_cost"];
  EXPECT_DOUBLE_EQ(double(byCost["wall_seconds"]), double(j["estimated_efficiency"]));
  EXPECT_NEAR(double(byCost["gpu_seconds"]), 1.0 / (relVar * double(j["gpu_seconds"])), 1e-9 * double(byCost["gpu_seconds"]));
  EXPECT_NEAR(double(byCost["rays_per_pixel"]), 1.0 / (relVar * rays / (40 * 30)), 1e-9 * double(byCost["rays_per_pixel"]));
  EXPECT_EQ(j["variance_from"], "replicates");  // the sobol sampler (the default)
  EXPECT_EQ(j["estimator"]["sampler"], "sobol");
  // How far the variance can be trusted, and the flag it sets (docs/manual/outputs.md).
  const double rse = j["variance_reliability"]["relative_standard_error"];
  EXPECT_GT(rse, 0.0);
  EXPECT_EQ(j["estimated_efficiency_reliable"], rse <= double(j["variance_reliability"]["reliable_below"]));
  // --integrator auto (the default) names the integrator that ran: the wavefront on lavapipe.
  if (j["device"].get<std::string>().find("llvmpipe") != std::string::npos) {
    EXPECT_EQ(j["integrator"], "wavefront");
  }
  // The EXR's image mean is the report's mean.
  double sum = 0;
  for (float v : img.channels["R"]) sum += v;
  EXPECT_NEAR(sum / (40 * 30), double(j["mean"][0]), 1e-5);
}

// The cost channel counts each sample's camera-path vertices: the extension rays the report counts, plus one a
// sample for the path's last vertex (its escape or its end), where nothing splits.
TEST(Cli, CostAndEfficiencyChannelsAndTheirPng) {
  fs::path exr = workDir() / "eff.exr", png = workDir() / "eff.png", report = workDir() / "eff.json";
  RunResult r = runVkmc("render " + cornell() + " --width 24 --height 24 --spp 8 --max-depth 3 -q -o " + exr.string() +
                        " --efficiency-png " + png.string() + " --report " + report.string());
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_TRUE(fs::exists(png));
  EXPECT_EQ(slurp(png).substr(1, 3), "PNG");
  vkmc::ExrImage img = vkmc::readExr(exr.string());
  ASSERT_EQ(img.channels.count("cost"), 1u);
  ASSERT_EQ(img.channels.count("efficiency"), 1u);
  double vertices = 0.0;
  for (size_t p = 0; p < img.channels["cost"].size(); ++p) {
    EXPECT_GE(img.channels["cost"][p], 1.0f);
    EXPECT_LE(img.channels["cost"][p], 4.0f);  // depth cap 3: at most 4 vertices
    EXPECT_GE(img.channels["efficiency"][p], 0.0f);
    vertices += double(img.channels["cost"][p]) * img.channels["samples"][p];
  }
  auto j = nlohmann::json::parse(slurp(report));
  EXPECT_NEAR(vertices, double(j["ray_counts"]["camera"]) + double(j["ray_counts"]["extension"]), 1e-6 * vertices);
  // compare draws the same map from the EXR's channel: the same bytes as the render's.
  fs::path again = workDir() / "eff_again.png";
  RunResult c = runVkmc("compare " + exr.string() + " " + exr.string() + " --efficiency-png " + again.string());
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_EQ(slurp(again), slurp(png));
}

TEST(Cli, DepthCapIsReportedAsBiased) {
  fs::path report = workDir() / "capped.json";
  RunResult r = runVkmc("render " + cornell() + " --width 16 --height 16 --spp 1 --max-depth 3 -q -o " +
                        (workDir() / "capped.exr").string() + " --report " + report.string());
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = nlohmann::json::parse(slurp(report));
  EXPECT_FALSE(j["estimator"]["unbiased"]);
  EXPECT_NE(std::string(j["estimator"]["bias"]).find("truncation"), std::string::npos);
}

// One scrambling a pixel (--replicates 1) estimates no variance, and nothing pretends it does: the report's
// variance figures are null, the EXR has no variance channels, and compare says why it runs no per-pixel test.
TEST(Cli, OneScramblingReportsNoVarianceAndWritesNoVarianceChannels) {
  fs::path exr = workDir() / "one_scrambling.exr", report = workDir() / "one_scrambling.json";
  RunResult r = runVkmc("render " + cornell() + " --width 16 --height 16 --spp 8 --replicates 1 -o " + exr.string() +
                        " --report " + report.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("variance    not estimated"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("no estimated efficiency"), std::string::npos) << r.out;
  auto j = nlohmann::json::parse(slurp(report));
  EXPECT_EQ(j["estimator"]["replicates"], 1);
  EXPECT_EQ(j["variance_from"], "none");
  for (const char* key : {"mean_relvariance", "estimated_efficiency", "estimated_efficiency_by_cost", "mean_variance"})
    EXPECT_TRUE(j[key].is_null()) << key;
  EXPECT_TRUE(j["variance_reliability"].is_null());
  EXPECT_FALSE(j["estimated_efficiency_reliable"]);
  EXPECT_GT(double(j["mean"][0]), 0.0);
  vkmc::ExrImage img = vkmc::readExr(exr.string());
  EXPECT_EQ(img.channels.count("variance.R"), 0u);
  EXPECT_EQ(img.channels.count("variance.dof"), 0u);
  EXPECT_EQ(img.channels["samples"][0], 8.0f);
  RunResult c = runVkmc("compare " + exr.string() + " " + exr.string());
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_NE(c.out.find("relMSE 0 ("), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("no per-pixel test: the image has no variance channels"), std::string::npos) << c.out;
  // The independent sampler's samples are independent: one replicate still estimates their variance.
  RunResult ind = runVkmc("render " + cornell() + " --width 16 --height 16 --spp 8 --replicates 1 --sampler independent -o " +
                          exr.string() + " --report " + report.string());
  ASSERT_EQ(ind.code, 0) << ind.err;
  auto k = nlohmann::json::parse(slurp(report));
  EXPECT_EQ(k["variance_from"], "samples");
  EXPECT_GT(double(k["mean_relvariance"]), 0.0);
  EXPECT_GT(double(k["variance_reliability"]["relative_standard_error"]), 0.0);  // assessed, as with 2
  EXPECT_EQ(ind.out.find("reliability fewer samples"), std::string::npos) << ind.out;
  EXPECT_EQ(vkmc::readExr(exr.string()).channels.count("variance.R"), 1u);
}

// A time budget the efficiency pilot spends most of is named in a warning, not only in a low sample count.
TEST(Cli, AnEfficiencyPilotThatTakesTheBudgetIsWarnedOf) {
  fs::path report = workDir() / "pilot_budget.json";
  RunResult r = runVkmc("render " + cornell() + " --width 16 --height 16 --rr efficiency --time-budget 0.0001 -o " +
                        (workDir() / "pilot_budget.exr").string() + " --report " + report.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("vkmc: warning: efficiency roulette's pilot took"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("warning"), std::string::npos) << "warnings go to stderr, the summary to stdout\n" << r.out;
  auto j = nlohmann::json::parse(slurp(report));
  ASSERT_EQ(j["warnings"].size(), 1u) << j["warnings"];
  EXPECT_NE(j["warnings"][0].get<std::string>().find("of the 0.0001 s time budget"), std::string::npos) << j["warnings"];
  // A budget the pilot does not dominate has no such warning (an hour: no machine is that slow; 4 spp end it).
  RunResult plain = runVkmc("render " + cornell() + " --width 16 --height 16 --spp 4 --time-budget 3600 --rr efficiency -q -o " +
                            (workDir() / "pilot_budget.exr").string() + " --report " + report.string());
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_TRUE(nlohmann::json::parse(slurp(report))["warnings"].empty());
}

TEST(Cli, FlagsOverridingAnEstimatorFileAreNamedInTheEcho) {
  fs::path file = workDir() / "named_estimator.json", report = workDir() / "named.json";
  std::ofstream(file) << R"({"name": "fixed q", "rr": "fixed", "rr_q": 0.5})";
  std::string common = "render " + cornell() + " --width 8 --height 8 --spp 1 -q -o " + (workDir() / "named.exr").string() +
                       " --report " + report.string() + " --estimator " + file.string();
  RunResult plain = runVkmc(common);
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_EQ(nlohmann::json::parse(slurp(report))["estimator"]["name"], "fixed q");
  RunResult overridden = runVkmc(common + " --rr-q 0.25 --nee off");
  ASSERT_EQ(overridden.code, 0) << overridden.err;
  auto e = nlohmann::json::parse(slurp(report))["estimator"];
  EXPECT_EQ(e["name"], "fixed q + rr_q=0.25, nee=off");
  EXPECT_EQ(e["rr_q"], 0.25);
  EXPECT_EQ(e["rr"], "fixed");
}

TEST(Cli, RenderHelpListsEveryEstimatorFlagWithItsValuesAndDefault) {
  RunResult r = runVkmc("render --help");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const vkmc::EstimatorParam& p : vkmc::estimatorParams()) {
    EXPECT_NE(r.out.find(p.flag() + " "), std::string::npos) << p.flag();
    EXPECT_NE(r.out.find(p.helpText()), std::string::npos) << p.helpText();
  }
}

namespace {
// The bad scenes of the rows below, written once into workDir() on first use.
const fs::path& badScenes() {
  static const fs::path d = [] {
    fs::path d = workDir();
    vkmc::test::GltfSpec nan = vkmc::test::quadSpec();
    nan.positions[0] = std::numeric_limits<float>::infinity();
    vkmc::test::writeGltf(d, "nan", nan);
    vkmc::test::GltfSpec idx = vkmc::test::quadSpec();
    idx.indices[0] = 77;
    vkmc::test::writeGltf(d, "idx", idx);
    vkmc::test::GltfSpec acc = vkmc::test::quadSpec();
    acc.positionCountOverride = 1000;
    vkmc::test::writeGltf(d, "acc", acc);
    vkmc::test::GltfSpec nobin = vkmc::test::quadSpec();
    nobin.writeBin = false;
    vkmc::test::writeGltf(d, "nobin", nobin);
    vkmc::test::GltfSpec empty = vkmc::test::quadSpec();
    empty.positions = {0, 0, 0, 1, 1, 1, 2, 2, 2};
    empty.indices = {0, 1, 2};
    vkmc::test::writeGltf(d, "empty", empty);
    std::ofstream(d / "broken.gltf") << "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [";
    return d;
  }();
  return d;
}

// A bad command line: a file of badScenes() (or the Cornell box when scene is empty) and flags.
struct BadInput {
  const char* name;
  const char* scene;
  const char* flags;
  const char* expect;
  int code;
  std::string args() const {
    std::string a = *scene ? (badScenes() / scene).string() : cornell();
    return *flags ? a + " " + flags : a;
  }
};
void PrintTo(const BadInput& c, std::ostream* os) { *os << (*c.scene ? c.scene : "cornell_box.gltf") << " " << c.flags; }

class CliBadInput : public ::testing::TestWithParam<BadInput> {};
}  // namespace

TEST_P(CliBadInput, FailsCleanlyAndWritesNothing) {
  const BadInput& c = GetParam();
  fs::path d = badScenes();
  SCOPED_TRACE(c.args());
  fs::path out = d / "out.exr";
  const std::string good = "GOOD EXISTING FILE";
  std::ofstream(out) << good;
  fs::path report = d / "bad_report.json";
  fs::remove(report);
  RunResult r = runVkmc("render " + c.args() + " -q -o " + out.string() + " --report " + report.string());
  EXPECT_EQ(r.code, c.code);
  EXPECT_NE(r.err.find(c.expect), std::string::npos) << "stderr: " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "stderr: " << r.err;
  EXPECT_EQ(slurp(out), good) << "a failed run touched the existing output";
  EXPECT_FALSE(fs::exists(report));
  for (const auto& f : fs::directory_iterator(d)) EXPECT_EQ(f.path().string().find(".vkmc-"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(
    Cli, CliBadInput,
    ::testing::Values(BadInput{"broken_gltf", "broken.gltf", "", "cannot load", 1},
                      BadInput{"missing_gltf", "missing.gltf", "", "cannot open", 1},
                      BadInput{"missing_bin", "nobin.gltf", "", "cannot load", 1},
                      BadInput{"accessor_past_the_end", "acc.gltf", "", "runs past the end", 1},
                      BadInput{"index_out_of_range", "idx.gltf", "", "out of range", 1},
                      BadInput{"infinite_position", "nan.gltf", "", "NaN or infinite position", 1},
                      BadInput{"no_triangles", "empty.gltf", "", "no triangles", 1}, BadInput{"spp_0", "", "--spp 0", "--spp", 1},
                      BadInput{"width_negative", "", "--width -4", "--width", 1},
                      BadInput{"width_100000", "", "--width 100000", "--width", 1},
                      BadInput{"image_too_large", "", "--width 16384 --height 16384", "too large", 1},
                      BadInput{"max_depth_negative", "", "--max-depth -1", "--max-depth", 1},
                      BadInput{"look_from_without_look_at", "", "--look-from 1,2,3", "--look-at", 1},
                      BadInput{"look_from_two_numbers", "", "--look-from 1,2 --look-at 0,0,0", "--look-from", 1},
                      BadInput{"camera_out_of_range", "", "--camera 5", "out of range", 1},
                      BadInput{"fov_0", "", "--fov 0 --look-from 0,0,5 --look-at 0,0,0", "--fov", 1},
                      BadInput{"background_nan", "", "--background nan,0,0", "--background", 1},
                      BadInput{"environment_missing", "", "--environment /nonexistent/sky.hdr", "cannot open", 1},
                      BadInput{"environment_not_hdr", "", "--environment /etc/hostname", "neither .hdr nor .exr", 1},
                      BadInput{"environment_rotation_absurd", "", "--environment sky.hdr --environment-rotation 1e9",
                               "--environment-rotation", 1},
                      BadInput{"environment_strength_negative", "", "--environment sky.hdr --environment-strength -1",
                               "--environment-strength", 1},
                      BadInput{"filter_unknown", "", "--filter lanczos", "--filter 'lanczos' is not a filter", 1},
                      BadInput{"filter_radius_0", "", "--filter mitchell --filter-radius 0", "--filter-radius", 1},
                      BadInput{"filter_radius_negative", "", "--filter gaussian --filter-radius -1", "--filter-radius", 1},
                      BadInput{"filter_radius_nan", "", "--filter gaussian --filter-radius nan", "--filter-radius", 1},
                      BadInput{"filter_radius_huge", "", "--filter box --filter-radius 1e9", "--filter-radius", 1},
                      BadInput{"filter_radius_not_a_number", "", "--filter-radius 2px", "--filter-radius", 1},
                      BadInput{"sampler_unknown", "", "--sampler halton", "is not one of independent|sobol|zsobol", 1},
                      BadInput{"zsobol_index_too_long", "", "--sampler zsobol --width 1024 --height 1024 --spp 20000",
                               "Morton index of 34 bits", 1},
                      BadInput{"replicates_0", "", "--replicates 0", "replicates must be between 1 and 4", 1},
                      BadInput{"replicates_5", "", "--replicates 5", "replicates must be between 1 and 4", 1},
                      BadInput{"workgroup_48", "", "--workgroup 48", "--workgroup must be 32, 64, 128 or 256", 1},
                      BadInput{"workgroup_negative", "", "--workgroup -64", "--workgroup expects auto or", 1},
                      BadInput{"wavefront_too_small", "", "--wavefront 100", "--wavefront must be 1024 to", 1},
                      BadInput{"wavefront_huge", "", "--wavefront 1e9", "--wavefront expects auto or", 1},
                      BadInput{"stage_times_yes", "", "--stage-times yes", "--stage-times expects on, off or auto", 1},
                      BadInput{"adaptive_maybe", "", "--adaptive maybe", "--adaptive must be on or off", 1},
                      BadInput{"adaptive_with_ears", "", "--adaptive on --rr ears", "does not work with rr ears", 1},
                      BadInput{"adaptive_with_zsobol", "", "--adaptive on --sampler zsobol", "needs the sobol or independent", 1},
                      BadInput{"adaptive_one_replicate", "", "--adaptive on --replicates 1", "needs a variance", 1},
                      BadInput{"adaptive_with_checkpoint", "", "--adaptive on --checkpoint ck.vkmc", "do not write or resume", 1},
                      BadInput{"auto_with_ears", "", "--estimator auto --rr ears", "--estimator auto does not work with rr ears",
                               1},
                      BadInput{"auto_one_replicate", "", "--estimator auto --replicates 1", "needs a variance", 1},
                      BadInput{"auto_with_checkpoint", "", "--estimator auto --checkpoint ck.vkmc", "do not write or resume", 1},
                      BadInput{"target_error_negative", "", "--target-error -1", "--target-error must be", 1},
                      BadInput{"target_error_nan", "", "--target-error nan", "--target-error must be", 1},
                      BadInput{"spp_not_a_number", "", "--spp abc", "spp", 2},
                      BadInput{"unknown_flag", "", "--no-such-flag", "no-such-flag", 2}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(Cli, ZSobolWithATimeBudgetRendersAtTheDefaultSize) {
  // Without --spp a budget leaves the count open; ZSobol's Morton index bounds it by the image (at 256x256 and 2
  // replicates 2^17 samples a pixel) instead of refusing the open count of 2^24.
  fs::path report = workDir() / "zsobol_budget.json";
  RunResult r = runVkmc("render " + cornell() + " --sampler zsobol --time-budget 0.2 -q --report " + report.string() + " -o " +
                        (workDir() / "zsobol_budget.exr").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_GE(nlohmann::json::parse(slurp(report))["spp_reached"].get<uint32_t>(), 1u);
}

TEST(Cli, PixelFilterIsEchoedAndTheBoxIsTheDefaultBitForBit) {
  fs::path report = workDir() / "filter.json";
  std::string common = "render " + cornell() + " --width 12 --height 12 --spp 2 -q --report " + report.string();
  ASSERT_EQ(runVkmc(common + " -o " + (workDir() / "default.exr").string()).code, 0);
  EXPECT_EQ(nlohmann::json::parse(slurp(report))["filter"]["name"], "box");
  RunResult box = runVkmc(common + " --filter box -o " + (workDir() / "box.exr").string());
  ASSERT_EQ(box.code, 0) << box.err;
  EXPECT_EQ(slurp(workDir() / "box.exr"), slurp(workDir() / "default.exr")) << "--filter box is the default, bit for bit";
  RunResult mitchell = runVkmc(common + " --filter mitchell --filter-radius 1.5 -o " + (workDir() / "mitchell.exr").string());
  ASSERT_EQ(mitchell.code, 0) << mitchell.err;
  auto f = nlohmann::json::parse(slurp(report))["filter"];
  EXPECT_EQ(f["name"], "mitchell");
  EXPECT_EQ(f["radius"], 1.5);
  EXPECT_NE(slurp(workDir() / "mitchell.exr"), slurp(workDir() / "default.exr"));
  RunResult help = runVkmc("render --help");
  for (const char* name : {"--filter-radius", "gaussian", "mitchell", "blackman-harris"})
    EXPECT_NE(help.out.find(name), std::string::npos) << name;
}

TEST(Cli, IntegratorAutoIsTheDefaultAndNamesTheOneThatRan) {
  fs::path report = workDir() / "integrator.json";
  std::string common = "render " + cornell() + " --width 12 --height 12 --spp 2 -q --report " + report.string();
  ASSERT_EQ(runVkmc(common + " -o " + (workDir() / "integrator_default.exr").string()).code, 0);
  const std::string ran = nlohmann::json::parse(slurp(report))["integrator"];
  EXPECT_TRUE(ran == "wavefront" || ran == "megakernel") << ran;
  RunResult autoRun = runVkmc(common + " --integrator auto -o " + (workDir() / "integrator_auto.exr").string());
  ASSERT_EQ(autoRun.code, 0) << autoRun.err;
  EXPECT_EQ(slurp(workDir() / "integrator_auto.exr"), slurp(workDir() / "integrator_default.exr")) << "auto is the default";
  RunResult named = runVkmc(common + " --integrator " + ran + " -o " + (workDir() / "integrator_named.exr").string());
  ASSERT_EQ(named.code, 0) << named.err;
  EXPECT_EQ(slurp(workDir() / "integrator_named.exr"), slurp(workDir() / "integrator_default.exr"))
      << "auto renders exactly what naming its choice renders";
  RunResult bogus = runVkmc(common + " --integrator fastest -o " + (workDir() / "integrator_bogus.exr").string());
  EXPECT_NE(bogus.code, 0);
  EXPECT_FALSE(fs::exists(workDir() / "integrator_bogus.exr"));
}

// --workgroup and --wavefront default to the device's choice (device_tuning.h); the report names what ran and the
// path pool it sized. Naming the choice renders exactly what auto renders.
TEST(Cli, WorkgroupAndWavefrontAreTheDevicesUnlessGivenAndAreReported) {
  fs::path report = workDir() / "tuning.json";
  std::string common = "render " + cornell() + " --width 40 --height 30 --spp 4 -q --report " + report.string();
  ASSERT_EQ(runVkmc(common + " -o " + (workDir() / "tuning_auto.exr").string()).code, 0);
  const nlohmann::json t = nlohmann::json::parse(slurp(report))["device_tuning"];
  EXPECT_GE(t["subgroup_size"].get<int>(), 1);
  EXPECT_TRUE(t["chosen_by_device"]["workgroup"].get<bool>());
  EXPECT_TRUE(t["chosen_by_device"]["wavefront"].get<bool>());
  EXPECT_EQ(t["paths_per_pass"].get<uint32_t>(), 40u * 30u * 4u) << "the whole render fits one pass of the default wavefront";
  const std::string named = " --workgroup " + std::to_string(t["workgroup_size"].get<int>()) + " --wavefront " +
                            std::to_string(t["wavefront_paths"].get<int>());
  RunResult same = runVkmc(common + named + " -o " + (workDir() / "tuning_named.exr").string());
  ASSERT_EQ(same.code, 0) << same.err;
  EXPECT_EQ(slurp(workDir() / "tuning_named.exr"), slurp(workDir() / "tuning_auto.exr"));
  EXPECT_FALSE(nlohmann::json::parse(slurp(report))["device_tuning"]["chosen_by_device"]["workgroup"].get<bool>());
  // A smaller wavefront (more passes of 1024 paths) and another workgroup size: the same image, bit for bit (a
  // sample's random numbers depend on its pixel and index, never on its pass or lane).
  RunResult small = runVkmc(common + " --wavefront 1024 --workgroup 256 -o " + (workDir() / "tuning_small.exr").string());
  ASSERT_EQ(small.code, 0) << small.err;
  const nlohmann::json j = nlohmann::json::parse(slurp(report));
  EXPECT_EQ(j["device_tuning"]["paths_per_pass"], 1024);
  EXPECT_EQ(j["device_tuning"]["workgroup_size"], 256);
  EXPECT_EQ(slurp(workDir() / "tuning_small.exr"), slurp(workDir() / "tuning_auto.exr"));
}

// lavapipe's SIMD width: 512 bits (16 lanes) where the CPU has AVX-512 and the user set none, the user's where set
// (vk/lavapipe_environment.h), reported; and Mesa's shader cache kept per width, so that a run at another width
// compiles its own kernels instead of loading the other width's (Mesa 22.3 keys them without it). The image is
// the same bit for bit at either width: a sample's random numbers never depend on its lane.
TEST(Cli, LavapipesVectorWidthIsChosenPerCpuAndCachedPerWidth) {
  const fs::path cache = workDir() / "width_cache", report = workDir() / "width.json";
  fs::remove_all(cache);
  const std::string common = "render " + cornell() + " --width 40 --height 30 --spp 4 -q --report " + report.string();
  const std::string env =
      "env -u LP_NATIVE_VECTOR_WIDTH -u MESA_SHADER_CACHE_DIR -u MESA_SHADER_CACHE_DISABLE XDG_CACHE_HOME=" + cache.string() +
      " ";
  RunResult chosen = vkmc::test::runShell(env + VKMC_BINARY + " " + common + " -o " + (workDir() / "width_auto.exr").string());
  ASSERT_EQ(chosen.code, 0) << chosen.err;
  const nlohmann::json a = nlohmann::json::parse(slurp(report));
  if (a["device"].get<std::string>().find("llvmpipe") == std::string::npos) {
    EXPECT_TRUE(a["device_tuning"]["cpu_vector_bits"].is_null());
    GTEST_SKIP() << "not lavapipe";
  }
  const bool sixteen = vkmc::vk::cpuPrefersSixteenLanes();
  const int bits = a["device_tuning"]["cpu_vector_bits"].get<int>();
  EXPECT_EQ(bits, 32 * a["device_tuning"]["subgroup_size"].get<int>());
  EXPECT_EQ(a["device_tuning"]["chosen_by_device"]["cpu_vector"].get<bool>(), sixteen);
  if (sixteen) {
    EXPECT_EQ(bits, 512);
  } else if (__builtin_cpu_supports("avx2")) {
    EXPECT_EQ(bits, 256) << "lavapipe's own width where vkmc leaves it";
  }
  auto filesIn = [](const fs::path& d) {
    size_t n = 0;
    if (fs::exists(d))
      for (const auto& f : fs::recursive_directory_iterator(d)) n += f.is_regular_file();
    return n;
  };
  EXPECT_GT(filesIn(cache / "vkmc" / ("mesa-lp" + std::to_string(bits))), 0u) << "kernels cached under their width";

  const int other = bits == 256 ? 128 : 256;
  RunResult given = vkmc::test::runShell(env + "LP_NATIVE_VECTOR_WIDTH=" + std::to_string(other) + " " + VKMC_BINARY + " " +
                                         common + " -o " + (workDir() / "width_given.exr").string());
  ASSERT_EQ(given.code, 0) << given.err;
  const nlohmann::json g = nlohmann::json::parse(slurp(report));
  EXPECT_EQ(g["device_tuning"]["cpu_vector_bits"].get<int>(), other);
  EXPECT_EQ(g["device_tuning"]["subgroup_size"].get<int>(), other / 32);
  EXPECT_FALSE(g["device_tuning"]["chosen_by_device"]["cpu_vector"].get<bool>());
  EXPECT_GT(filesIn(cache / "vkmc" / ("mesa-lp" + std::to_string(other))), 0u);
  EXPECT_EQ(slurp(workDir() / "width_given.exr"), slurp(workDir() / "width_auto.exr"));
}

// glibc's malloc tuning (app/malloc_tuning.h): vkmc starts itself once more with huge-page tunables added, never
// overrides a key the user set (in GLIBC_TUNABLES or an older MALLOC_*_ variable), keeps its name, claims nothing
// for a marker it did not set, stays off with VKMC_MALLOC_TUNING=off, and the image does not depend on it.
TEST(Cli, MallocIsTunedByOneRestartUnlessTheUserSaysOtherwise) {
  const fs::path report = workDir() / "malloc.json";
  const std::string common = " render " + cornell() + " --width 40 --height 30 --spp 4 -q --report " + report.string() + " -o ";
  auto run = [&](const std::string& env, const std::string& name) {
    fs::remove(report);
    RunResult r = vkmc::test::runShell("env -u GLIBC_TUNABLES -u VKMC_MALLOC_TUNING -u VKMC_MALLOC_TUNED -u MALLOC_TOP_PAD_ " +
                                       env + " " + VKMC_BINARY + common + (workDir() / name).string());
    EXPECT_EQ(r.code, 0) << r.err;
    if (!fs::exists(report)) return std::string("no report");
    const nlohmann::json tunables = nlohmann::json::parse(slurp(report))["device_tuning"]["malloc_tunables"];
    return tunables.is_null() ? std::string() : tunables.get<std::string>();
  };
  const std::string tuned = run("", "malloc_tuned.exr");
  EXPECT_EQ(run("VKMC_MALLOC_TUNING=off", "malloc_off.exr"), "");
  EXPECT_EQ(slurp(workDir() / "malloc_off.exr"), slurp(workDir() / "malloc_tuned.exr"));
  // A marker the process did not set (its tunables not in GLIBC_TUNABLES): no restart, nothing claimed.
  EXPECT_EQ(run("VKMC_MALLOC_TUNED=glibc.malloc.hugetlb=1", "malloc_marker.exr"), "");
  int major = 0, minor = 0;
  std::sscanf(gnu_get_libc_version(), "%d.%d", &major, &minor);
  if (major < 2 || (major == 2 && minor < 35)) {
    EXPECT_EQ(tuned, "") << "no glibc.malloc.hugetlb before glibc 2.35: nothing to add";
    return;
  }
  EXPECT_NE(tuned.find("glibc.malloc.hugetlb=1"), std::string::npos) << tuned;
  EXPECT_NE(tuned.find("glibc.malloc.top_pad="), std::string::npos) << tuned;
  const std::string userKey = run("GLIBC_TUNABLES=glibc.malloc.arena_max=4:glibc.malloc.hugetlb=0", "malloc_user.exr");
  EXPECT_EQ(userKey.find("hugetlb"), std::string::npos) << "the user's key stands: " << userKey;
  EXPECT_NE(userKey.find("glibc.malloc.top_pad="), std::string::npos) << userKey;
  EXPECT_EQ(slurp(workDir() / "malloc_user.exr"), slurp(workDir() / "malloc_tuned.exr"));
  const std::string oldVariable = run("MALLOC_TOP_PAD_=131072", "malloc_old_variable.exr");
  EXPECT_EQ(oldVariable.find("top_pad"), std::string::npos) << "MALLOC_TOP_PAD_ is the user's key: " << oldVariable;
  EXPECT_NE(oldVariable.find("glibc.malloc.hugetlb=1"), std::string::npos) << oldVariable;
  // Every key the user's: nothing to add, no restart.
  EXPECT_EQ(run("GLIBC_TUNABLES=glibc.malloc.hugetlb=0:glibc.malloc.top_pad=0:glibc.malloc.mmap_threshold=131072",
                "malloc_all_users.exr"),
            "");
  // `vkmc info` says the same.
  RunResult info =
      vkmc::test::runShell("env -u GLIBC_TUNABLES -u VKMC_MALLOC_TUNING " + std::string(VKMC_BINARY) + " info " + cornell());
  EXPECT_NE(info.out.find("malloc       GLIBC_TUNABLES added glibc.malloc.hugetlb=1"), std::string::npos) << info.out;
  RunResult infoOff = vkmc::test::runShell("VKMC_MALLOC_TUNING=off " + std::string(VKMC_BINARY) + " info " + cornell());
  EXPECT_NE(infoOff.out.find("malloc       glibc's defaults"), std::string::npos) << infoOff.out;
  // Restarted by its own path, the process keeps its name (exec names it after the path it was given): read once
  // its environment holds the added tunables (the restarted image's), then the render is killed.
  const std::string script =
      "env -u GLIBC_TUNABLES -u VKMC_MALLOC_TUNING " + std::string(VKMC_BINARY) + " render " + cornell() +
      " --width 8 --height 8 --spp 100000000 -q -o " + (workDir() / "malloc_name.exr").string() +
      " & pid=$!; for i in $(seq 1 3000); do tr '\\0' '\\n' < /proc/$pid/environ 2>/dev/null | grep -q "
      "'^GLIBC_TUNABLES=.*hugetlb=1' && break; sleep 0.01; done; cat /proc/$pid/comm; kill -9 $pid; wait $pid";
  RunResult name = vkmc::test::runShell(script);
  EXPECT_EQ(name.out, "vkmc\n") << name.err;
}

// --stage-times: every stage's GPU seconds in the report, or (off, lavapipe's default) only the command buffers'
// GPU time. Timing is a measurement: the image is the same bit for bit either way.
TEST(Cli, StageTimesAreTheDevicesChoiceAndLeaveTheImageAlone) {
  fs::path report = workDir() / "stage_times.json";
  std::string common = "render " + cornell() + " --width 40 --height 30 --spp 4 -q --report " + report.string();
  ASSERT_EQ(runVkmc(common + " -o " + (workDir() / "stage_times_auto.exr").string()).code, 0);
  const nlohmann::json a = nlohmann::json::parse(slurp(report));
  EXPECT_TRUE(a["device_tuning"]["chosen_by_device"]["stage_times"].get<bool>());
  const bool lavapipe = a["device"].get<std::string>().find("llvmpipe") != std::string::npos;
  if (lavapipe) {
    EXPECT_FALSE(a["device_tuning"]["stage_times"].get<bool>());
  }
  EXPECT_EQ(a["stage_gpu_seconds"].is_null(), !a["device_tuning"]["stage_times"].get<bool>());
  EXPECT_GT(a["gpu_seconds"].get<double>(), 0.0);
  for (const char* mode : {"on", "off"}) {
    SCOPED_TRACE(mode);
    const fs::path exr = workDir() / (std::string("stage_times_") + mode + ".exr");
    RunResult r = runVkmc(common + " --stage-times " + mode + " -o " + exr.string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(slurp(exr), slurp(workDir() / "stage_times_auto.exr"));
    const nlohmann::json j = nlohmann::json::parse(slurp(report));
    const bool on = std::string(mode) == "on";
    EXPECT_EQ(j["device_tuning"]["stage_times"].get<bool>(), on);
    EXPECT_FALSE(j["device_tuning"]["chosen_by_device"]["stage_times"].get<bool>());
    const double gpu = j["gpu_seconds"];
    EXPECT_GT(gpu, 0.0);
    EXPECT_LE(gpu, j["seconds"].get<double>() * 1.05);
    if (!on) {
      EXPECT_TRUE(j["stage_gpu_seconds"].is_null());
      continue;
    }
    // On lavapipe dispatches run one after another inside their command buffers: the stages' sum is at most the
    // buffers' time (a GPU may overlap a range's start with the last dispatch's end).
    double stages = 0.0;
    for (const char* stage : {"camera_rays", "intersect_primary", "shade", "accumulate"}) {
      ASSERT_TRUE(j["stage_gpu_seconds"].contains(stage)) << stage;
      EXPECT_GT(j["stage_gpu_seconds"][stage].get<double>(), 0.0) << stage;
    }
    for (const auto& [stage, seconds] : j["stage_gpu_seconds"].items()) stages += seconds.get<double>();
    if (lavapipe) {
      EXPECT_LE(stages, gpu * (1.0 + 1e-9) + 1e-6);
    }
  }
}

TEST(Cli, MissingOutputFolderFailsBeforeRendering) {
  RunResult r = runVkmc("render " + cornell() + " -q -o /nonexistent-folder/x.exr");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
}

// A user's file (no declared world) is lit by the studio with no warning; --background 0,0,0 leaves its own lights
// alone, and a file without any is then black, which the render says.
TEST(Cli, AFileIsLitByTheStudioAndBackgroundReplacesIt) {
  vkmc::test::GltfSpec dark = vkmc::test::quadSpec();
  dark.materialJson = R"({"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.5,0.5,1]}})";
  std::string scene = vkmc::test::withoutWorld(vkmc::test::writeGltf(workDir(), "dark", dark));
  fs::path report = workDir() / "dark.json";
  std::string common = "render " + scene + " --width 16 --height 16 --spp 4 -q -o " + (workDir() / "dark.exr").string() +
                       " --report " + report.string();
  RunResult lit = runVkmc(common);
  ASSERT_EQ(lit.code, 0) << lit.err;
  EXPECT_EQ(lit.err.find("environment"), std::string::npos) << "the studio is the default, not a warning: " << lit.err;
  nlohmann::json j = nlohmann::json::parse(slurp(report));
  EXPECT_GT(j["mean"][0].get<double>(), 0.01);
  EXPECT_EQ(j["environment"].get<std::string>(), "studio");
  RunResult black = runVkmc(common + " --background 0,0,0");  // asked for: no environment, so only that it is black
  ASSERT_EQ(black.code, 0) << black.err;
  EXPECT_NE(black.err.find("the image is black"), std::string::npos) << black.err;
  EXPECT_EQ(nlohmann::json::parse(slurp(report))["mean"][0].get<double>(), 0.0);
  // --environment-strength scales the default studio as it scales --environment's (the lit quad, doubled; the
  // backdrop that escaped camera rays see stays), and
  // is refused where --background leaves no environment, or the file declares its world lights-only.
  const double litMean = j["mean"][0].get<double>();
  RunResult doubled = runVkmc(common + " --environment-strength 2");
  ASSERT_EQ(doubled.code, 0) << doubled.err;
  EXPECT_GT(nlohmann::json::parse(slurp(report))["mean"][0].get<double>(), 1.3 * litMean);
  RunResult refused = runVkmc(common + " --background 0,0,0 --environment-rotation 30");
  EXPECT_EQ(refused.code, 1);
  EXPECT_NE(refused.err.find("need an environment, and --background replaces it"), std::string::npos) << refused.err;
  RunResult lightsOnly = runVkmc("render " + cornell() + " --width 16 --height 16 --spp 4 -q -o " +
                                 (workDir() / "lights_only.exr").string() + " --environment-strength 2");
  EXPECT_EQ(lightsOnly.code, 1);
  EXPECT_NE(lightsOnly.err.find("declares its world lights-only"), std::string::npos) << lightsOnly.err;
}

// The default chooses its estimator only where its pilots fit; elsewhere the fixed defaults render and the report
// says why (a tiny image, a render of too few samples, --spp capping a budget, a budget too short).
TEST(Cli, TheDefaultEstimatorChoiceSaysWhereItDoesNotChoose) {
  struct Row {
    std::string args, why;
  } rows[] = {{"--width 8 --height 8 --spp 4 --time-budget 20", "the image is too small"},
              {"--width 64 --height 64 --spp 8", "the render is too small for its pilots"},
              {"--width 64 --height 64 --spp 8 --time-budget 12", "the render is too small for its pilots"},
              {"--width 32 --height 32 --time-budget 0.2", "too short to choose in"}};
  for (const Row& row : rows) {
    fs::path report = workDir() / "left_out.json";
    RunResult r = runVkmc("render " + cornell() + " " + row.args + " -q -o " + (workDir() / "left_out.exr").string() +
                          " --report " + report.string());
    ASSERT_EQ(r.code, 0) << r.err;
    auto j = nlohmann::json::parse(slurp(report));
    EXPECT_TRUE(j["estimator_choice"]["chosen"].is_null()) << row.args;
    EXPECT_NE(j["estimator_choice"].value("left_out", "").find(row.why), std::string::npos) << row.args << "\n"
                                                                                            << j["estimator_choice"];
  }
  // Asked for, it chooses however small the render (and says what it measured).
  fs::path report = workDir() / "asked.json";
  RunResult r = runVkmc("render " + cornell() + " --width 32 --height 32 --spp 64 --estimator auto -q -o " +
                        (workDir() / "asked.exr").string() + " --report " + report.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json choice = nlohmann::json::parse(slurp(report))["estimator_choice"];
  EXPECT_GE(choice["candidates"].size(), 2u);
  // The confirmation says whether it ran; where it did, what the winner measured against the start again.
  ASSERT_TRUE(choice["confirmation"].is_object()) << choice;
  const nlohmann::json& confirmation = choice["confirmation"];
  bool startChosen = false;
  for (const auto& c : choice["candidates"])
    if (c["chosen"].get<bool>()) startChosen = c["candidate"] == "start";
  if (confirmation["ran"].get<bool>()) {
    EXPECT_TRUE(confirmation["vs_start_95"].is_array()) << confirmation;
    EXPECT_EQ(confirmation["confirmed"].get<bool>(), !startChosen) << "the start renders where the winner did not hold";
  } else {
    const std::string why = confirmation.value("why", "");
    EXPECT_TRUE(startChosen ? why == "the start won the search" || why.find("no challenger fitted") == 0
                            : why.find("the winner renders unconfirmed") != std::string::npos)
        << confirmation;
  }
}

// A scene the camera sees only from behind: every triangle is a single-sided face it looks through, and removing
// them all would leave no scene to build a BVH on (the render once looped there). It is kept whole, and the render
// shows what the culled faces show, the backdrop.
TEST(Cli, ASceneSeenOnlyFromBehindRendersTheBackdrop) {
  const fs::path d = workDir() / "seen_from_behind";
  fs::create_directories(d);
  vkmc::test::GltfSpec quad = vkmc::test::quadSpec();
  quad.materialJson = R"({"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.5,0.5,1]}})";
  const std::string scene = vkmc::test::writeGltf(d, "quad", quad);
  RunResult r = runVkmc("render " + scene + " --width 8 --height 8 --spp 1 -q --look-from 0.5,0.5,-3 --look-at 0.5,0.5,0 -o " +
                        (d / "a.exr").string() + " --report " + (d / "a.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json report = nlohmann::json::parse(slurp((d / "a.json").string()));
  EXPECT_EQ(report["scene_info"]["seen_through_triangles_removed"], 0);
  EXPECT_EQ(report["scene_info"]["triangles"], 2);
}
