// `vkmc bench-kernels`: per scene, the set-up split and the medians of samples/s and Mrays/s over runs.
#pragma once
#include <string>
#include <vector>

namespace vkmc {

struct BenchOptions {
  std::vector<std::string> scenes;
  int runs = 5;
  int spp = 4;
  int width = 256;
  int height = 256;
  std::string jsonPath;
  bool specialization = false;                        // compare specialized with general pipelines instead
  uint32_t workgroupSize = 0;                         // 0: the device's (device_tuning.h)
  uint32_t wavefrontPaths = 0;                        // 0: the device's
  bool sah = false;                                   // BVH quality instead: binned against full-sweep SAH cost
  std::vector<std::string> integrators{"wavefront"};  // each is benchmarked, interleaved run by run
};

int runBenchKernels(const BenchOptions& options);

}  // namespace vkmc
