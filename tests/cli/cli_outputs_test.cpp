// vkmc's outputs are written all or nothing and never replace what is not a regular file: FIFOs (standing in for
// device nodes, which tests never touch) are written directly, symlinks keep pointing at their replaced target,
// colliding paths are refused, a failed or interrupted commit leaves every existing output and no temporary.
// Also the scenes and numbers that used to be refused or rendered wrong without a word.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include <thread>

#include "io/tone_map.h"
#include "support/adversarial_geometry.h"
#include "support/cli_run.h"
#include "support/param_name.h"
#include "support/test_scenes.h"

namespace fs = std::filesystem;
using namespace vkmc::test;

extern char** environ;

namespace {

fs::path dir() {
  static fs::path d = makeTempDir("outputs");
  return d;
}

std::string render(const std::string& scene) { return "render " + scene + " --width 16 --height 16 --spp 1 -q"; }

// A scene of one emissive (Le = 1) mesh from a soup.
std::string emissiveSoup(const Soup& soup, const std::string& name, const std::string& material = "") {
  GltfSpec spec;
  for (glm::vec3 p : soup.positions) spec.positions.insert(spec.positions.end(), {p.x, p.y, p.z});
  if (!material.empty()) spec.materialJson = material;
  return writeGltf(dir(), name, spec);
}

double reportMean(const fs::path& report) { return nlohmann::json::parse(slurp(report))["mean"][0].get<double>(); }

// Output paths that collide with each other or with the input (scene), x a path no run may create.
struct Collision {
  const char* name;
  std::string (*args)(const fs::path& scene, const fs::path& x);
  const char* expect;
};
void PrintTo(const Collision& c, std::ostream* os) { *os << c.name; }
class CollidingPaths : public ::testing::TestWithParam<Collision> {};

// A scene whose camera has an aspect ratio of 5.96e-8, written once.
const std::string& thinCamera() {
  static const std::string camera = [] {
    std::string camera = writeGltf(dir(), "thin_camera", [] {
      GltfSpec s = quadSpec();
      s.nodeExtra = "\"camera\":0";
      return s;
    }());
    std::string json = slurp(camera);
    json.replace(json.find("\"scene\":0,"), 10,
                 "\"scene\":0,\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.8,\"znear\":0.1,\"aspectRatio\":"
                 "5.96e-8}}],");
    std::ofstream(camera) << json;
    return camera;
  }();
  return camera;
}

struct Absurd {
  const char* name;
  std::string (*args)();
  const char* expect;
};
void PrintTo(const Absurd& c, std::ostream* os) { *os << c.name; }
class AbsurdNumbers : public ::testing::TestWithParam<Absurd> {};

}  // namespace

TEST_P(CollidingPaths, AreRefused) {
  fs::path scene = dir() / "scene.gltf";
  fs::copy_file(cornell(), scene, fs::copy_options::overwrite_existing);
  std::string before = slurp(scene);
  fs::path x = dir() / "x";
  const std::string args = GetParam().args(scene, x);
  RunResult r = runVkmc(render(scene.string()) + " " + args);
  EXPECT_EQ(r.code, 1) << args;
  EXPECT_NE(r.err.find(GetParam().expect), std::string::npos) << args << ": " << r.err;
  EXPECT_EQ(slurp(scene), before);
  EXPECT_FALSE(fs::exists(x));
}

