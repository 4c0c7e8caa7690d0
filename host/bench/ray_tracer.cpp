// Ray-array tracing with the trace_rays kernel.
#include "bench/ray_tracer.h"

#include <cstring>
#include <map>

#include "error.h"
#include "spirv/trace_rays_bvh2_spv.h"
#include "spirv/trace_rays_deep_spv.h"
#include "spirv/trace_rays_spv.h"

namespace vkmc {

RayTracer::RayTracer(vk::Context& ctx, const GpuScene& scene, bool binaryBvh, bool walkStats) : ctx_(ctx), scene_(scene) {
  layout_ = std::make_unique<vk::KernelLayout>(ctx);
  scene.bindTo(*layout_, binaryBvh);
  // The kernel declares every binding of the shared set; those it never touches still need a buffer.
  dummy_ = vk::Buffer(ctx, 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::DeviceLocal);
  for (uint32_t b : {BINDING_PATHS, BINDING_HITS, BINDING_RAY_QUEUES, BINDING_SHADOW_QUEUE, BINDING_FILM, BINDING_ROULETTE_TABLE,
                     BINDING_DEPTH_STATS, BINDING_QUEUE_STATS})
    layout_->bindStorage(b, dummy_);
  for (uint32_t b : gpu::kRendererTexelBindings) {
    texelDummies_.emplace_back(ctx, 256, VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT, vk::MemoryKind::DeviceLocal);
    texelDummies_.back().createView(sceneTexelFormat(b));
    layout_->bindTexel(b, texelDummies_.back());
  }
  // The deep pass's dispatch arguments and counters (the trace kernels use nothing else of Control).
  control_ = vk::Buffer(ctx, sizeof(gpu::Control), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                        vk::MemoryKind::HostVisible);
  layout_->bindStorage(BINDING_CONTROL, control_);
  std::span<const uint32_t> spirv =
      binaryBvh ? std::span<const uint32_t>(kSpirv_trace_rays_bvh2) : std::span<const uint32_t>(kSpirv_trace_rays);
  // Two-sided, as the host walks and Embree's rtcIntersect1 are; the alpha test only where a triangle needs it, as
  // the renderer's kernels are specialized.
  // The register stack sized to the tree and the deep pass only where a walk can outgrow it, as the renderer's
  // walks are specialized (pipelineFeatures).
  const uint32_t alpha = scene.info().alphaTested ? 1u : 0u, stack = scene.info().registerStackEntries;
  const uint32_t deep = scene.info().deepWalks ? 1u : 0u;
  auto specs = [alpha, stack, deep](bool anyHit, bool counting) {
    return std::vector<vk::SpecConstant>{{SPEC_WORKGROUP_SIZE, gpu::kWorkgroupSize},
                                         {SPEC_ANY_HIT, anyHit},
                                         {SPEC_WALK_STATS, counting},
                                         {SPEC_CULLS_BACK_FACES, 0u},
                                         {SPEC_HAS_ALPHA, alpha},
                                         {SPEC_REGISTER_STACK, stack},
                                         {SPEC_DEEP_WALKS, deep}};
  };
  closest_ = std::make_unique<vk::Kernel>(ctx, *layout_, "trace_closest", spirv, specs(false, walkStats));
  any_ = std::make_unique<vk::Kernel>(ctx, *layout_, "trace_any", spirv, specs(true, walkStats));
  // The binary walk keeps its stack in memory and never defers; the 4-wide one defers walks that outgrow its
  // register stack to a second, indirect dispatch of the deep variant (where one can).
  if (!binaryBvh && deep) {
    closestDeep_ = std::make_unique<vk::Kernel>(ctx, *layout_, "trace_closest_deep", kSpirv_trace_rays_deep, specs(false, false));
    anyDeep_ = std::make_unique<vk::Kernel>(ctx, *layout_, "trace_any_deep", kSpirv_trace_rays_deep, specs(true, false));
  }
}

RayTracer::~RayTracer() = default;

std::vector<glm::vec4> RayTracer::trace(std::span<const gpu::TestRay> rays, bool anyHit, double* gpuSeconds) {
  size_t n = rays.size();
  // Read through a texel view (trace_rays.comp), two rgba32ui texels a ray.
  if (2 * n > ctx_.properties().limits.maxTexelBufferElements)
    throw Error("too many rays for one dispatch: " + std::to_string(n) + " need " + std::to_string(2 * n) +
                " texels, the device allows " + std::to_string(ctx_.properties().limits.maxTexelBufferElements));
  vk::Buffer in(ctx_, std::max<size_t>(n, 1) * sizeof(gpu::TestRay),
                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT, vk::MemoryKind::HostVisible);
  in.createView(sceneTexelFormat(BINDING_PATH_TEXELS));
  vk::Buffer out(ctx_, std::max<size_t>(n, 1) * 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::HostVisible);
  if (n) std::memcpy(in.mapped(), rays.data(), n * sizeof(gpu::TestRay));
  layout_->bindStorage(BINDING_TEST_RAYS, in);
  layout_->bindTexel(BINDING_PATH_TEXELS, in);
  layout_->bindStorage(BINDING_TEST_HITS, out);
  vk::Buffer deep(ctx_, std::max<size_t>(n, 1) * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                  vk::MemoryKind::DeviceLocal);
  layout_->bindStorage(BINDING_DEEP_WALKS, deep);
  auto* control = static_cast<gpu::Control*>(control_.mapped());
  std::memset(control, 0, sizeof(gpu::Control));
  control->deepArgs = glm::uvec4(0u, 1u, 1u, 0u);
  gpu::PushConstants pc{};
  pc.pathCount = static_cast<uint32_t>(n);
  vk::GpuTimer timer(ctx_, 2);
  ctx_.runCommands([&](VkCommandBuffer cmd) {
    timer.reset(cmd);
    timer.begin(cmd, "trace");  // both passes
    vk::dispatch(cmd, *layout_, anyHit ? *any_ : *closest_, &pc, sizeof(pc),
                 static_cast<uint32_t>((n + gpu::kWorkgroupSize - 1) / gpu::kWorkgroupSize));
    if (closestDeep_)
      vk::dispatchIndirect(cmd, *layout_, anyHit ? *anyDeep_ : *closestDeep_, &pc, sizeof(pc), control_,
                           offsetof(gpu::Control, deepArgs));
    timer.end(cmd);
  });
  deepWalks_ = control->deepWalksDeferred;
  const double perRay = n ? 1.0 / double(n) : 0.0;
  walkStats_ = {control->walkIterations * perRay, control->walkNodeSteps * perRay, control->walkTriangleTests * perRay,
                control->walkSlowestLaneIterations * perRay};
  if (control->deepWalksTraced != control->deepWalksDeferred)
    throw Error("internal error: " + std::to_string(control->deepWalksDeferred) + " walks deferred, " +
                std::to_string(control->deepWalksTraced) + " traced by the deep pass");
  std::map<std::string, double> seconds;
  timer.collect(seconds);
  if (gpuSeconds) *gpuSeconds = seconds.empty() ? 0.0 : seconds.begin()->second;
  std::vector<glm::vec4> hits(n);
  if (n) std::memcpy(hits.data(), out.mapped(), n * 16);
  return hits;
}

}  // namespace vkmc
