// Runs the vkmc binary for end-to-end tests: exit code, stdout and stderr.
#pragma once
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "test_scenes.h"

namespace vkmc::test {

struct RunResult {
  int code;  // -1: killed by a signal
  std::string out, err;
};

inline std::filesystem::path workDir() {
  static std::filesystem::path d = makeTempDir("cli");
  return d;
}

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A shell command line (its stdout and stderr captured, stdin empty).
inline RunResult runShell(const std::string& command) {
  std::filesystem::path out = workDir() / "stdout.txt", err = workDir() / "stderr.txt";
  std::string cmd = "( " + command + " ) >" + out.string() + " 2>" + err.string() + " </dev/null";
  int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
}

inline RunResult runVkmc(const std::string& args) { return runShell(std::string(VKMC_BINARY) + " " + args); }

// Whether a folder holds a temporary of vkmc's output commit (io/output_files.h names them .vkmc-*).
inline bool hasTemporaries(const std::filesystem::path& d) {
  for (const auto& f : std::filesystem::directory_iterator(d))
    if (f.path().filename().string().rfind(".vkmc-", 0) == 0) return true;
  return false;
}

// Starts vkmc with these arguments without waiting (for signals and races), with `env` ("NAME=value") added to the
// environment; -1 when it could not start.
inline pid_t spawnVkmc(std::vector<std::string> args, const std::vector<std::string>& env = {}) {
  args.insert(args.begin(), VKMC_BINARY);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> envCopy(env);
  std::vector<char*> envp;
  for (char** e = ::environ; *e; ++e) envp.push_back(*e);  // ::environ: unistd.h
  for (std::string& e : envCopy) envp.push_back(e.data());
  envp.push_back(nullptr);
  // SIGINT and SIGTERM at their defaults: a test run from a background shell inherits SIGINT ignored, and vkmc
  // keeps an ignored signal ignored (nohup), which would make the signal tests fail.
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF);
  pid_t pid = -1;
  int failed = posix_spawn(&pid, VKMC_BINARY, nullptr, &attr, argv.data(), envp.data());
  posix_spawnattr_destroy(&attr);
  return failed ? -1 : pid;
}

// The environment under which vkmc waits for a signal after its first checkpoint (command_render.cpp): a signal
// sent once the checkpoint exists lands in a render that is certainly still running.
inline const std::vector<std::string> kHoldAfterCheckpoint = {"VKMC_HOLD_AFTER_CHECKPOINT=1"};

// Waits until `path` exists (a hang guard of minutes, not a timing assumption).
inline void waitForFile(const std::filesystem::path& path) {
  for (int i = 0; i < 6000 && !std::filesystem::exists(path); ++i) ::usleep(50000);
}

inline std::string cornell() { return std::string(VKMC_SOURCE_DIR) + "/scenes/cornell_box.gltf"; }

}  // namespace vkmc::test
