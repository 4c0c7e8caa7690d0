// A parallel loop whose work division does not depend on the thread count: fixed chunks, taken in turn.
#pragma once
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace vkmc {

// Calls fn(begin, end) for each chunk [k * chunk, min(n, (k + 1) * chunk)) of [0, n) on up to `threads` threads
// (the caller's included). Which thread runs a chunk varies; the chunks do not. The first exception thrown is
// rethrown here after every thread has stopped.
template <typename Fn>
void parallelChunks(size_t n, size_t chunk, unsigned threads, Fn&& fn) {
  const size_t chunks = chunk ? (n + chunk - 1) / chunk : 0;
  std::atomic<size_t> next{0};
  std::exception_ptr failure;
  std::mutex failureMutex;
  auto work = [&] {
    for (size_t k; (k = next.fetch_add(1)) < chunks;) {
      try {
        fn(k * chunk, std::min(n, (k + 1) * chunk));
      } catch (...) {
        std::lock_guard lock(failureMutex);
        if (!failure) failure = std::current_exception();
        next = chunks;  // stop handing out work
      }
    }
  };
  std::vector<std::thread> workers;
  try {
    for (size_t w = 1; w < std::min<size_t>(threads, chunks); ++w) workers.emplace_back(work);
  } catch (...) {  // no thread to be had: the threads started and this one do the work
  }
  work();
  for (std::thread& w : workers) w.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace vkmc
