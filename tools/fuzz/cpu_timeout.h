// A per-input timeout in CPU time, for the harnesses: libFuzzer's -timeout counts wall time, which a busy machine
// stretches into false findings. ITIMER_VIRTUAL counts this process's user CPU time only; when one input has used
// kCpuSecondsPerInput of it, the harness aborts with a line saying so (libFuzzer keeps the input as a finding).
#pragma once
#include <signal.h>
#include <sys/time.h>
#include <unistd.h>

#include <cstdlib>

namespace vkmc::fuzz {

constexpr int kCpuSecondsPerInput = 10;

inline void onCpuTimeout(int) {
  const char line[] = "fuzz: one input used more than its CPU-time limit (a hang)\n";
  (void)!::write(STDERR_FILENO, line, sizeof(line) - 1);
  std::abort();
}

// Armed at the start of each input, disarmed at its end (RAII).
struct CpuTimeout {
  CpuTimeout() {
    static bool installed = (::signal(SIGVTALRM, onCpuTimeout), true);
    (void)installed;
    itimerval t{};
    t.it_value.tv_sec = kCpuSecondsPerInput;
    ::setitimer(ITIMER_VIRTUAL, &t, nullptr);
  }
  ~CpuTimeout() {
    itimerval off{};
    ::setitimer(ITIMER_VIRTUAL, &off, nullptr);
  }
};

}  // namespace vkmc::fuzz
