// Checkpoints end to end: SIGINT and SIGTERM stop a render after the pass in flight and write the samples done
// with the checkpoint; `--resume` finishes it bit for bit; foreign, corrupt and mismatched checkpoints are refused
// with one line; a full disk costs the checkpoint, never the render or an old output.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <thread>

#include "support/cli_run.h"

namespace fs = std::filesystem;
using namespace vkmc::test;

namespace {

fs::path dir() {
  static fs::path d = makeTempDir("cli-checkpoint");
  return d;
}

// 64x64 pixels take 64 samples a pass: 8 passes, a second or more on lavapipe.
const std::string kRender = " --width 64 --height 64 --spp 512 --seed 5 -q";

int lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

}  // namespace

TEST(CliCheckpoint, ASignalStopsTheRenderAndResumeFinishesItBitForBit) {
  for (int sig : {SIGINT, SIGTERM}) {
    fs::path d = dir() / (sig == SIGINT ? "int" : "term");
    fs::create_directories(d);
    const std::string ck = (d / "render.ckpt").string(), out = (d / "out.exr").string(), report = (d / "report.json").string();
    const std::vector<std::string> args = {"render",   cornell(),
                                           "--width",  "64",
                                           "--height", "64",
                                           "--spp",    "512",
                                           "--seed",   "5",
                                           "-q",       "-o",
                                           out,        "--report",
                                           report,     "--checkpoint",
                                           ck,         "--checkpoint-every",
                                           "0.01",     "--stage-times",
                                           "off"};
    pid_t pid = spawnVkmc(args, kHoldAfterCheckpoint);
    ASSERT_GT(pid, 0);
    waitForFile(ck);  // the first periodic checkpoint: vkmc holds there until the signal
    kill(pid, sig);
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    ASSERT_EQ(WEXITSTATUS(status), 128 + sig);
    nlohmann::json j = nlohmann::json::parse(slurp(report));
    EXPECT_TRUE(j["interrupted"].get<bool>());
    EXPECT_LT(j["spp"].get<int>(), 512);
    EXPECT_GT(j["samples"].get<uint64_t>(), 0u);  // the EXR holds the samples done
    EXPECT_TRUE(fs::exists(out));
    EXPECT_FALSE(hasTemporaries(d));

    // --stage-times may change on resume (a measurement, not the render): a report whose earlier part was not
    // timed has no stage times, rather than those of its last part.
    RunResult resumed = runVkmc("render --resume " + ck + " -q --report " + (d / "resumed.json").string() +
                                (sig == SIGTERM ? " --stage-times on" : ""));
    EXPECT_EQ(resumed.code, 0) << resumed.err;
    nlohmann::json r = nlohmann::json::parse(slurp(d / "resumed.json"));
    EXPECT_TRUE(r["resumed"].get<bool>());
    EXPECT_TRUE(r["stage_gpu_seconds"].is_null());
    EXPECT_GT(r["gpu_seconds"].get<double>(), j["gpu_seconds"].get<double>()) << "the resumed part's GPU time adds";
    EXPECT_EQ(r["spp"].get<int>(), 512);
    EXPECT_FALSE(fs::exists(ck)) << "a finished render removes its checkpoint";
    EXPECT_EQ(j["estimator_choice"]["left_out"], "a checkpoint records one estimator");
    // A checkpointed render renders the fixed defaults; so does the uninterrupted one asked for them.
    RunResult uninterrupted = runVkmc("render " + cornell() + kRender + " --estimator defaults -o " + (d / "whole.exr").string());
    ASSERT_EQ(uninterrupted.code, 0) << uninterrupted.err;
    EXPECT_TRUE(slurp(out) == slurp(d / "whole.exr")) << "the resumed render (written to the original -o) differs";
  }
}

