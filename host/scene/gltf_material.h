// A glTF material read into vkmc's Material: the core metallic-roughness factors and textures, then the extensions
// (gltf_material_extensions.h), specular-glossiness (spec_gloss.h) and unlit. Every factor is checked against its
// range in the glTF 2.0 schema; a value outside it gets one error naming the material and the key.
#pragma once
#include <string>
#include <vector>

#include "scene/scene.h"

namespace tinygltf {
struct Material;
}

namespace vkmc {

// `textures`: the file's; textures baked for the material (specular-glossiness) go to `baked`.
Material convertMaterial(const tinygltf::Material& m, int index, const std::vector<Texture>& textures,
                         std::vector<Texture>& baked, std::vector<std::string>& warnings);

}  // namespace vkmc
