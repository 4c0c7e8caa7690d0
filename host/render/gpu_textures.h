// The scene's textures and per-triangle shading attributes in their device encodings (texture_layout.h).
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include "../shaders/shared/layout.h"
#include "render/texture_atlas.h"
#include "scene/scene.h"

namespace vkmc {

struct PackedTextures {
  TextureAtlas atlas;             // BINDING_TEXTURE_PAGES (render/texture_atlas.h)
  std::vector<glm::uvec4> infos;  // BINDING_TEXTURES, one per texture
};
// maxPageSide, maxPages: the device's largest 2D image side and array layers.
PackedTextures packTextures(const std::vector<Texture>& textures, uint32_t maxPageSide, uint32_t maxPages);

// kAttributeTexels per triangle, in the given triangle order (the BVH's).
std::vector<glm::uvec4> packTriangleAttributes(const Scene& scene, const std::vector<uint32_t>& order);

gpu::TextureSlot textureSlot(const TextureRef& ref);

}  // namespace vkmc
