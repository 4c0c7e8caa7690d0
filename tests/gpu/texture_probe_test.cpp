// Texture lookups on the device (shaders/probes/texture_probe.comp, the code shading runs) against a host
// reference written here from the glTF and KHR_texture_transform specifications: wrap modes, bilinear and
// nearest filtering, sRGB decoding, the uv transform and the second uv set.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "bvh/bvh.h"
#include "layout.h"
#include "render/gpu_scene.h"
#include "spirv/texture_probe_spv.h"
#include "support/render_helpers.h"

using namespace vkmc;

namespace {

// The reference: one texel under a wrap mode, written without the shared header's helpers.
int wrapped(int i, int n, TextureWrap w) {
  if (w == TextureWrap::ClampToEdge) return std::clamp(i, 0, n - 1);
  if (w == TextureWrap::Repeat) return ((i % n) + n) % n;
  int period = 2 * n, m = ((i % period) + period) % period;
  return m < n ? m : period - 1 - m;
}
double srgb(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }
glm::dvec4 texel(const Texture& t, int x, int y, bool decode) {
  uint32_t v = t.texels[size_t(wrapped(y, t.height, t.wrapT)) * t.width + wrapped(x, t.width, t.wrapS)];
  glm::dvec4 c((v & 255) / 255.0, ((v >> 8) & 255) / 255.0, ((v >> 16) & 255) / 255.0, (v >> 24) / 255.0);
  if (decode) c = glm::dvec4(srgb(c.r), srgb(c.g), srgb(c.b), c.a);
  return c;
}
glm::dvec4 reference(const Texture& t, const TextureRef& ref, glm::dvec2 uv0, glm::dvec2 uv1, bool decode) {
  glm::dvec2 uv = ref.texCoord == 1 ? uv1 : uv0;
  glm::dvec2 st(ref.uvRow0.x * uv.x + ref.uvRow0.y * uv.y + ref.uvRow0.z,
                ref.uvRow1.x * uv.x + ref.uvRow1.y * uv.y + ref.uvRow1.z);
  if (t.nearest) return texel(t, int(std::floor(st.x * t.width)), int(std::floor(st.y * t.height)), decode);
  double x = st.x * t.width - 0.5, y = st.y * t.height - 0.5;
  int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  double fx = x - x0, fy = y - y0;
  return (1 - fy) * ((1 - fx) * texel(t, x0, y0, decode) + fx * texel(t, x0 + 1, y0, decode)) +
         fy * ((1 - fx) * texel(t, x0, y0 + 1, decode) + fx * texel(t, x0 + 1, y0 + 1, decode));
}

Texture randomTexture(uint32_t w, uint32_t h, TextureWrap s, TextureWrap t, bool nearest, std::mt19937& rng) {
  Texture tex;
  tex.width = w, tex.height = h, tex.wrapS = s, tex.wrapT = t, tex.nearest = nearest;
  for (uint32_t i = 0; i < w * h; ++i) tex.texels.push_back(rng());
  return tex;
}

struct Case {
  int material, slot;
  bool srgb;
};

}  // namespace

