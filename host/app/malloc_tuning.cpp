#include "app/malloc_tuning.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <unistd.h>
#if defined(__GLIBC__)
#include <gnu/libc-version.h>
#include <sys/auxv.h>
#endif

namespace vkmc {

namespace {

// One row per tunable (glibc.malloc.<name>), measured together (docs/performance.md, "Page faults").
struct Tunable {
  const char* name;
  const char* value;
};
constexpr Tunable kTunables[] = {
    {"hugetlb", "1"},                  // madvise(MADV_HUGEPAGE) on the heaps: 2 MiB pages where the kernel allows
    {"top_pad", "67108864"},           // the heap grows 64 MiB at a time, so that its pages can be huge
    {"trim_threshold", "268435456"},   // up to 256 MiB of freed memory stays mapped instead of faulting in again
    {"mmap_threshold", "33554432"},    // blocks under 32 MiB come from the heap, not from a fresh mapping each
};
constexpr const char* kMarker = "VKMC_MALLOC_TUNED";  // set for the re-executed process: what was added

std::string& added() {
  static std::string s;
  return s;
}

bool glibcHasHugetlbTunable() {
#if defined(__GLIBC__)
  int major = 0, minor = 0;
  if (std::sscanf(gnu_get_libc_version(), "%d.%d", &major, &minor) != 2) return false;
  return major > 2 || (major == 2 && minor >= 35);  // glibc.malloc.hugetlb came in 2.35
#else
  return false;
#endif
}

bool secureStart() {
#if defined(__GLIBC__)
  return getauxval(AT_SECURE) != 0;  // glibc ignores GLIBC_TUNABLES there
#else
  return true;
#endif
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
  if ((mode && std::strcmp(mode, "off") == 0) || !glibcHasHugetlbTunable() || secureStart()) return;
  const char* given = std::getenv("GLIBC_TUNABLES");
  const std::string user = given ? given : "";
  std::string extra;
  for (const Tunable& t : kTunables) {
    const std::string key = std::string("glibc.malloc.") + t.name + "=";
    if (user.find(key) != std::string::npos) continue;  // the user's choice stands
    extra += (extra.empty() ? "" : ":") + key + t.value;
  }
  if (extra.empty()) return;
  const std::string combined = user.empty() ? extra : user + ":" + extra;
  if (setenv("GLIBC_TUNABLES", combined.c_str(), 1) != 0 || setenv(kMarker, extra.c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);
  // Not re-executed (no /proc): run as started, untuned.
  unsetenv(kMarker);
  if (given)
    setenv("GLIBC_TUNABLES", user.c_str(), 1);
  else
    unsetenv("GLIBC_TUNABLES");
}

const std::string& mallocTunablesAdded() { return added(); }

}  // namespace vkmc
