// Traces arrays of rays through the GPU traversal (closest or any hit): for tests against brute force and for
// traversal benchmarks on dumped rays.
#pragma once
#include <glm/glm.hpp>

#include <memory>
#include <span>
#include <vector>

#include "../shaders/shared/layout.h"
#include "render/gpu_scene.h"
#include "vk/kernel.h"

namespace vkmc {

class RayTracer {
 public:
  // binaryBvh: walk the binary node layout (the scene must keep it) instead of the 4-wide one.
  RayTracer(vk::Context& ctx, const GpuScene& scene, bool binaryBvh = false);
  ~RayTracer();
  // Returns (t, b1, b2, triangle bits) per ray, triangle = kMissPrimitive on a miss. gpuSeconds: kernel time.
  std::vector<glm::vec4> trace(std::span<const gpu::TestRay> rays, bool anyHit, double* gpuSeconds = nullptr);
  // Rays of the last trace() whose walk outgrew the register stack and ran in the deep pass.
  uint32_t deepWalks() const { return deepWalks_; }

 private:
  vk::Context& ctx_;
  const GpuScene& scene_;
  std::unique_ptr<vk::KernelLayout> layout_;
  std::unique_ptr<vk::Kernel> closest_, any_, closestDeep_, anyDeep_;
  vk::Buffer dummy_, control_;
  uint32_t deepWalks_ = 0;
};

}  // namespace vkmc
