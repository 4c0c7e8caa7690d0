// llvmpipe compiles a kernel at its first dispatch, on the thread of its one queue, and Mesa's disk cache keeps
// the result. A BackgroundWarmUp compiles kernels on a second device in a helper thread while the caller compiles
// others on its own device; the caller's first dispatch of a kernel warmed here then reads it from the cache.
// Set-up time on a cold cache becomes the larger of the two shares instead of their sum. Best effort: if the
// helper fails, or the cache is off, the caller just compiles those kernels itself.
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "vk/kernel.h"

namespace vkmc {

struct KernelSource {
  std::string name;
  std::span<const uint32_t> spirv;
  std::vector<vk::SpecConstant> specs;
};

class BackgroundWarmUp {
 public:
  explicit BackgroundWarmUp(std::vector<KernelSource> kernels);
  ~BackgroundWarmUp();  // waits
  BackgroundWarmUp(const BackgroundWarmUp&) = delete;
  BackgroundWarmUp& operator=(const BackgroundWarmUp&) = delete;
  void wait();  // returns once the helper's device is gone (its cache entries written)

 private:
  std::thread thread_;
};

// True on devices that compile at first dispatch and share Mesa's disk cache (llvmpipe).
bool compilesAtFirstDispatch(const vk::Context& ctx);

}  // namespace vkmc
