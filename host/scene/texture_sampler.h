// Texture lookups on the host, with the device's addressing (shaders/shared/texture_layout.h): used to weight
// textured emitters by their power. The kernels' own lookups are in shaders/include/textures.glsl.
#pragma once
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace vkmc {

// A sampler's wrap mode as the device encodes it (texture_layout.h kWrap*).
uint32_t wrapCode(TextureWrap wrap);

// The texture's filtered RGBA at uv (bilinear or nearest, its wrap modes); rgb decoded from sRGB when `srgb`.
glm::vec4 sampleTexture(const Texture& texture, glm::vec2 uv, bool srgb);

// A slot's uv from the corner uvs' interpolation: its texture coordinate set, then its KHR_texture_transform.
glm::vec2 slotUv(const TextureRef& ref, glm::vec2 uv0, glm::vec2 uv1);

// Emitted radiance of triangle `tri` averaged over its area (emissiveFactor x the emissive texture's mean over
// a fixed 64-point stratified pattern): what light selection weights it by.
glm::vec3 averageEmission(const Scene& scene, size_t tri);

}  // namespace vkmc
