// glibc's malloc tuned for vkmc's allocations: transparent huge pages for its heaps, and a heap that grows and is
// trimmed in large steps (docs/performance.md, "Page faults"). On this project's virtual machines a page fault costs
// several microseconds; a 1M-triangle scene's load, BVH build and upload took 167k of them with 4 KiB pages.
// glibc reads GLIBC_TUNABLES only when a process starts, so vkmc executes itself once more with them added.
#pragma once

#include <string>

namespace vkmc {

// Called first in main: returns where no re-execution is needed or possible (tuned already, the user's own
// glibc.malloc tunables, VKMC_MALLOC_TUNING=off, not glibc 2.35 or later, a set-uid start, no /proc/self/exe);
// otherwise does not return. Keys the user set in GLIBC_TUNABLES are never overridden.
void tuneMallocByReexecuting(char** argv);

// The tunables vkmc added to this process ("glibc.malloc.hugetlb=1:..."), empty where it added none.
const std::string& mallocTunablesAdded();

}  // namespace vkmc
