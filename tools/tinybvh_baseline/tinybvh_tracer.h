// One tinybvh traversal kernel on vkmc's device, its layout's buffers bound: traces arrays of rays, timed by GPU
// timestamps around the dispatch as bench/ray_tracer.h times vkmc's kernel.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "../shaders/shared/layout.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/kernel.h"

namespace vkmc {

class TinybvhTracer {
 public:
  // indices: empty for a kernel that reads none (CWBVH). workgroupSize: the kernel's local_size_x. walkStats: the
  // spirv is a counting variant (TINYBVH_WALK_STATS), see walkStats().
  TinybvhTracer(vk::Context& ctx, std::string name, std::span<const uint32_t> spirv, uint32_t workgroupSize,
                std::span<const glm::vec4> nodes, std::span<const uint32_t> indices, std::span<const glm::vec4> triangles,
                bool walkStats = false);
  // Returns (t, u, v, triangle bits) per ray, t = gpu::kTinybvhFar on a miss (u, v and the triangle then undefined,
  // as tinybvh leaves them). gpuSeconds: the dispatch's time.
  std::vector<glm::vec4> trace(std::span<const gpu::TestRay> rays, double* gpuSeconds = nullptr);
  const std::string& name() const { return kernel_->name(); }
  // Per ray of the last trace() of a counting variant: loop iterations, triangle tests, and the iterations and
  // triangle tests of the slowest of each 8 consecutive rays (a subgroup on lavapipe, which pays its slowest lane),
  // as RayTracer counts.
  struct WalkStats {
    double iterations = 0, triangleTests = 0, slowestLaneIterations = 0, slowestLaneTriangleTests = 0;
  };
  WalkStats walkStats() const { return walkStats_; }

 private:
  vk::Context& ctx_;
  uint32_t workgroupSize_;
  std::unique_ptr<vk::KernelLayout> layout_;
  std::unique_ptr<vk::Kernel> kernel_;
  vk::Buffer nodes_, indices_, triangles_;
  bool counting_;
  WalkStats walkStats_;
};

}  // namespace vkmc
