#include "app/malloc_tuning.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <dlfcn.h>
#include <unistd.h>
#if defined(__GLIBC__)
#include <gnu/libc-version.h>
#include <sys/auxv.h>
#endif

namespace vkmc {

namespace {

// One row per tunable (glibc.malloc.<name>), with the older variable that also sets it (GLIBC_TUNABLES would win
// over it, so a user's variable counts as the user's key). Measured together: docs/journal/performance.md, "Page faults".
struct Tunable {
  const char* name;
  const char* value;
  const char* oldVariable;
};
constexpr Tunable kTunables[] = {
    {"hugetlb", "1", nullptr},                                 // madvise(MADV_HUGEPAGE) on the heaps: 2 MiB pages
    {"top_pad", "67108864", "MALLOC_TOP_PAD_"},                // the heap grows 64 MiB at a time, so its pages can be huge
    {"mmap_threshold", "33554432", "MALLOC_MMAP_THRESHOLD_"},  // blocks under 32 MiB (glibc's largest) from the heap
};
constexpr const char* kMarker = "VKMC_MALLOC_TUNED";  // set for the restarted process: what was added

std::string& added() {
  static std::string s;
  return s;
}

bool glibcMallocInUse() {
#if defined(__GLIBC__)
  int major = 0, minor = 0;
  if (std::sscanf(gnu_get_libc_version(), "%d.%d", &major, &minor) != 2) return false;
  if (major < 2 || (major == 2 && minor < 35)) return false;  // glibc.malloc.hugetlb came in 2.35
  // Not where another malloc is in place (valgrind's, a sanitizer's, jemalloc through LD_PRELOAD): its tunables
  // would do nothing, and a restart would leave valgrind behind.
  Dl_info info{};
  void* mallocInUse = dlsym(RTLD_DEFAULT, "malloc");
  return mallocInUse && dladdr(mallocInUse, &info) && info.dli_fname && std::strstr(info.dli_fname, "/libc.so");
#else
  return false;
#endif
}

bool secureStart() {
#if defined(__GLIBC__)
  return getauxval(AT_SECURE) != 0;  // glibc drops malloc tunables there
#else
  return true;
#endif
}

// The binary to start again, by its own path, so the process keeps its name (exec names it after the path's last
// part: "/proc/self/exe" would make it "exe"). Empty where that is not this program: started through the dynamic
// loader (`ld-linux-x86-64.so.2 ./vkmc`), or replaced on disk since.
std::string ownPath() {
  char buf[4096];
  ssize_t n = readlink("/proc/self/exe", buf, sizeof(buf) - 1);
  if (n <= 0) return {};
  std::string path(buf, size_t(n));
  const std::string name = path.substr(path.find_last_of('/') + 1);
  if (name.rfind("ld-", 0) == 0 || path.find(" (deleted)") != std::string::npos) return {};
  return path;
}

}  // namespace

void tuneMallocByReexecuting(char** argv) {
  if (const char* marker = std::getenv(kMarker)) {  // the second start: never a third
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    if (tunables && *marker && std::strstr(tunables, marker)) added() = marker;
    unsetenv(kMarker);
    return;
  }
  const char* mode = std::getenv("VKMC_MALLOC_TUNING");
  if ((mode && std::strcmp(mode, "off") == 0) || secureStart() || !glibcMallocInUse()) return;
  const char* given = std::getenv("GLIBC_TUNABLES");
  const std::string user = given ? given : "";
  std::string extra;
  for (const Tunable& t : kTunables) {
    const std::string key = std::string("glibc.malloc.") + t.name + "=";
    const bool usersKey = (":" + user).find(":" + key) != std::string::npos || (t.oldVariable && std::getenv(t.oldVariable));
    if (!usersKey) extra += (extra.empty() ? "" : ":") + key + t.value;
  }
  const std::string path = ownPath();
  if (extra.empty() || path.empty()) return;
  const std::string combined = user.empty() ? extra : user + ":" + extra;
  if (setenv("GLIBC_TUNABLES", combined.c_str(), 1) != 0 || setenv(kMarker, extra.c_str(), 1) != 0) return;
  execv(path.c_str(), argv);
  // exec failed: run as started, untuned.
  unsetenv(kMarker);
  if (given)
    setenv("GLIBC_TUNABLES", user.c_str(), 1);
  else
    unsetenv("GLIBC_TUNABLES");
}

const std::string& mallocTunablesAdded() { return added(); }

}  // namespace vkmc
