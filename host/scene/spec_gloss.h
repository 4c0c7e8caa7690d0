// KHR_materials_pbrSpecularGlossiness (archived by Khronos, still common in older exports) read into vkmc's
// metallic-roughness material, as converters and Blender's importer do: per texel where the material has
// textures (baked on the host into a baseColor and a metallicRoughness texture), from the factors otherwise.
#pragma once
#include <glm/glm.hpp>

#include <string>
#include <vector>

#include "scene/scene.h"

namespace tinygltf {
class Value;
}

namespace vkmc {

struct MetalRoughSample {
  glm::vec3 baseColor;
  float metallic, roughness;
};

// One specular-glossiness sample (linear RGB diffuse and specular, glossiness) as metallic-roughness: the metallic
// factor that makes the two models' diffuse and specular energies agree (a quadratic in it), then the base
// colour blended from what each reading implies, roughness = 1 - glossiness. Exact for a plain dielectric
// (specular 0.04) and a plain metal (diffuse 0).
MetalRoughSample metalRoughFromSpecGloss(glm::vec3 diffuse, glm::vec3 specular, float glossiness);

// Replaces `out`'s base colour, metallic, roughness and alpha by the extension's (`ext`, its JSON value). With a
// diffuse or specularGlossiness texture, two textures are baked into `baked` at the resolution of the larger of
// the two, sampling both at the same uv: they must share a texture coordinate set and transform, or the
// specularGlossiness texture is ignored with a warning. `textures` are the file's (references are checked against
// them alone); a baked texture's index is textures.size() + its place in `baked`, where the loader appends them.
// `name` names the material in messages.
void applySpecularGlossiness(const tinygltf::Value& ext, Material& out, const std::vector<Texture>& textures,
                             std::vector<Texture>& baked, const std::string& name, std::vector<std::string>& warnings);

}  // namespace vkmc