TEST(TextureProbe, DeviceLookupsMatchTheSpecification) {
  std::mt19937 rng(11);
  Scene scene;
  const TextureWrap modes[] = {TextureWrap::Repeat, TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat};
  // Every pair of wrap modes, bilinear, on a 5x3 texture; then nearest, and a 1x1 texture.
  for (TextureWrap s : modes)
    for (TextureWrap t : modes) scene.textures.push_back(randomTexture(5, 3, s, t, false, rng));
  scene.textures.push_back(randomTexture(4, 7, TextureWrap::Repeat, TextureWrap::MirroredRepeat, true, rng));
  scene.textures.push_back(randomTexture(1, 1, TextureWrap::Repeat, TextureWrap::Repeat, false, rng));
  // One material per texture, its baseColor slot plain and its emissive slot transformed on uv set 1.
  for (size_t i = 0; i < scene.textures.size(); ++i) {
    Material m;
    m.baseColorTexture.texture = int(i);
    m.emissiveTexture.texture = int(i);
    m.emissiveTexture.texCoord = 1;
    double rotation = 0.3 + 0.2 * double(i), sx = 1.7, sy = -0.6, ox = 0.25, oy = -1.5;  // KHR_texture_transform
    m.emissiveTexture.uvRow0 = glm::vec3(std::cos(rotation) * sx, std::sin(rotation) * sy, ox);
    m.emissiveTexture.uvRow1 = glm::vec3(-std::sin(rotation) * sx, std::cos(rotation) * sy, oy);
    m.metallicRoughnessTexture.texture = int(i);  // linear slot
    scene.materials.push_back(m);
  }
  test::addQuad(scene, glm::vec3(0.0f), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), 0);
  Bvh bvh = buildBvh(scene.triangleBounds());
  vk::Context& ctx = test::sharedContext();
  GpuScene gpuScene(ctx, scene, bvh);

  std::vector<gpu::TestRay> lookups;
  std::vector<Case> cases;
  std::uniform_real_distribution<float> uv(-3.0f, 4.0f);
  for (int m = 0; m < int(scene.materials.size()); ++m)
    for (int k = 0; k < 200; ++k) {
      Case c{m, k % 3 == 0 ? 0 : (k % 3 == 1 ? 3 : 1), k % 3 != 2};
      gpu::TestRay r{};
      r.origin = glm::vec4(uv(rng), uv(rng), uv(rng), uv(rng));
      if (k < 4) r.origin = glm::vec4(0.5f / 5.0f * float(k), 0.0f, 1.0f, 1.0f);  // texel centres and edges
      r.direction = glm::vec4(std::bit_cast<float>(uint32_t(m)), std::bit_cast<float>(uint32_t(c.slot)), c.srgb ? 1.0f : 0.0f, 0);
      lookups.push_back(r);
      cases.push_back(c);
    }
  vk::KernelLayout layout(ctx);
  vk::Buffer placeholder(ctx, 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::DeviceLocal);
  test::bindPlaceholders(layout, placeholder, {});
  gpuScene.bindTo(layout);
  vk::Buffer in(ctx, lookups.size() * sizeof(gpu::TestRay), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::HostVisible);
  std::memcpy(in.mapped(), lookups.data(), lookups.size() * sizeof(gpu::TestRay));
  vk::Buffer out(ctx, lookups.size() * 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::HostVisible);
  layout.bindStorage(BINDING_TEST_RAYS, in);
  layout.bindStorage(BINDING_TEST_HITS, out);
  vk::Kernel kernel(ctx, layout, "texture_probe", kSpirv_texture_probe, {{SPEC_WORKGROUP_SIZE, gpu::kWorkgroupSize}});
  gpu::PushConstants pc{};
  pc.pathCount = uint32_t(lookups.size());
  ctx.runCommands([&](VkCommandBuffer cmd) {
    vk::dispatch(cmd, layout, kernel, &pc, sizeof(pc), (pc.pathCount + gpu::kWorkgroupSize - 1) / gpu::kWorkgroupSize);
  });
  std::vector<glm::vec4> got(lookups.size());
  std::memcpy(got.data(), out.mapped(), got.size() * 16);

  int failures = 0;
  const int subTexelBits = int(ctx.properties().limits.subTexelPrecisionBits);
  double worst = 0.0;
  for (size_t i = 0; i < lookups.size(); ++i) {
    const Case& c = cases[i];
    const Material& m = scene.materials[c.material];
    const TextureRef& ref = c.slot == 0 ? m.baseColorTexture : c.slot == 3 ? m.emissiveTexture : m.metallicRoughnessTexture;
    glm::dvec4 want = reference(scene.textures[ref.texture], ref, glm::dvec2(lookups[i].origin.x, lookups[i].origin.y),
                                glm::dvec2(lookups[i].origin.z, lookups[i].origin.w), c.srgb);
    // The sampler quantizes bilinear weights to subTexelPrecisionBits (an error up to 2^(1 - bits) of the largest
    // texel difference, <= 1) and returns 8-bit texels' filtered values at 8-bit precision (1/255); a wrong texel,
    // wrap or transform is off by ~0.3 on these random textures.
    const Texture& tex = scene.textures[(c.slot == 0   ? m.baseColorTexture
                                         : c.slot == 3 ? m.emissiveTexture
                                                       : m.metallicRoughnessTexture)
                                            .texture];
    const double tolerance = (tex.nearest ? 0.0 : std::ldexp(1.0, 1 - subTexelBits)) + 1.0 / 255.0;
    for (int k = 0; k < 4; ++k) worst = std::max(worst, std::abs(double(got[i][k]) - want[k]));
    for (int k = 0; k < 4; ++k)
      if (!(std::abs(got[i][k] - want[k]) < tolerance) && failures++ < 10)
        ADD_FAILURE() << "lookup " << i << " material " << c.material << " slot " << c.slot << " srgb " << c.srgb << " uv0 ("
                      << lookups[i].origin.x << ", " << lookups[i].origin.y << ") uv1 (" << lookups[i].origin.z << ", "
                      << lookups[i].origin.w << ") channel " << k << ": device " << got[i][k] << ", reference " << want[k];
  }
  EXPECT_EQ(failures, 0) << "largest difference " << worst << ", subTexelPrecisionBits " << subTexelBits;
  std::printf("largest difference from the specification's bilinear filter: %.2e (subTexelPrecisionBits %d)\n", worst,
              subTexelBits);
}
