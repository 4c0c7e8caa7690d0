#include "render/background_warm_up.h"

#include <cstring>

#include "../shaders/shared/layout.h"
#include "render/gpu_scene.h"
#include "vk/buffer.h"
#include "vk/context.h"

namespace vkmc {

namespace {
// One empty dispatch of each kernel on a device of its own. Zero push constants and zeroed buffers: every kernel
// finds empty queues and returns, as in the renderer's own warm-up; the texel bindings get the formats the
// renderer uses, so the compiled variants are the ones it will look up.
void warmOnSecondDevice(const std::vector<KernelSource>& kernels) {
  vk::Context ctx;
  vk::KernelLayout layout(ctx);
  // Not a power of two: llvmpipe keys a compiled variant on whether each texel buffer's size is one, and a
  // scene's buffers almost never are.
  constexpr VkDeviceSize kBytes = (1 << 16) + 48;
  vk::Buffer storage(ctx, kBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::HostVisible);
  std::memset(storage.mapped(), 0, kBytes);
  for (uint32_t b = 0; b < BINDING_COUNT; ++b)
    if (!vk::isTexelBinding(b) && !vk::isImageBinding(b)) layout.bindStorage(b, storage);
  std::vector<vk::Buffer> views;
  for (uint32_t binding : gpu::kTexelBindings) {
    views.emplace_back(ctx, kBytes, VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT, vk::MemoryKind::HostVisible);
    std::memset(views.back().mapped(), 0, kBytes);
    views.back().createView(sceneTexelFormat(binding));
    layout.bindTexel(binding, views.back());
  }
  // The renderer's image formats and samplers: llvmpipe keys variants on them too.
  const uint32_t white = 0xffffffffu;
  vk::ArrayImage pages(ctx, 1, 1, 1, &white);
  vk::Sampler bilinear(ctx, VK_FILTER_LINEAR);
  bindTexturePages(layout, pages, bilinear);
  gpu::PushConstants pc{};
  for (const KernelSource& k : kernels) {
    vk::Kernel kernel(ctx, layout, k.name, k.spirv, k.specs);
    ctx.runCommands([&](VkCommandBuffer cmd) { vk::dispatch(cmd, layout, kernel, &pc, sizeof(pc), 1); });
  }
}
}  // namespace

BackgroundWarmUp::BackgroundWarmUp(std::vector<KernelSource> kernels) {
  if (kernels.empty()) return;
  thread_ = std::thread([kernels = std::move(kernels)] {
    try {
      warmOnSecondDevice(kernels);
    } catch (...) {  // best effort: the caller compiles whatever is not in the cache
    }
  });
}

BackgroundWarmUp::~BackgroundWarmUp() { wait(); }

void BackgroundWarmUp::wait() {
  if (thread_.joinable()) thread_.join();
}

bool compilesAtFirstDispatch(const vk::Context& ctx) { return ctx.deviceName().find("llvmpipe") != std::string::npos; }

}  // namespace vkmc
