// The texture-form benchmark: lookups, the texel-buffer copy of the pages, interleaved timed dispatches.
#include "bench/texture_forms.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <memory>
#include <numeric>
#include <random>

#include "bvh/bvh.h"
#include "error.h"
#include "render/gpu_scene.h"
#include "render/gpu_textures.h"
#include "spirv/texture_forms_spv.h"
#include "spirv/texture_forms_texel_buffer_spv.h"
#include "vk/buffer.h"
#include "vk/kernel.h"

namespace vkmc {

namespace {

uint32_t slotTexture(const TextureRef& ref) { return ref.present() ? uint32_t(ref.texture) : gpu::kNoTexture; }

// Bits of x spread to the even positions (x < 2^16).
uint32_t spreadBits(uint32_t x) {
  x = (x | (x << 8)) & 0x00ff00ffu;
  x = (x | (x << 4)) & 0x0f0f0f0fu;
  x = (x | (x << 2)) & 0x33333333u;
  return (x | (x << 1)) & 0x55555555u;
}
uint32_t mortonOfUv(glm::vec2 uv) {
  auto cell = [](float u) { return uint32_t(std::clamp((u - std::floor(u)) * 65536.0f, 0.0f, 65535.0f)); };
  return spreadBits(cell(uv.x)) | (spreadBits(cell(uv.y)) << 1);
}

}  // namespace

std::vector<gpu::TestRay> makeTextureLookups(const Scene& scene, uint32_t count, bool coherent, uint32_t seed) {
  std::vector<double> areas(scene.triangleCount());
  for (size_t i = 0; i < areas.size(); ++i) {
    const glm::vec3* p = &scene.positions[3 * i];
    areas[i] = 0.5 * double(glm::length(glm::cross(p[1] - p[0], p[2] - p[0])));
  }
  if (areas.empty() || !scene.hasUv0()) throw Error("bench-textures: the scene has no textured triangles");
  std::discrete_distribution<size_t> pickTriangle(areas.begin(), areas.end());
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  struct Keyed {
    uint64_t key;
    gpu::TestRay ray;
  };
  std::vector<Keyed> out;
  out.reserve(count);
  for (uint32_t i = 0; i < count; ++i) {
    size_t t = pickTriangle(rng);
    float u = unit(rng), v = unit(rng);
    if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
    glm::vec2 uv = (1.0f - u - v) * scene.uv0[3 * t] + u * scene.uv0[3 * t + 1] + v * scene.uv0[3 * t + 2];
    const Material& m = scene.materials[scene.materialIds[t]];
    gpu::TestRay r{};
    r.origin = glm::vec4(uv, 0.0f, 0.0f);
    r.direction = glm::vec4(
        std::bit_cast<float>(slotTexture(m.baseColorTexture)), std::bit_cast<float>(slotTexture(m.metallicRoughnessTexture)),
        std::bit_cast<float>(slotTexture(m.normalTexture)), std::bit_cast<float>(slotTexture(m.emissiveTexture)));
    out.push_back({(uint64_t(scene.materialIds[t]) << 32) | mortonOfUv(uv), r});
  }
  if (coherent) std::sort(out.begin(), out.end(), [](const Keyed& a, const Keyed& b) { return a.key < b.key; });
  std::vector<gpu::TestRay> rays(out.size());
  std::transform(out.begin(), out.end(), rays.begin(), [](const Keyed& k) { return k.ray; });
  return rays;
}

uint64_t countTextureLookups(const std::vector<gpu::TestRay>& lookups) {
  uint64_t n = 0;
  for (const gpu::TestRay& r : lookups)
    for (int k = 0; k < 4; ++k) n += std::bit_cast<uint32_t>(r.direction[k]) != gpu::kNoTexture ? 1 : 0;
  return n;
}

std::vector<TextureFormTiming> timeTextureForms(vk::Context& ctx, const Scene& scene, const std::vector<gpu::TestRay>& lookups,
                                                int rounds) {
  Bvh bvh = buildBvh(scene.triangleBounds());
  GpuScene gpuScene(ctx, scene, bvh);  // the texture pages as the renderer samples them
  vk::KernelLayout layout(ctx);
  vk::Buffer placeholder(ctx, 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::DeviceLocal);
  for (uint32_t b = 0; b < BINDING_COUNT; ++b)
    if (!vk::isTexelBinding(b) && !vk::isImageBinding(b)) layout.bindStorage(b, placeholder);
  gpuScene.bindTo(layout);
  // The same pages' texels for the texel-buffer form (the same packing as GpuScene's).
  const VkPhysicalDeviceLimits& limits = ctx.properties().limits;
  PackedTextures packed = packTextures(scene.textures, limits.maxImageDimension2D, limits.maxImageArrayLayers);
  std::string texelSkip = packed.atlas.texels.size() > limits.maxTexelBufferElements || packed.atlas.texels.size() > (1u << 31)
                              ? "the pages exceed the device's texel-buffer size"
                              : "";
  vk::Buffer texels;
  if (texelSkip.empty()) {
    texels =
        vk::Buffer(ctx, packed.atlas.texels.size() * 4, VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT, vk::MemoryKind::DeviceLocal);
    texels.upload(packed.atlas.texels.data(), packed.atlas.texels.size() * 4);
    texels.createView(sceneTexelFormat(BINDING_TEXTURE_TEXELS));
    layout.bindTexel(BINDING_TEXTURE_TEXELS, texels);
  }
  const size_t n = lookups.size();
  vk::Buffer in(ctx, std::max<size_t>(n, 1) * sizeof(gpu::TestRay), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                vk::MemoryKind::HostVisible);
  std::memcpy(in.mapped(), lookups.data(), n * sizeof(gpu::TestRay));
  vk::Buffer out(ctx, std::max<size_t>(n, 1) * 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::HostVisible);
  layout.bindStorage(BINDING_TEST_RAYS, in);
  layout.bindStorage(BINDING_TEST_HITS, out);

  // Specialized as a textured scene's kernels are (normal maps, alpha and the rest do not touch a lookup).
  std::vector<vk::SpecConstant> specs{{SPEC_WORKGROUP_SIZE, gpu::kWorkgroupSize}, {SPEC_HAS_TEXTURES, 1u}};
  struct Form {
    std::string name;
    std::unique_ptr<vk::Kernel> kernel;
  };
  std::vector<Form> forms;
  forms.push_back({"sampled image", std::make_unique<vk::Kernel>(ctx, layout, "texture_forms", kSpirv_texture_forms, specs)});
  forms.push_back({"texel buffer", texelSkip.empty() ? std::make_unique<vk::Kernel>(ctx, layout, "texture_forms_texel_buffer",
                                                                                    kSpirv_texture_forms_texel_buffer, specs)
                                                     : nullptr});

  gpu::PushConstants pc{};
  pc.pathCount = uint32_t(n);
  const uint32_t groups = uint32_t((n + gpu::kWorkgroupSize - 1) / gpu::kWorkgroupSize);
  vk::GpuTimer timer(ctx, 2);
  auto run = [&](const vk::Kernel& kernel) {
    ctx.runCommands([&](VkCommandBuffer cmd) {
      timer.reset(cmd);
      vk::dispatch(cmd, layout, kernel, &pc, sizeof(pc), groups, &timer);
    });
    std::map<std::string, double> seconds;
    timer.collect(seconds);
    return seconds[kernel.name()];
  };

  std::vector<TextureFormTiming> timings(forms.size());
  std::vector<glm::vec4> reference(n), got(n);
  for (size_t f = 0; f < forms.size(); ++f) {
    timings[f].form = forms[f].name;
    if (!forms[f].kernel) {
      timings[f].skipped = texelSkip;
      continue;
    }
    run(*forms[f].kernel);  // also the warm-up: llvmpipe compiles on first dispatch
    std::memcpy((f == 0 ? reference : got).data(), out.mapped(), n * 16);
    if (f == 0) continue;
    for (size_t i = 0; i < n; ++i)
      for (int k = 0; k < 4; ++k) {
        double d = std::abs(double(got[i][k]) - double(reference[i][k]));
        timings[f].maxDifference = std::max(timings[f].maxDifference, std::isfinite(d) ? d : INFINITY);
      }
  }
  const double perLookup = 1e9 / double(std::max<uint64_t>(1, countTextureLookups(lookups)));
  for (int r = 0; r < rounds; ++r)
    for (size_t f = 0; f < forms.size(); ++f)
      if (forms[f].kernel) timings[f].nsPerLookup.push_back(run(*forms[f].kernel) * perLookup);
  return timings;
}

}  // namespace vkmc
