// Host texture lookups.
#include "scene/texture_sampler.h"

#include "../shaders/shared/texture_layout.h"

namespace vkmc {
namespace {

glm::vec4 texel(const Texture& t, int x, int y, bool srgb) {
  x = gpu::wrapNearTexel(x, int(t.width), wrapCode(t.wrapS));
  y = gpu::wrapNearTexel(y, int(t.height), wrapCode(t.wrapT));
  glm::vec4 c = glm::unpackUnorm4x8(t.texels[size_t(y) * t.width + size_t(x)]);
  if (srgb)
    for (int k = 0; k < 3; ++k) c[k] = gpu::srgbToLinear(c[k]);
  return c;
}

}  // namespace

uint32_t wrapCode(TextureWrap w) {
  return w == TextureWrap::ClampToEdge      ? gpu::kWrapClampToEdge
         : w == TextureWrap::MirroredRepeat ? gpu::kWrapMirroredRepeat
                                            : gpu::kWrapRepeat;
}

glm::vec4 sampleTexture(const Texture& t, glm::vec2 uv, bool srgb) {
  if (t.width == 0 || t.height == 0) return glm::vec4(1.0f);
  uv = glm::vec2(gpu::wrapUnit(uv.x, wrapCode(t.wrapS)), gpu::wrapUnit(uv.y, wrapCode(t.wrapT)));
  if (t.nearest) return texel(t, gpu::nearestTexel(uv.x, int(t.width)), gpu::nearestTexel(uv.y, int(t.height)), srgb);
  float fx = 0.0f, fy = 0.0f;
  int x = gpu::bilinearLow(uv.x, int(t.width), fx), y = gpu::bilinearLow(uv.y, int(t.height), fy);
  glm::vec4 top = glm::mix(texel(t, x, y, srgb), texel(t, x + 1, y, srgb), fx);
  glm::vec4 bottom = glm::mix(texel(t, x, y + 1, srgb), texel(t, x + 1, y + 1, srgb), fx);
  return glm::mix(top, bottom, fy);
}

glm::vec2 slotUv(const TextureRef& ref, glm::vec2 uv0, glm::vec2 uv1) {
  glm::vec3 uv(ref.texCoord == 1 ? uv1 : uv0, 1.0f);
  return glm::vec2(glm::dot(ref.uvRow0, uv), glm::dot(ref.uvRow1, uv));
}

glm::vec3 averageEmission(const Scene& scene, size_t tri) {
  const Material& m = scene.materials[scene.materialIds[tri]];
  if (!m.emissiveTexture.present() || scene.uv0.empty()) return m.emission;
  const Texture& t = scene.textures[m.emissiveTexture.texture];
  const std::vector<glm::vec2>* uvs1 = scene.uv1.empty() ? &scene.uv0 : &scene.uv1;
  constexpr int kGrid = 8;
  glm::dvec3 sum(0.0);
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      // Stratified points of the unit square folded onto the triangle (uniform in area).
      float a = (i + 0.5f) / kGrid, b = (j + 0.5f) / kGrid;
      if (a + b > 1.0f) a = 1.0f - a, b = 1.0f - b;
      glm::vec3 w(1.0f - a - b, a, b);
      glm::vec2 uv0(0.0f), uv1(0.0f);
      for (int k = 0; k < 3; ++k) uv0 += w[k] * scene.uv0[3 * tri + k], uv1 += w[k] * (*uvs1)[3 * tri + k];
      sum += glm::dvec3(glm::vec3(sampleTexture(t, slotUv(m.emissiveTexture, uv0, uv1), true)));
    }
  return m.emission * glm::vec3(sum / double(kGrid * kGrid));
}

}  // namespace vkmc
