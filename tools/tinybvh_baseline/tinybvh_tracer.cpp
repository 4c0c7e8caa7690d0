// Uploads a tinybvh layout once; each trace uploads the rays, dispatches, reads the hits back.
#include "tinybvh_tracer.h"

#include <algorithm>
#include <cstring>
#include <map>

#include "tinybvh_bindings.h"

namespace vkmc {

namespace {
vk::Buffer deviceBuffer(vk::Context& ctx, const void* data, size_t bytes) {
  vk::Buffer b(ctx, std::max<size_t>(bytes, 16), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::DeviceLocal);
  b.upload(data, bytes);
  return b;
}

TinybvhTracer::WalkStats summarize(std::span<const glm::uvec2> perRay) {
  TinybvhTracer::WalkStats w;
  if (perRay.empty()) return w;
  for (size_t i = 0; i < perRay.size(); i += 8) {
    glm::uvec2 slowest(0);
    for (size_t k = i; k < std::min(perRay.size(), i + 8); ++k) {
      w.iterations += perRay[k].x, w.triangleTests += perRay[k].y;
      slowest = glm::max(slowest, perRay[k]);
    }
    const double lanes = double(std::min<size_t>(8, perRay.size() - i));
    w.slowestLaneIterations += slowest.x * lanes, w.slowestLaneTriangleTests += slowest.y * lanes;
  }
  const double n = double(perRay.size());
  return {w.iterations / n, w.triangleTests / n, w.slowestLaneIterations / n, w.slowestLaneTriangleTests / n};
}
}  // namespace

TinybvhTracer::TinybvhTracer(vk::Context& ctx, std::string name, std::span<const uint32_t> spirv, uint32_t workgroupSize,
                             std::span<const glm::vec4> nodes, std::span<const uint32_t> indices,
                             std::span<const glm::vec4> triangles, bool walkStats)
    : ctx_(ctx), workgroupSize_(workgroupSize), counting_(walkStats) {
  layout_ = std::make_unique<vk::KernelLayout>(ctx);
  nodes_ = deviceBuffer(ctx, nodes.data(), nodes.size_bytes());
  indices_ = deviceBuffer(ctx, indices.data(), indices.size_bytes());
  triangles_ = deviceBuffer(ctx, triangles.data(), triangles.size_bytes());
  layout_->bindStorage(TINYBVH_BINDING_NODES, nodes_);
  layout_->bindStorage(TINYBVH_BINDING_INDICES, indices_);
  layout_->bindStorage(TINYBVH_BINDING_TRIANGLES, triangles_);
  kernel_ = std::make_unique<vk::Kernel>(ctx, *layout_, std::move(name), spirv, std::vector<vk::SpecConstant>{});
}

std::vector<glm::vec4> TinybvhTracer::trace(std::span<const gpu::TestRay> rays, double* gpuSeconds) {
  size_t n = rays.size();
  vk::Buffer in(ctx_, std::max<size_t>(n, 1) * sizeof(gpu::TestRay), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                vk::MemoryKind::HostVisible);
  vk::Buffer out(ctx_, std::max<size_t>(n, 1) * 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::HostVisible);
  if (n) std::memcpy(in.mapped(), rays.data(), n * sizeof(gpu::TestRay));
  layout_->bindStorage(TINYBVH_BINDING_RAYS, in);
  layout_->bindStorage(TINYBVH_BINDING_HITS, out);
  vk::Buffer stats(ctx_, std::max<size_t>(n, 1) * sizeof(glm::uvec2), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                   vk::MemoryKind::HostVisible);
  if (counting_) layout_->bindStorage(TINYBVH_BINDING_WALK_STATS, stats);
  gpu::PushConstants pc{};
  pc.pathCount = static_cast<uint32_t>(n);
  vk::GpuTimer timer(ctx_, 2);
  ctx_.runCommands([&](VkCommandBuffer cmd) {
    timer.reset(cmd);
    timer.begin(cmd, "trace");  // as RayTracer brackets its dispatches (binding and barrier included)
    vk::dispatch(cmd, *layout_, *kernel_, &pc, sizeof(pc), static_cast<uint32_t>((n + workgroupSize_ - 1) / workgroupSize_));
    timer.end(cmd);
  });
  std::map<std::string, double> seconds;
  timer.collect(seconds);
  if (gpuSeconds) *gpuSeconds = seconds.empty() ? 0.0 : seconds.begin()->second;
  if (counting_) walkStats_ = summarize(std::span(static_cast<const glm::uvec2*>(stats.mapped()), n));
  std::vector<glm::vec4> hits(n);
  if (n) std::memcpy(hits.data(), out.mapped(), n * 16);
  return hits;
}

}  // namespace vkmc
