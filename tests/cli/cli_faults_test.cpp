// Faults around a render: a full disk (a small tmpfs in a private mount namespace, never /dev/full), two
// processes writing the same output, SIGKILL mid-render, no Vulkan driver. Each ends with one clear line or a
// complete file, and never with a clobbered output or a leftover temporary.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include "support/cli_run.h"
#include "error.h"
#include "io/exr.h"

namespace fs = std::filesystem;
using namespace vkmc::test;

namespace {
fs::path dir() {
  static fs::path d = makeTempDir("faults");
  return d;
}

}  // namespace

TEST(CliFaults, AFullDiskFailsCleanlyAndKeepsTheOldOutput) {
  if (std::system("unshare -m --propagation private true 2>/dev/null") != 0) GTEST_SKIP() << "no private mount namespace here";
  fs::path d = dir() / "disk";
  fs::create_directories(d);
  // 64 KiB holds the old output but not a 256x256 EXR (~1 MB). The tmpfs exists only inside the namespace, so
  // the render, the old output and the listing all happen in there.
  std::string script = "mount -t tmpfs -o size=64k tmpfs " + d.string() + " && printf GOOD > " + d.string() + "/out.exr && " +
                       VKMC_BINARY + " render " + cornell() + " --spp 1 -q -o " + d.string() + "/out.exr 2>" +
                       (dir() / "disk.err").string() + "; echo rc=$?; cat " + d.string() + "/out.exr; echo; ls -a " + d.string();
  RunResult r = runShell("unshare -m --propagation private sh -c '" + script + "'");
  std::string err = slurp(dir() / "disk.err");
  EXPECT_NE(r.out.find("rc=1"), std::string::npos) << r.out << err;
  EXPECT_NE(err.find("No space left on device"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_NE(r.out.find("GOOD"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find(".vkmc-"), std::string::npos) << "a temporary was left behind: " << r.out;
}

TEST(CliFaults, TwoProcessesWritingOneOutputLeaveAWholeFile) {
  fs::path out = dir() / "shared.exr";
  std::vector<pid_t> pids;
  for (const char* seed : {"1", "2"})
    pids.push_back(spawnVkmc(
        {"render", cornell(), "--width", "64", "--height", "64", "--spp", "4", "--seed", seed, "-q", "-o", out.string()}));
  for (pid_t pid : pids) {
    ASSERT_GT(pid, 0);
    int status = 0;
    waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  }
  vkmc::ExrImage image;
  ASSERT_NO_THROW(image = vkmc::readExr(out.string()));
  EXPECT_EQ(image.width, 64);
  EXPECT_EQ(image.channels.count("R"), 1u);
  EXPECT_FALSE(hasTemporaries(dir()));
}

TEST(CliFaults, SigkillMidRenderKeepsTheOldOutput) {
  fs::path d = dir() / "kill";
  fs::create_directories(d);
  fs::path out = d / "out.exr";
  std::ofstream(out) << "GOOD";
  pid_t pid = spawnVkmc({"render", cornell(), "--spp", "100000", "-q", "-o", out.string(), "--report", (d / "r.json").string()});
  ASSERT_GT(pid, 0);
  std::this_thread::sleep_for(std::chrono::seconds(2));  // set-up or rendering: either way nothing is written yet
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(slurp(out), "GOOD");
  EXPECT_FALSE(fs::exists(d / "r.json"));
  EXPECT_FALSE(hasTemporaries(d));
}

TEST(CliFaults, NoVulkanDriverIsOneClearLine) {
  fs::path out = dir() / "nodevice.exr";
  RunResult r = runShell("VK_ICD_FILENAMES=" + (dir() / "no-such-icd.json").string() + " " + VKMC_BINARY + " render " +
                         cornell() + " --spp 1 -q -o " + out.string());
  const std::string& err = r.err;
  EXPECT_EQ(r.code, 1) << err;
  EXPECT_NE(err.find("Vulkan"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_FALSE(fs::exists(out));
}

// FIFOs (made in the test's own folder, never a /dev node) given as inputs: refused at once with one line, not
// blocked on (an open of a FIFO waits for a writer). `timeout` turns a hang into a failure, not a stuck suite.
TEST(CliFaults, FifosAsInputsAreRefusedNotBlockedOn) {
  fs::path d = makeTempDir("cli-fifo");
  const std::string fifo = (d / "pipe").string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const std::string out = " -o " + (d / "o.exr").string();
  for (const std::string& args :
       {"render " + cornell() + " --width 8 --height 8 --spp 1 -q --estimator " + fifo + out,
        "render " + cornell() + " --width 8 --height 8 --spp 1 -q --reference " + fifo + out,
        "render " + cornell() + " --width 8 --height 8 --spp 1 -q --checkpoint " + fifo + out, "compare " + fifo + " " + fifo}) {
    RunResult r = runShell("timeout 60 " + std::string(VKMC_BINARY) + " " + args);
    EXPECT_NE(r.code, 124) << "blocked on the FIFO: " << args;
    EXPECT_NE(r.code, 0) << args;
    EXPECT_NE(r.err.find("not a regular file"), std::string::npos) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}
