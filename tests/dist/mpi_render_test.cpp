// `mpirun -np 2 vkmc render ...` end to end (host/dist/): the image and the ray counts are bit-identical to one
// process's, each rank reports what it did, a rank that fails ends the job with one line and no output, and a
// render stopped under MPI resumes in one process to the uninterrupted image.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "dist/rank_group.h"
#include "support/cli_run.h"

namespace fs = std::filesystem;
using namespace vkmc::test;

namespace {

fs::path dir() {
  static fs::path d = makeTempDir("mpi");
  return d;
}

// -q keeps Open MPI's own banners out of stderr; root may run it only when allowed (containers, CI).
std::string mpirun(int ranks, const std::string& extra = "") {
  return "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun -q --oversubscribe " + extra + "-np " +
         std::to_string(ranks) + " ";
}

// Why these tests cannot run here ("" when they can). GTEST_SKIP returns only from the function it is in, so
// each test skips itself with this reason (a helper that skipped left the test running: 5 minutes of renders
// failing on machines without MPI).
std::string mpiMissing() {
  if (!vkmc::builtWithMpi()) return "vkmc was built without MPI (apt-get install libopenmpi-dev, then rebuild)";
  if (std::system("command -v mpirun >/dev/null 2>&1") != 0) return "mpirun is not installed (openmpi-bin)";
  return "";
}
#define VKMC_REQUIRE_MPI() \
  if (std::string why = mpiMissing(); !why.empty()) GTEST_SKIP() << why

// 64x64 pixels: one pass of 64 samples is a batch; 256 samples are two rounds of two ranks.
const std::string kImage = " --width 64 --height 64 --spp 256 --seed 9 -q";

nlohmann::json report(const fs::path& p) { return nlohmann::json::parse(slurp(p)); }

// The launch under `timeout 120` (after the environment's assignments): a hang becomes exit 124, not a stuck suite.
std::string withTimeout(std::string launch) { return launch.insert(launch.find("mpirun"), "timeout 120 "); }

}  // namespace

TEST(MpiRender, TwoRanksRenderTheImageOfOneProcessBitForBit) {
  VKMC_REQUIRE_MPI();
  for (const std::string& estimator : {std::string(""), std::string(" --rr efficiency --sampler sobol")}) {
    const std::string args = "render " + cornell() + kImage + estimator;
    // Under mpirun the default renders the fixed defaults (each rank would choose on its own): the one process is
    // asked for them.
    RunResult one =
        runVkmc(args + " --estimator defaults -o " + (dir() / "one.exr").string() + " --report " + (dir() / "one.json").string());
    ASSERT_EQ(one.code, 0) << one.err;
    RunResult two = runShell(mpirun(2) + VKMC_BINARY + " " + args + " -o " + (dir() / "two.exr").string() + " --report " +
                             (dir() / "two.json").string());
    ASSERT_EQ(two.code, 0) << two.err;
    EXPECT_TRUE(slurp(dir() / "one.exr") == slurp(dir() / "two.exr")) << "the 2-rank image differs" << estimator;
    nlohmann::json a = report(dir() / "one.json"), b = report(dir() / "two.json");
    EXPECT_EQ(a["rays"], b["rays"]) << estimator;
    EXPECT_EQ(a["samples"], b["samples"]);
    EXPECT_FALSE(a.contains("mpi"));
    ASSERT_TRUE(b.contains("mpi"));
    EXPECT_NE(b["estimator_choice"].value("left_out", "").find("mpirun"), std::string::npos) << b["estimator_choice"];
    EXPECT_EQ(b["mpi"]["ranks"], 2);
    uint64_t rays = 0;
    for (const auto& r : b["mpi"]["per_rank"]) {
      EXPECT_EQ(r["batches"], 2) << r;  // 4 batches of 64 samples, 2 a rank
      EXPECT_GT(r["busy_seconds"].get<double>(), 0.0);
      rays += r["rays"].get<uint64_t>();
    }
    EXPECT_EQ(rays, b["rays"].get<uint64_t>());
  }
}

