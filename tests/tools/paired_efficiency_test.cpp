// tools/paired_efficiency.py end to end on the furnace, whose analytic reference the tool writes itself: both
// renders of a pair ran and were compared with that reference, a control pair (A against A, one seed) differs by
// what its two renders' sample counts explain, a --json path that is not a regular file is refused, and a rendered
// reference is kept across a binary that renders A's image the same and rendered again by one that does not.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/cli_run.h"

namespace fs = std::filesystem;
using namespace vkmc::test;

namespace {

std::string tool(const std::string& args) {
  return "VKMC=" + std::string(VKMC_BINARY) + " python3 " + std::string(VKMC_SOURCE_DIR) + "/tools/paired_efficiency.py " +
         std::string(VKMC_SOURCE_DIR) + "/scenes/furnace.gltf --reference-constant 2 --width 16 --height 16 " + args;
}

bool toolRuns() { return runShell("command -v python3 && nproc | grep -qv '^1$'").code == 0; }

}  // namespace

TEST(PairedEfficiency, AControlPairOfTheFurnaceReadsItsSampleCountsRatio) {
  if (!toolRuns()) GTEST_SKIP() << "needs python3 and two cores";
  fs::path out = workDir() / "paired_control.json";
  std::string est = std::string(VKMC_SOURCE_DIR) + "/scenes/estimators/baseline.json";
  RunResult r = runShell(tool("--seconds 0.3 --pairs 2 --a " + est + " --b " + est + " --json " + out.string()));
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(slurp(out));
  ASSERT_EQ(j.at("pairs").size(), 2u);
  for (const auto& p : j.at("pairs")) {
    const auto &a = p.at("a"), &b = p.at("b");
    EXPECT_EQ(a.at("seed"), b.at("seed"));  // common random numbers
    EXPECT_GE(a.at("spp").get<int>(), 1);
    // Against the analytic 2: the furnace's error is its noise alone, so relMSE ~ variance / spp.
    EXPECT_GT(a.at("relmse").get<double>(), 0.0);
    EXPECT_LT(a.at("relmse").get<double>(), 1.0);
    // The ratio is what the two renders report: efficiency = 1 / (relMSE x seconds), the analytic reference
    // adding no noise of its own.
    const double relA = a.at("relmse").get<double>(), relB = b.at("relmse").get<double>();
    EXPECT_DOUBLE_EQ(a.at("relmse_own").get<double>(), relA);
    EXPECT_NEAR(p.at("ratio").get<double>() / (relA * a.at("seconds").get<double>() / (relB * b.at("seconds").get<double>())),
                1.0, 1e-9);
    // One seed, one estimator: B's samples are A's first ones or A's B's, so the two relMSEs differ by what the
    // sample counts explain (relMSE ~ 1/spp; a factor 3 leaves room for the noise of 256 pixels), and not at all
    // where the counts are equal (the same samples, summed in the same order: rng.h keys them by sample index).
    const double sppRatio = double(b.at("spp").get<int>()) / double(a.at("spp").get<int>());
    EXPECT_GT(relA / relB, sppRatio / 3.0);
    EXPECT_LT(relA / relB, sppRatio * 3.0);
    if (a.at("spp") == b.at("spp")) {
      EXPECT_NEAR(relA / relB, 1.0, 1e-4);
    }
  }
  ASSERT_TRUE(j.at("interval95").is_array());
  const double low = j.at("interval95")[0].get<double>(), high = j.at("interval95")[1].get<double>();
  EXPECT_TRUE(std::isfinite(low) && std::isfinite(high));
  EXPECT_LE(low, high);
  EXPECT_EQ(j.at("reference_relvariance").get<double>(), 0.0);
  EXPECT_EQ(j.at("cores"), "swap");  // the default: the two renders trade cores
}

TEST(PairedEfficiency, RefusesToReplaceAJsonPathThatIsNotARegularFile) {
  if (!toolRuns()) GTEST_SKIP() << "needs python3 and two cores";
  fs::path folder = workDir() / "paired_json_folder";
  fs::create_directories(folder);
  RunResult r = runShell(tool("--seconds 0.2 --pairs 1 --json " + folder.string()));
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("not a regular file"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_directory(folder));
}

// The cached reference is keyed on a probe render's bytes, not on the binary: a wrapper that runs the same vkmc (a
// rebuild that changed nothing A renders) finds it; a wrapper that changes A's image (here by capping the depth)
// renders its own.
TEST(PairedEfficiency, KeepsItsReferenceForABinaryThatRendersTheSameImageOnly) {
  if (!toolRuns()) GTEST_SKIP() << "needs python3 and two cores";
  fs::path cache = workDir() / "paired_reference_cache";
  fs::remove_all(cache);
  auto wrapper = [&](const std::string& name, const std::string& extra) {
    fs::path path = workDir() / name;
    {
      std::ofstream f(path);
      f << "#!/bin/sh\nexec " << VKMC_BINARY << " \"$@\"" << extra << "\n";
    }
    fs::permissions(path, fs::perms::owner_all);
    return path.string();
  };
  const std::string same = wrapper("vkmc_same.sh", ""), deeper = wrapper("vkmc_capped.sh", " --max-depth 1");
  auto run = [&](const std::string& vkmc, const std::string& json) {
    return runShell("VKMC_CACHE_DIR=" + cache.string() + " python3 " + std::string(VKMC_SOURCE_DIR) +
                    "/tools/paired_efficiency.py " + std::string(VKMC_SOURCE_DIR) +
                    "/scenes/furnace.gltf --width 8 --height 8 --reference-spp 8192 --seconds 0.2 --pairs 1 --vkmc " + vkmc +
                    " --json " + (workDir() / json).string());
  };
  auto reference = [&](const std::string& json) {
    return nlohmann::json::parse(slurp(workDir() / json)).at("reference").get<std::string>();
  };
  RunResult first = run(VKMC_BINARY, "paired_ref_first.json");
  ASSERT_EQ(first.code, 0) << first.err;
  EXPECT_NE(first.err.find("rendering the reference"), std::string::npos) << first.err;
  RunResult again = run(same, "paired_ref_same.json");
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_EQ(again.err.find("rendering the reference"), std::string::npos) << again.err;
  EXPECT_EQ(reference("paired_ref_same.json"), reference("paired_ref_first.json"));
  RunResult capped = run(deeper, "paired_ref_capped.json");
  ASSERT_EQ(capped.code, 0) << capped.err;
  EXPECT_NE(capped.err.find("rendering the reference"), std::string::npos) << capped.err;
  EXPECT_NE(reference("paired_ref_capped.json"), reference("paired_ref_first.json"));
}