TEST(CliCheckpoint, ForeignCorruptAndMismatchedCheckpointsAreRefusedWithOneLine) {
  fs::path d = dir() / "refuse";
  fs::create_directories(d);
  const std::string ck = (d / "r.ckpt").string();
  // A checkpoint to refuse things with: the render is stopped at once by SIGTERM after its first checkpoint.
  pid_t pid = spawnVkmc({"render", cornell(), "--width", "64", "--height", "64", "--spp", "512", "--seed", "5", "-q", "-o",
                         (d / "o.exr").string(), "--checkpoint", ck, "--checkpoint-every", "0.01"},
                        kHoldAfterCheckpoint);
  waitForFile(ck);
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(fs::exists(ck)) << "a stopped render keeps its checkpoint";
  const std::string bytes = slurp(ck);

  auto refused = [&](const std::string& args, const std::string& expected) {
    RunResult r = runVkmc(args);
    EXPECT_EQ(r.code, 1) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << args << "\n" << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
  };
  refused("render " + cornell() + " --width 64 --height 64 --spp 256 --seed 5 -q --resume " + ck, "differs in spp");
  refused("render " + std::string(VKMC_SOURCE_DIR) +
              "/scenes/veach_mis.gltf --width 64 --height 64 --spp 512 --seed 5 -q --resume " + ck,
          "differs in scene");
  refused("render --resume " + ck + " --spp 8", "--spp cannot change a resumed render");
  std::ofstream(d / "text.ckpt") << "not a checkpoint\n";
  refused("render --resume " + (d / "text.ckpt").string(), "is not a vkmc checkpoint");
  std::ofstream(d / "short.ckpt", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  refused("render --resume " + (d / "short.ckpt").string(), "is truncated");
  std::string flipped = bytes;
  flipped[flipped.size() / 2] ^= 1;
  std::ofstream(d / "flipped.ckpt", std::ios::binary) << flipped;
  refused("render --resume " + (d / "flipped.ckpt").string(), "is corrupt");
  refused("render --resume " + (d / "missing.ckpt").string(), "does not exist");
  // The checkpoint being resumed as an output of the resumed render (with the checkpoints going elsewhere).
  refused("render --resume " + ck + " -o " + ck + " --checkpoint " + (d / "elsewhere.ckpt").string(),
          "is the checkpoint being resumed");
  refused("render --resume " + d.string(), "is not a regular file");
  // The same scene file with one material changed is another scene.
  fs::create_directories(d / "scene");
  for (const char* f : {"cornell_box.gltf", "cornell_box.bin"})
    if (fs::exists(fs::path(VKMC_SOURCE_DIR) / "scenes" / f))
      fs::copy_file(fs::path(VKMC_SOURCE_DIR) / "scenes" / f, d / "scene" / f);
  // A checkpoint of the copy's render, stopped at once.
  const std::string ck2 = (d / "copy.ckpt").string();
  pid = spawnVkmc({"render", (d / "scene/cornell_box.gltf").string(), "--width", "64", "--height", "64", "--spp", "512", "--seed",
                   "5", "-q", "-o", (d / "c2.exr").string(), "--checkpoint", ck2, "--checkpoint-every", "0.01"},
                  kHoldAfterCheckpoint);
  waitForFile(ck2);
  kill(pid, SIGTERM);
  waitpid(pid, &status, 0);
  ASSERT_TRUE(fs::exists(ck2)) << "a stopped render keeps its checkpoint";
  std::string gltf = slurp(d / "scene/cornell_box.gltf");
  size_t at = gltf.find("\"emissiveStrength\"");
  ASSERT_NE(at, std::string::npos);
  size_t digit = gltf.find_first_of("123456789", at);
  gltf[digit] = gltf[digit] == '9' ? '8' : char(gltf[digit] + 1);
  std::ofstream(d / "scene/cornell_box.gltf", std::ios::binary | std::ios::trunc) << gltf;
  refused("render --resume " + ck2, "belongs to another scene");
}

TEST(CliCheckpoint, AFullDiskCostsTheCheckpointNotTheRender) {
  if (std::system("unshare -m --propagation private true 2>/dev/null") != 0) GTEST_SKIP() << "no private mount namespace here";
  fs::path d = dir() / "disk";
  fs::create_directories(d);
  // 256 KiB: the 32x32 EXR (~60 KB) and the report fit, a checkpoint of this image (~300 KB) does not.
  const std::string disk = d.string() + "/mnt";
  fs::create_directories(disk);
  std::string script = "mount -t tmpfs -o size=256k tmpfs " + disk + " && " + VKMC_BINARY + " render " + cornell() +
                       " --width 32 --height 32 --spp 512 -q -o " + disk + "/out.exr --checkpoint " + disk +
                       "/render.ckpt --checkpoint-every 0.01 2>" + (d / "err.txt").string() + "; echo rc=$?; ls -a " + disk;
  RunResult r = runShell("unshare -m --propagation private sh -c '" + script + "'");
  std::string err = slurp(d / "err.txt");
  EXPECT_NE(r.out.find("rc=0"), std::string::npos) << r.out << err;
  EXPECT_NE(r.out.find("out.exr"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("render.ckpt"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find(".vkmc-"), std::string::npos) << "a temporary was left behind: " << r.out;
  EXPECT_NE(err.find("No space left on device (the render goes on"), std::string::npos) << err;
}

TEST(CliCheckpoint, AnOutputThatIsAFolderIsRefusedBeforeRendering) {
  fs::create_directories(dir() / "a-folder");
  RunResult r = runVkmc("render " + cornell() + " --spp 1 -q -o " + (dir() / "a-folder").string());
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("folder"), std::string::npos) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  RunResult c = runVkmc("render " + cornell() + " --spp 1 -q -o " + (dir() / "x.exr").string() + " --checkpoint " +
                        (dir() / "a-folder").string());
  EXPECT_EQ(c.code, 1) << c.err;
  EXPECT_NE(c.err.find("--checkpoint"), std::string::npos) << c.err;
  EXPECT_FALSE(fs::exists(dir() / "x.exr"));
}

// --checkpoint naming a file vkmc did not write: refused before the render (never overwritten), and a render that
// wrote no checkpoint (it finished before the first) leaves an earlier checkpoint it was not resumed from alone.
TEST(CliCheckpoint, ACheckpointPathHoldingAUsersFileIsNeverOverwrittenNorRemoved) {
  fs::path d = dir() / "foreign";
  fs::create_directories(d);
  const fs::path notes = d / "notes.txt";
  std::ofstream(notes) << "a user's file\n";
  RunResult r = runVkmc("render " + cornell() + " --width 16 --height 16 --spp 4 -q -o " + (d / "o.exr").string() +
                        " --checkpoint " + notes.string());
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("exists and is not a vkmc checkpoint"), std::string::npos) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(slurp(notes), "a user's file\n");
  EXPECT_FALSE(fs::exists(d / "o.exr"));
  // A checkpoint of another render at the path, and a render that finishes before its first checkpoint is due.
  const fs::path old = d / "old.ckpt";
  std::ofstream(old, std::ios::binary) << "VKMC-CHECKPOINT\n" << std::string(64, '\0');
  RunResult quick = runVkmc("render " + cornell() + " --width 16 --height 16 --spp 4 -q -o " + (d / "o.exr").string() +
                            " --checkpoint " + old.string() + " --checkpoint-every 1000");
  EXPECT_EQ(quick.code, 0) << quick.err;
  EXPECT_TRUE(fs::exists(old)) << "removed a checkpoint this render never wrote";
}

// Two renders naming one checkpoint: the second is refused with one line while the first holds it (the first
// holds at its first checkpoint, VKMC_HOLD_AFTER_CHECKPOINT, so the two certainly overlap), and the first's lock
// file is gone once it ends.
TEST(CliCheckpoint, TwoRendersCannotShareOneCheckpoint) {
  fs::path d = dir() / "shared";
  fs::create_directories(d);
  const std::string ck = (d / "r.ckpt").string();
  pid_t first = spawnVkmc({"render", cornell(), "--width", "64", "--height", "64", "--spp", "512", "-q", "-o",
                           (d / "a.exr").string(), "--checkpoint", ck, "--checkpoint-every", "0.01"},
                          kHoldAfterCheckpoint);
  ASSERT_GT(first, 0);
  waitForFile(ck);
  RunResult second =
      runVkmc("render " + cornell() + " --width 16 --height 16 --spp 4 -q -o " + (d / "b.exr").string() + " --checkpoint " + ck);
  kill(first, SIGTERM);
  int status = 0;
  waitpid(first, &status, 0);
  EXPECT_EQ(second.code, 1) << second.err;
  EXPECT_NE(second.err.find("is in use by another vkmc render"), std::string::npos) << second.err;
  EXPECT_EQ(lines(second.err), 1) << second.err;
  EXPECT_FALSE(fs::exists(d / "b.exr"));
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGTERM) << status;
  EXPECT_FALSE(fs::exists(ck + ".lock"));
}

