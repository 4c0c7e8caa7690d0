// glibc's malloc tuned for vkmc's allocations: transparent huge pages for its heaps, which grow in large steps
// (docs/journal/performance.md, "Page faults"). On this project's virtual machines a page fault costs microseconds; a
// 1M-triangle scene's load, BVH build and upload took 166k of them with 4 KiB pages. glibc reads GLIBC_TUNABLES only
// when a process starts, so vkmc starts itself once more, by its own path (same pid, same name), with them added.
#pragma once

#include <string>

namespace vkmc {

// Called first in main. Returns where it restarts nothing: started by itself already, VKMC_MALLOC_TUNING=off, a
// set-uid start, glibc older than 2.35 or another malloc in place (valgrind's, a sanitizer's), started through
// the dynamic loader, or every key set by the user (in GLIBC_TUNABLES or the older MALLOC_*_ variables), whose
// keys are never overridden; and where exec fails. Otherwise does not return.
void tuneMallocByReexecuting(char** argv);

// The tunables vkmc added to this process ("glibc.malloc.hugetlb=1:..."), empty where it added none.
const std::string& mallocTunablesAdded();

}  // namespace vkmc