TEST(MpiRender, AFailingRankEndsTheJobWithOneLineAndNoOutput) {
  VKMC_REQUIRE_MPI();
  const fs::path out = dir() / "failed.exr";
  std::ofstream(out) << "GOOD";
  // MPMD: rank 1 is started without a Vulkan driver.
  const std::string args = " render " + cornell() + kImage + " -o " + out.string();
  RunResult r = runShell(mpirun(1) + VKMC_BINARY + args + " : -np 1 env VK_ICD_FILENAMES=" + (dir() / "none.json").string() +
                         " " + VKMC_BINARY + args);
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("vkmc: error: rank 1 of 2"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("Vulkan"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(slurp(out), "GOOD");
  EXPECT_FALSE(hasTemporaries(dir()));
}

TEST(MpiRender, ARenderStoppedUnderMpiResumesInOneProcessToTheUninterruptedImage) {
  VKMC_REQUIRE_MPI();
  const fs::path d = dir() / "stop";
  fs::create_directories(d);
  const std::string ck = (d / "r.ckpt").string();
  const std::string args = " render " + cornell() + " --width 64 --height 64 --spp 1024 --seed 9 -q";
  // SIGTERM to both ranks once the first checkpoint (a round's end) is there; rank 0 writes the samples done.
  // Rank 0 holds after its first checkpoint until the signal (VKMC_HOLD_AFTER_CHECKPOINT), so it lands mid-render.
  std::string script = mpirun(2, "-x VKMC_HOLD_AFTER_CHECKPOINT=1 ") + VKMC_BINARY + args + " -o " + (d / "part.exr").string() +
                       " --report " + (d / "part.json").string() + " --checkpoint " + ck +
                       " --checkpoint-every 0.01 & m=$!; i=0; " + "while [ ! -e " + ck +
                       " ] && [ $i -lt 6000 ]; do sleep 0.05; i=$((i+1)); done; pkill -TERM -P $m; wait $m";
  RunResult stopped = runShell(script);
  ASSERT_TRUE(fs::exists(d / "part.json")) << stopped.err;
  nlohmann::json part = report(d / "part.json");
  ASSERT_TRUE(part["interrupted"].get<bool>()) << stopped.err;
  EXPECT_LT(part["spp"].get<int>(), 1024);
  EXPECT_EQ(part["spp"].get<int>() % 128, 0) << "a stop abandons the round in flight (2 ranks x 64 samples)";
  RunResult resumed = runVkmc("render --resume " + ck + " -q -o " + (d / "resumed.exr").string());
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  RunResult whole = runVkmc(args + " --estimator defaults -o " + (d / "whole.exr").string());  // what a checkpoint renders
  ASSERT_EQ(whole.code, 0) << whole.err;
  EXPECT_TRUE(slurp(d / "resumed.exr") == slurp(d / "whole.exr"));
}

// A signal that reaches one rank only (here rank 1) stops the whole job, and rank 0 reports it as what it was:
// SIGTERM, exit 128 + 15 (the relay once said "SIGINT", exit 128). The render is far too long to end by itself.
TEST(MpiRender, AStopThatReachesOneRankIsReportedAsWhatItWas) {
  VKMC_REQUIRE_MPI();
  const fs::path d = dir() / "relay";
  fs::create_directories(d);
  const std::string ck = (d / "r.ckpt").string();
  const std::string script = mpirun(2) + VKMC_BINARY + " render " + cornell() + " --width 32 --height 32 --spp 1048576 -q -o " +
                             (d / "part.exr").string() + " --checkpoint " + ck +
                             " --checkpoint-every 0.01 & m=$!; i=0; while [ ! -e " + ck +
                             " ] && [ $i -lt 6000 ]; do sleep 0.05; i=$((i+1)); done; for p in $(pgrep -P $m); do "
                             "grep -qa OMPI_COMM_WORLD_RANK=1 /proc/$p/environ && kill -TERM $p; done; wait $m";
  RunResult r = runShell(script);
  EXPECT_EQ(r.code, 128 + SIGTERM) << r.err;
  EXPECT_NE(r.err.find("vkmc: interrupted by SIGTERM"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(d / "part.exr"));
}

// A rank stopped by SIGSTOP (it neither answers nor dies) ends the job after the bounded wait (VKMC_RANK_TIMEOUT,
// 2 s here) with one line naming it, instead of keeping every other rank in MPI forever. `timeout` turns the old
// behaviour, a hang, into a failure.
TEST(MpiRender, AStoppedRankEndsTheJobWithALineNamingIt) {
  VKMC_REQUIRE_MPI();
  const fs::path d = dir() / "stopped";
  fs::create_directories(d);
  const std::string ck = (d / "r.ckpt").string();
  const std::string script =
      withTimeout(mpirun(2, "-x VKMC_RANK_TIMEOUT=2 ")) + VKMC_BINARY + " render " + cornell() +
      " --width 32 --height 32 --spp 1048576 -q -o " + (d / "part.exr").string() + " --checkpoint " + ck +
      " --checkpoint-every 0.01 & m=$!; i=0; while [ ! -e " + ck +
      " ] && [ $i -lt 6000 ]; do sleep 0.05; i=$((i+1)); done; for p in $(pgrep -P \"$(pgrep -P $m)\"); do "
      "grep -qa OMPI_COMM_WORLD_RANK=1 /proc/$p/environ && kill -STOP $p; done; wait $m";
  RunResult r = runShell(script);
  EXPECT_NE(r.code, 0) << r.err;
  EXPECT_NE(r.code, 124) << "the job hung on the stopped rank: " << r.err;
  EXPECT_NE(r.err.find("vkmc: error: rank 1 of 2 did not answer for"), std::string::npos) << r.err;
}