// SIGTERM while a periodic checkpoint is being written (a temporary of it exists: the sync point) stops the render
// gracefully: the write completes, then the EXR of the samples done and the final checkpoint are written. Before,
// the write swapped out the stop handler and a signal landing in one of lavapipe's threads killed the process with
// nothing written (0 of 6 trials wrote the EXR). Where the write ends before the signal lands, this checks less,
// never fails wrongly. 512 x 512 pixels make each checkpoint tens of MB, a write long enough to land in.
TEST(CliCheckpoint, ASignalDuringACheckpointWriteStopsTheRenderGracefully) {
  fs::path d = dir() / "during_write";
  fs::create_directories(d);
  const std::string ck = (d / "r.ckpt").string(), out = (d / "o.exr").string();
  pid_t pid = spawnVkmc({"render", cornell(), "--width", "512", "--height", "512", "--spp", "65536", "-q", "-o", out,
                         "--checkpoint", ck, "--checkpoint-every", "0.01"});
  ASSERT_GT(pid, 0);
  waitForFile(ck);  // the first checkpoint is written; the next write's temporary is what the signal waits for
  for (int i = 0; i < 600000 && !hasTemporaries(d); ++i) ::usleep(100);
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM);
  EXPECT_TRUE(fs::exists(out)) << "no EXR of the samples done";
  EXPECT_FALSE(hasTemporaries(d));
  RunResult resumable = runVkmc("render --resume " + ck + " --spp 4");
  EXPECT_NE(resumable.err.find("--spp cannot change a resumed render"), std::string::npos)
      << "the checkpoint was not read whole: " << resumable.err;
}