INSTANTIATE_TEST_SUITE_P(
    CliOutputs, CollidingPaths,
    ::testing::Values(
        Collision{"output_is_the_input", [](const fs::path& scene, const fs::path&) { return "-o " + scene.string(); },
                  "is an input"},
        Collision{"exr_and_png", [](const fs::path&, const fs::path& x) { return "-o " + x.string() + " --png " + x.string(); },
                  "name the same file"},
        Collision{"exr_and_report",
                  [](const fs::path&, const fs::path& x) { return "-o " + x.string() + ".exr --report " + x.string() + ".exr"; },
                  "name the same file"},
        Collision{"exr_and_png_through_a_dot",
                  [](const fs::path&, const fs::path&) {
                    return "-o " + (dir() / "." / "x.exr").string() + " --png " + (dir() / "x.exr").string();
                  },
                  "name the same file"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(CliOutputs, ASymlinkKeepsPointingAtItsReplacedTarget) {
  fs::path target = dir() / "target.json", link = dir() / "link.json";
  std::ofstream(target) << "old";
  fs::remove(link);
  fs::create_symlink(target, link);
  RunResult r = runVkmc(render(cornell()) + " -o " + (dir() / "l.exr").string() + " --report " + link.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  EXPECT_GT(reportMean(target), 0.0);
}

TEST(CliOutputs, AFifoIsWrittenDirectlyAndStaysAFifo) {
  fs::path fifo = dir() / "report.fifo";
  fs::remove(fifo);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  // The read end open first (without blocking), so vkmc finds a reader; the report (~2 KB) fits the pipe.
  int readEnd = open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(readEnd, 0);
  // Through a symlink, as /dev/stdout leads to a pipe: the link and the FIFO must both survive.
  fs::path link = dir() / "report.link";
  fs::remove(link);
  fs::create_symlink(fifo, link);
  RunResult r = runVkmc(render(cornell()) + " -o " + (dir() / "f.exr").string() + " --report " + link.string());
  std::string received;
  char buf[4096];
  for (ssize_t n; (n = read(readEnd, buf, sizeof(buf))) > 0;) received.append(buf, size_t(n));
  close(readEnd);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_GT(nlohmann::json::parse(received)["mean"][0].get<double>(), 0.0);
  struct stat st {};
  ASSERT_EQ(stat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
}

TEST(CliOutputs, AFailedOutputLeavesEveryExistingOutputIntact) {
  // A FIFO nobody reads cannot be written: the render fails after rendering, at the commit.
  fs::path fifo = dir() / "unread.fifo", exr = dir() / "kept.exr", report = dir() / "kept.json";
  fs::remove(fifo);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  std::ofstream(exr) << "GOOD EXR";
  std::ofstream(report) << "GOOD REPORT";
  RunResult r = runVkmc(render(cornell()) + " -o " + exr.string() + " --png " + fifo.string() + " --report " + report.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("cannot write '" + fifo.string() + "'"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(exr), "GOOD EXR");
  EXPECT_EQ(slurp(report), "GOOD REPORT");
  EXPECT_FALSE(hasTemporaries(dir()));
}

TEST(CliOutputs, SigtermDuringTheCommitRemovesTheTemporaries) {
  // The EXR goes to a FIFO whose reader never reads: vkmc blocks there once the pipe is full, after writing the
  // other outputs' temporaries, which is where the signal must find it.
  fs::path d = dir() / "signal";
  fs::create_directories(d);
  fs::path fifo = d / "exr.fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  int readEnd = open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(readEnd, 0);
  std::vector<std::string> args = {VKMC_BINARY, "render",
                                   cornell(),   "--width",
                                   "256",       "--height",
                                   "256",       "--spp",
                                   "1",         "-q",
                                   "-o",        fifo.string(),
                                   "--png",     (d / "p.png").string(),
                                   "--report",  (d / "r.json").string()};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid;
  ASSERT_EQ(posix_spawn(&pid, VKMC_BINARY, nullptr, nullptr, argv.data(), environ), 0);
  bool sawTemporaries = false, exited = false;
  int status = 0;
  for (int i = 0; i < 6000 && !sawTemporaries && !exited; ++i) {  // a hang guard of 10 minutes, not a timing assertion
    sawTemporaries = hasTemporaries(d);
    exited = !sawTemporaries && waitpid(pid, &status, WNOHANG) == pid;
    if (!sawTemporaries && !exited) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  if (!sawTemporaries) {
    if (!exited) kill(pid, SIGKILL), waitpid(pid, &status, 0);
    close(readEnd);
    FAIL() << "vkmc " << (exited ? "exited" : "never reached its commit") << " before writing its temporaries";
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // into the blocked FIFO write
  kill(pid, SIGTERM);
  waitpid(pid, &status, 0);
  close(readEnd);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  EXPECT_FALSE(hasTemporaries(d));
  EXPECT_FALSE(fs::exists(d / "p.png"));
  EXPECT_FALSE(fs::exists(d / "r.json"));
}

TEST(CliOutputs, ALongValidOutputNameIsWritten) {
  fs::path exr = dir() / (std::string(248, 'n') + ".exr");  // 252 characters: a suffix would exceed NAME_MAX
  RunResult r = runVkmc(render(cornell()) + " -o " + exr.string());
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(exr));
}

TEST_P(AbsurdNumbers, AreRefusedWithOneLine) {
  const std::string args = GetParam().args();
  RunResult r = runVkmc(args + " -o " + (dir() / "absurd.exr").string());
  EXPECT_EQ(r.code, 1) << args;
  EXPECT_NE(r.err.find(GetParam().expect), std::string::npos) << args << ": " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir() / "absurd.exr"));
}

INSTANTIATE_TEST_SUITE_P(
    CliOutputs, AbsurdNumbers,
    ::testing::Values(Absurd{"exposure_nan", [] { return render(cornell()) + " --exposure nan"; }, "--exposure"},
                      Absurd{"look_from_1e20", [] { return render(cornell()) + " --look-from 1e20,0,0 --look-at 0,0,0"; },
                             "must be finite and within +-"},
                      Absurd{"camera_aspect_ratio_6e_8", [] { return "render " + thinCamera() + " --spp 1 -q"; },
                             "aspect ratio"}),
    [](const auto& info) { return std::string(info.param.name); });

class SphereAtTheOrigin : public ::testing::TestWithParam<double> {};

TEST_P(SphereAtTheOrigin, Renders) {
  const double radius = GetParam();
  fs::path report = dir() / "scene.json";
  RunResult r =
      runVkmc(render(emissiveSoup(uvSphere(radius, 32, 16), "sphere", R"({"emissiveFactor":[1,1,1],"doubleSided":true})")) +
              " -o " + (dir() / "s.exr").string() + " --report " + report.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_GT(reportMean(report), 0.1);
}

// Radii once refused by the BVH quantizer.
INSTANTIATE_TEST_SUITE_P(CliOutputs, SphereAtTheOrigin, ::testing::Values(0.5, 1.0, 1024.0),
                         [](const auto& info) { return paramName("radius " + shortNumber(info.param)); });

TEST(CliOutputs, HugeGroundsAndBrightLightsRender) {
  fs::path report = dir() / "scene.json";
  // A ground of half-size 3e9 (its normal overflowed float and it was dropped as zero-area).
  Soup ground = box(glm::vec3(-3e9f, 0.0f, -3e9f), glm::vec3(3e9f, 0.0f, 3e9f), "ground");
  RunResult r = runVkmc(render(emissiveSoup(ground, "ground", R"({"emissiveFactor":[1,1,1],"doubleSided":true})")) +
                        " --look-from 0,10,0 --look-at 0,0,1 -o " + (dir() / "g.exr").string() + " --report " + report.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NEAR(reportMean(report), 1.0, 1e-3);
  EXPECT_EQ(nlohmann::json::parse(slurp(report))["high_range_samples"].get<uint64_t>(), 0u);
  // Radiance 2e19: finite, but its square overflows float; it was counted as non-finite and dropped.
  std::string bright =
      R"({"emissiveFactor":[1,1,1],"doubleSided":true,"extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":2e19}}})";
  r = runVkmc(render(emissiveSoup(uvSphere(1.0, 32, 16), "bright", bright)) + " -o " + (dir() / "b.exr").string() + " --report " +
              report.string());
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(slurp(report));
  EXPECT_EQ(j["nonfinite_samples"].get<uint64_t>(), 0u);
  EXPECT_GT(j["high_range_samples"].get<uint64_t>(), 0u);  // counted apart from the non-finite ones, and kept
  EXPECT_GT(j["mean"][0].get<double>(), 1e18);
  EXPECT_TRUE(std::isfinite(j["mean_variance"][0].get<double>()));
}

// A unit lamp over a ground of half-size 10^k, k = 0 ... 11 (the accepted coordinate range). From 1e1 to 1e5 the image
// under the lamp is the same for every ground, without a word; beyond, float hit points cannot follow the lamp's
// scale (at 1e6 the mean read 26% low, from 1e7 the ground's far half was missed), and the render says so
// (scene/coordinate_precision.h). The renders share their seed, so the tolerance (5 sigma of two independent
// means) is loose for them.
TEST(CliOutputs, AGroundOfAnySizeShadesTheSameUnderALampOrSaysItCannot) {
  const std::string materials = R"({"pbrMetallicRoughness":{"baseColorFactor":[0.8,0.8,0.8,1],"metallicFactor":0}},)"
                                R"({"pbrMetallicRoughness":{"baseColorFactor":[0,0,0,1]},"emissiveFactor":[1,1,1]})";
  double smallMean = 0.0, smallVariance = 0.0;
  for (int k = 0; k <= 11; ++k) {  // 10^0: a ground smaller than the view (no warning, a different image)
    const float h = std::pow(10.0f, float(k));
    const std::string scene =
        writeQuadsGltf(dir(), "ground" + std::to_string(k),
                       {QuadSpec{{-h, 0.0f, -h}, {0.0f, 0.0f, 2.0f * h}, {2.0f * h, 0.0f, 0.0f}, 0},  // facing +y
                        QuadSpec{{-0.5f, 1.0f, -0.5f}, {1.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, 1}},   // facing -y, 1 above
                       materials);
    const fs::path report = dir() / ("ground" + std::to_string(k) + ".json");
    RunResult r = runVkmc("render " + scene + " --width 32 --height 32 --spp 64 -q --look-from 0,2.5,2.5 --look-at 0,0,0 -o " +
                          (dir() / "ground.exr").string() + " --report " + report.string());
    ASSERT_EQ(r.code, 0) << "10^" << k << ": " << r.err;
    const nlohmann::json j = nlohmann::json::parse(slurp(report));
    bool warned = false;
    for (const auto& w : j["warnings"]) warned |= w.get<std::string>().find("float hit points") != std::string::npos;
    EXPECT_EQ(warned, k >= 6) << "half-size 10^" << k << ": " << j["warnings"].dump();
    EXPECT_EQ(warned, r.err.find("float hit points") != std::string::npos) << "10^" << k << ": the warning on stderr too";
    if (k >= 6) continue;
    const double mean = j["mean"][0].get<double>(), variance = j["mean_variance"][0].get<double>() / (32.0 * 32.0);
    if (k == 0) {
      EXPECT_GT(mean, 0.0);
      continue;
    }
    if (k == 1) {
      smallMean = mean, smallVariance = variance;
      EXPECT_GT(mean, 0.02);  // the lamp lights the ground in view
      continue;
    }
    EXPECT_LT(std::abs(mean - smallMean), 5.0 * std::sqrt(variance + smallVariance))
        << "half-size 10^" << k << ": mean " << mean << " against " << smallMean;
  }
}

TEST(CliOutputs, AnInstancingBombIsRefusedBeforeAnythingIsAllocated) {
  // 2^25 instances of a quad (a 1 KB file) are 2^26 triangles, over any device's limit (at most 2^25): refused
  // from the node graph's counts, before flattening (which took 10 GB and minutes before this check).
  std::string path = writeGltf(dir(), "bomb", quadSpec());
  std::string json = slurp(path), nodes = "\"nodes\":[";
  for (int i = 0; i < 25; ++i) nodes += "{\"children\":[" + std::to_string(i + 1) + "," + std::to_string(i + 1) + "]},";
  nodes += "{\"mesh\":0}],";
  size_t a = json.find("\"nodes\":[{"), b = json.find("],", a) + 2;
  json.replace(a, b - a, nodes);
  std::ofstream(path) << json;
  RunResult r = runVkmc(render(path) + " -o " + (dir() / "bomb.exr").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("scene too big"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("67108864 instanced"), std::string::npos) << r.err;
}

// The scene's own buffer file as an output (-o, --png, --checkpoint): refused before anything is written, the
// buffer unchanged (it was overwritten before outputs were checked against the files a scene reads).
TEST(CliOutputs, AnOutputNamingTheScenesBufferIsRefused) {
  const fs::path d = dir() / "own_buffer";
  fs::create_directories(d);
  const std::string scene = writeGltf(d, "quad", quadSpec());  // quad.gltf and its buffer quad.bin
  const std::string bin = (d / "quad.bin").string(), before = slurp(bin);
  for (const std::string flag : {"-o", "--png", "--checkpoint"}) {
    const std::string extra = flag == "-o" ? "" : " -o " + (d / "out.exr").string();
    RunResult r = runVkmc(render(scene) + extra + " " + flag + " " + bin);
    EXPECT_EQ(r.code, 1) << flag << ": " << r.err;
    EXPECT_NE(r.err.find("is an input of this command"), std::string::npos) << flag << ": " << r.err;
    EXPECT_EQ(slurp(bin), before) << flag;
  }
  EXPECT_FALSE(fs::exists(d / "out.exr"));
}

// A study's outputs never overwrite what it reads: here the study file itself is named as one of them.
TEST(CliOutputs, AStudyWhoseOutputIsItsOwnFileIsRefused) {
  const fs::path d = dir() / "own_study";
  fs::create_directories(d);
  writeGltf(d, "quad", quadSpec());
  const std::string study = (d / "results.json").string();
  const std::string text = R"({"scene":"quad.gltf","spp":[1],"configurations":[{"name":"defaults"}]})";
  { std::ofstream(study) << text; }
  RunResult r = runVkmc("bench " + study + " -o " + d.string());
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("is an input of this command"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(study), text);
  EXPECT_FALSE(fs::exists(d / "summary.md"));
}

// The PNG preview is exposed automatically (its log-average at middle grey) and tone-mapped, and the report says
// how; a fixed exposure that clips it, and an image that came out black, each get one warning naming the cause.
TEST(CliOutputs, ThePreviewSaysItsExposureAndWarnsWhenClippedOrBlack) {
  const fs::path d = dir() / "preview";
  fs::create_directories(d);
  const std::string base = render(cornell()) + " -o " + (d / "a.exr").string() + " --png " + (d / "a.png").string() +
                           " --report " + (d / "a.json").string();
  RunResult automatic = runVkmc(base);
  ASSERT_EQ(automatic.code, 0) << automatic.err;
  nlohmann::json report = nlohmann::json::parse(slurp((d / "a.json").string()));
  EXPECT_EQ(report["png"]["exposure"], "auto");
  EXPECT_EQ(report["png"]["tonemap"], "neutral");
  EXPECT_GT(report["png"]["exposure_stops"].get<double>(), 0.0) << "the Cornell box's log-average is under middle grey";
  RunResult clipped = runVkmc(base + " --exposure 8 --tonemap clamp");
  ASSERT_EQ(clipped.code, 0) << clipped.err;
  EXPECT_NE(clipped.err.find("the PNG preview is clipped"), std::string::npos) << clipped.err;
  report = nlohmann::json::parse(slurp((d / "a.json").string()));
  EXPECT_EQ(report["png"]["exposure_stops"], 8.0);
  EXPECT_NE(report["warnings"].dump().find("clipped"), std::string::npos);
  GltfSpec dark = quadSpec();
  dark.materialJson = R"({"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.5,0.5,1]}})";
  RunResult black = runVkmc(render(writeGltf(d, "unlit", dark)) + " --background 0,0,0 -o " + (d / "b.exr").string());
  ASSERT_EQ(black.code, 0) << black.err;
  EXPECT_NE(black.err.find("the image is black (100.0% of its pixels): no light reaches the camera"), std::string::npos)
      << black.err;
  EXPECT_EQ(automatic.err.find("is black"), std::string::npos) << automatic.err;
}

// A lamp-bright quad (radiance 50) against the studio's grey backdrop (0.18) over about half the image: the whole
// image's key alone (its log-average at middle grey) would expose the quad at about 4.5, white, so the automatic
// exposure keeps the scene's highlights (io/tone_map.h) and puts the quad at kHighlightLimit. The report gives the
// share of pixels that show only the backdrop.
TEST(CliOutputs, TheAutomaticExposureKeepsABrightSubjectsHighlightsAgainstTheBackdrop) {
  const fs::path d = dir() / "highlights";
  fs::create_directories(d);
  GltfSpec bright = quadSpec();
  bright.materialJson = R"({"pbrMetallicRoughness":{"baseColorFactor":[0,0,0,1]},"emissiveFactor":[50,50,50]})";
  RunResult r = runVkmc(render(writeGltf(d, "bright", bright)) + " --environment studio -o " + (d / "a.exr").string() +
                        " --png " + (d / "a.png").string() + " --report " + (d / "a.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json report = nlohmann::json::parse(slurp((d / "a.json").string()));
  EXPECT_NEAR(report["png"]["exposure_stops"].get<double>(), std::log2(vkmc::kHighlightLimit / 50.0), 0.01);
  const double backdrop = report["png"]["backdrop_share"].get<double>();
  EXPECT_GT(backdrop, 0.3) << "the automatic camera frames the quad with the backdrop around it";
  EXPECT_LT(backdrop, 0.95);
  EXPECT_EQ(r.err.find("clipped"), std::string::npos) << r.err;
}
