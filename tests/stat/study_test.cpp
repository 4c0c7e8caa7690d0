// A small error-against-time study end to end: every output exists and parses, the SVG is well-formed XML with
// one line per configuration, and the baseline's error falls as 1/spp. Bad study files are rejected. (Against
// time the slope of such tiny renders is steeper than -1: per-pass overhead dominates their few samples.)
#include <gtest/gtest.h>

#include <cmath>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/study.h"
#include "error.h"

namespace fs = std::filesystem;
using namespace vkmc;

namespace {
std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
fs::path writeStudy(const std::string& name, const std::string& body) {
  fs::path dir = fs::temp_directory_path() / "vkmc-study-test";
  fs::create_directories(dir);
  fs::path p = dir / (name + ".json");
  std::ofstream(p) << body;
  return p;
}
}  // namespace

TEST(Study, SmallSppLadderEndToEnd) {
  setenv("VKMC_CACHE_DIR", (fs::temp_directory_path() / "vkmc-study-cache").c_str(), 1);
  fs::path file = writeStudy("tiny", R"({"name": "tiny", "scene": ")" + std::string(VKMC_SOURCE_DIR) +
                                         R"(/scenes/cornell_box.gltf", "width": 32, "height": 32, "reference": {"spp": 8192},
      "configurations": [{"name": "baseline"}, {"name": "cosine", "estimator": {"bsdf_sampling": "cosine"}}],
      "spp": [8, 64], "repeats": 1})");
  Study study = loadStudy(file.string());
  fs::path out = fs::temp_directory_path() / "vkmc-study-out";
  fs::remove_all(out);
  std::vector<StudyRow> rows = runStudy(study, out.string());
  for (const char* f : {"results.csv", "results.json", "error_vs_time.svg", "summary.md", "equal_time.png"})
    ASSERT_TRUE(fs::exists(out / f)) << f;

  // CSV: header plus one row per configuration and rung, every numeric field parses.
  std::istringstream csv(slurp(out / "results.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line.rfind("configuration,rung,repeat,spp,seconds", 0), 0u);
  int n = 0;
  while (std::getline(csv, line)) {
    ++n;
    std::stringstream fields(line.substr(line.find("\",") + 2));
    std::string field;
    while (std::getline(fields, field, ',')) EXPECT_NO_THROW((void)std::stod(field)) << line;
  }
  EXPECT_EQ(n, 4);

  // SVG: well-formed (xmllint), one polyline per configuration.
  std::string svg = slurp(out / "error_vs_time.svg");
  size_t lines = 0;
  for (size_t p = svg.find("<polyline"); p != std::string::npos; p = svg.find("<polyline", p + 1)) ++lines;
  EXPECT_EQ(lines, 2u);
  if (std::system("command -v xmllint >/dev/null 2>&1") == 0)
    EXPECT_EQ(std::system(("xmllint --noout " + (out / "error_vs_time.svg").string()).c_str()), 0);
  else
    ADD_FAILURE() << "xmllint missing: tools/setup.sh installs libxml2-utils";

  // The baseline's error falls as the samples rise, as 1/spp for an unbiased estimator.
  const StudyRow &a = rows[0], &b = rows[2];
  ASSERT_EQ(a.configuration, "baseline");
  ASSERT_EQ(b.configuration, "baseline");
  EXPECT_EQ(b.spp, 64u);
  EXPECT_LT(b.relmse, a.relmse);
  EXPECT_GT(b.seconds, a.seconds);
  double slope = std::log(b.relmse / a.relmse) / std::log(double(b.spp) / a.spp);
  EXPECT_GT(slope, -1.3);
  EXPECT_LT(slope, -0.7);
  EXPECT_NE(slurp(out / "summary.md").find("| cosine |"), std::string::npos);
}

TEST(Study, RejectsBadStudyFiles) {
  EXPECT_THROW(loadStudy(writeStudy("noscene", R"({"configurations": [{"name": "a"}], "spp": [1]})").string()), Error);
  EXPECT_THROW(
      loadStudy(writeStudy("twoladders", R"({"scene": "x.gltf", "configurations": [{"name": "a"}], "spp": [1], "seconds": [1]})")
                    .string()),
      Error);
  EXPECT_THROW(
      loadStudy(writeStudy("badest",
                           R"({"scene": "x.gltf", "configurations": [{"name": "a", "estimator": {"mis": "best"}}], "spp": [1]})")
                    .string()),
      Error);
  EXPECT_THROW(
      loadStudy(writeStudy("negative", R"({"scene": "x.gltf", "configurations": [{"name": "a"}], "seconds": [-1]})").string()),
      Error);
}

TEST(Study, ReadsItsPixelFilter) {
  Study s = loadStudy(
      writeStudy("filtered",
                 R"({"scene": "x.gltf", "configurations": [{"name": "a"}], "spp": [1], "filter": {"name": "mitchell"}})")
          .string());
  EXPECT_EQ(s.filter.kind, gpu::kPixelFilterMitchell);
  EXPECT_EQ(s.filter.radius, 2.0f);
  EXPECT_TRUE(
      loadStudy(writeStudy("unfiltered", R"({"scene": "x.gltf", "configurations": [{"name": "a"}], "spp": [1]})").string())
          .filter.isPixelBox());
  for (const char* bad : {R"({"name": "lanczos"})", R"({"name": "gaussian", "radius": 0})", R"("mitchell")"})
    EXPECT_THROW(
        loadStudy(writeStudy(
                      "badfilter",
                      std::string(R"({"scene": "x.gltf", "configurations": [{"name": "a"}], "spp": [1], "filter": )") + bad + "}")
                      .string()),
        Error)
        << bad;
}

TEST(Study, TimeBudgetRendersReachMoreSamplesWithMoreTime) {
  setenv("VKMC_CACHE_DIR", (fs::temp_directory_path() / "vkmc-study-cache").c_str(), 1);
  fs::path file = writeStudy("timed", R"({"name": "timed", "scene": ")" + std::string(VKMC_SOURCE_DIR) +
                                          R"(/scenes/cornell_box.gltf", "width": 32, "height": 32, "reference": {"spp": 512},
      "configurations": [{"name": "baseline"}], "seconds": [0.2, 0.8], "repeats": 1})");
  std::vector<StudyRow> rows = runStudy(loadStudy(file.string()), (fs::temp_directory_path() / "vkmc-study-timed").string());
  ASSERT_EQ(rows.size(), 2u);
  for (const StudyRow& r : rows) {
    EXPECT_GE(r.seconds, r.rung) << "a budget is spent";
    EXPECT_LT(r.seconds, 2.0 * r.rung + 0.1) << "and not overrun by much more than a pass (a quarter budget)";
  }
  // Four times the time renders more samples even where the machine is twice as busy for the longer rung (how many
  // more depends on the load: 249 against 141 under a parallel ctest, 411 against 39 alone).
  EXPECT_GT(rows[1].spp, rows[0].spp);
  // The error follows the samples, not the seconds: where the longer rung has half as many again, its relMSE
  // (against a 512-spp reference, whose own noise bounds how far it falls) is lower.
  if (2 * rows[1].spp >= 3 * rows[0].spp) {
    EXPECT_LT(rows[1].relmse, rows[0].relmse);
  }
}

