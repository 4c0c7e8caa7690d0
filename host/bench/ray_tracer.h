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
  // binaryBvh: walk the binary node layout (the scene must keep it) instead of the 4-wide one. walkStats: count
  // the 4-wide walk's steps (a kernel variant of its own; see walkStats()).
  RayTracer(vk::Context& ctx, const GpuScene& scene, bool binaryBvh = false, bool walkStats = false);
  ~RayTracer();
  // Returns (t, b1, b2, triangle bits) per ray, triangle = kMissPrimitive on a miss. gpuSeconds: kernel time.
  std::vector<glm::vec4> trace(std::span<const gpu::TestRay> rays, bool anyHit, double* gpuSeconds = nullptr);
  // Rays of the last trace() whose walk outgrew the register stack and ran in the deep pass.
  uint32_t deepWalks() const { return deepWalks_; }
  // Per ray of the last trace() with walkStats: loop iterations, node steps, triangle tests, and the iterations
  // of the slowest lane of its subgroup (what the subgroup pays, the walk being SIMD on lavapipe).
  struct WalkStats {
    double iterations = 0, nodeSteps = 0, triangleTests = 0, slowestLaneIterations = 0;
  };
  WalkStats walkStats() const { return walkStats_; }

 private:
  vk::Context& ctx_;
  const GpuScene& scene_;
  std::unique_ptr<vk::KernelLayout> layout_;
  std::unique_ptr<vk::Kernel> closest_, any_, closestDeep_, anyDeep_;
  vk::Buffer dummy_, control_;
  std::vector<vk::Buffer> texelDummies_;  // viewed placeholders on the renderer's texel bindings
  uint32_t deepWalks_ = 0;
  WalkStats walkStats_;
};

}  // namespace vkmc
