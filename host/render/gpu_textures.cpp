// Texture and attribute packing.
#include "render/gpu_textures.h"

#include <algorithm>

#include "../shaders/shared/texture_layout.h"
#include "error.h"
#include "scene/texture_sampler.h"

namespace vkmc {

PackedTextures packTextures(const std::vector<Texture>& textures, uint32_t maxPageSide, uint32_t maxPages) {
  PackedTextures out;
  // 16-bit fields in the texture info (texture_layout.h)
  out.atlas = packTextureAtlas(textures, std::min<uint32_t>(maxPageSide, 0xffffu), std::min<uint32_t>(maxPages, 0xffffu));
  for (size_t i = 0; i < textures.size(); ++i) {
    const Texture& t = textures[i];
    const AtlasPlacement& p = out.atlas.placements[i];
    out.infos.push_back(gpu::encodeTextureInfo(p.x, p.y, p.layer, t.width, t.height, out.atlas.pageWidth, out.atlas.pageHeight,
                                               wrapCode(t.wrapS), wrapCode(t.wrapT), t.nearest));
  }
  return out;
}

std::vector<glm::uvec4> packTriangleAttributes(const Scene& scene, const std::vector<uint32_t>& order) {
  std::vector<glm::uvec4> out(gpu::kAttributeTexels * order.size());
  auto uv = [&](const std::vector<glm::vec2>& v, size_t corner) { return v.empty() ? glm::vec2(0.0f) : v[corner]; };
  auto tangent = [&](size_t corner) { return scene.tangents.empty() ? glm::vec4(1, 0, 0, 1) : scene.tangents[corner]; };
  auto color = [&](size_t corner) { return scene.colors.empty() ? glm::vec4(1.0f) : scene.colors[corner]; };
  for (size_t i = 0; i < order.size(); ++i) {
    size_t c = 3 * size_t(order[i]);
    glm::vec2 uvs[6] = {uv(scene.uv0, c), uv(scene.uv0, c + 1), uv(scene.uv0, c + 2),
                        uv(scene.uv1, c), uv(scene.uv1, c + 1), uv(scene.uv1, c + 2)};
    glm::uvec4* t = &out[gpu::kAttributeTexels * i];
    for (int k = 0; k < 3; ++k) t[k] = gpu::encodeUvTexel(uvs[2 * k], uvs[2 * k + 1]);
    t[3] = gpu::encodeTangents(tangent(c), tangent(c + 1), tangent(c + 2));
    t[4] = gpu::encodeColors(color(c), color(c + 1), color(c + 2));
  }
  return out;
}

gpu::TextureSlot textureSlot(const TextureRef& ref) {
  gpu::TextureSlot s{};
  s.uvRow0 = glm::vec4(ref.uvRow0, ref.scale);
  s.uvRow1 = glm::vec4(ref.uvRow1, 0.0f);
  s.texture = ref.present() ? static_cast<uint32_t>(ref.texture) : gpu::kNoTexture;
  s.texCoord = static_cast<uint32_t>(ref.texCoord);
  return s;
}

}  // namespace vkmc
