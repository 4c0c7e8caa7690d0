// The scene's textures and per-triangle shading attributes in their device encodings (texture_layout.h).
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include "../shaders/shared/layout.h"
#include "scene/scene.h"

namespace vkmc {

struct PackedTextures {
  std::vector<uint32_t> texels;   // BINDING_TEXTURE_TEXELS
  std::vector<glm::uvec4> infos;  // BINDING_TEXTURES, one per Scene::textures entry
};
PackedTextures packTextures(const Scene& scene);

// kAttributeTexels per triangle, in the given triangle order (the BVH's).
std::vector<glm::uvec4> packTriangleAttributes(const Scene& scene, const std::vector<uint32_t>& order);

gpu::TextureSlot textureSlot(const TextureRef& ref);

}  // namespace vkmc