// A reference the scene's physics gives exactly: the furnace (every surface albedo 0.5, emission 1, seen from
// inside) has radiance 1 / (1 - 0.5) = 2 everywhere. Its relMSE must fall as 1/spp all the way (a biased renderer
// would level off), and the summary must name the reference.
TEST(Study, AConstantReferenceMeasuresTheFurnaceAgainstItsAnalyticRadiance) {
  fs::path file = writeStudy("furnace", R"({"name": "furnace", "scene": ")" + std::string(VKMC_SOURCE_DIR) +
                                            R"(/scenes/furnace.gltf", "width": 16, "height": 16, "reference": {"constant": 2},
      "configurations": [{"name": "baseline"}], "spp": [16, 1024], "repeats": 1})");
  Study study = loadStudy(file.string());
  ASSERT_TRUE(study.referenceConstant.has_value());
  EXPECT_EQ(*study.referenceConstant, glm::vec3(2.0f));
  fs::path out = fs::temp_directory_path() / "vkmc-study-furnace";
  fs::remove_all(out);
  std::vector<StudyRow> rows = runStudy(study, out.string());
  ASSERT_EQ(rows.size(), 2u);
  double slope = std::log(rows[1].relmse / rows[0].relmse) / std::log(double(rows[1].spp) / rows[0].spp);
  EXPECT_GT(slope, -1.3);
  EXPECT_LT(slope, -0.7);
  EXPECT_NE(slurp(out / "summary.md").find("constant (2, 2, 2)"), std::string::npos);
}

TEST(Study, RejectsBadConstantReferences) {
  Study s = loadStudy(writeStudy("rgb", R"({"scene": "x.gltf", "configurations": [{"name": "a"}], "spp": [1],
      "reference": {"constant": [1, 0.5, 100]}})")
                          .string());
  ASSERT_TRUE(s.referenceConstant.has_value());
  EXPECT_EQ(*s.referenceConstant, glm::vec3(1.0f, 0.5f, 100.0f));
  for (const char* bad : {R"("2")", "[1, 2]", "-1", "[1, 2, -3]", "1e39", "{}"})
    EXPECT_THROW(
        loadStudy(
            writeStudy(
                "badconstant",
                std::string(R"({"scene": "x.gltf", "configurations": [{"name": "a"}], "spp": [1], "reference": {"constant": )") +
                    bad + "}}")
                .string()),
        Error)
        << bad;
}

// Each repeat renders the configurations in turn, reversed every other repeat (no configuration always first).
TEST(Study, RepeatsAlternateTheOrderOfTheirConfigurations) {
  EXPECT_EQ(studyRunOrder(3, 0), (std::vector<size_t>{0, 1, 2}));
  EXPECT_EQ(studyRunOrder(3, 1), (std::vector<size_t>{2, 1, 0}));
  EXPECT_EQ(studyRunOrder(3, 2), (std::vector<size_t>{0, 1, 2}));
  EXPECT_EQ(studyRunOrder(1, 1), (std::vector<size_t>{0}));
  EXPECT_TRUE(studyRunOrder(0, 0).empty());
}
