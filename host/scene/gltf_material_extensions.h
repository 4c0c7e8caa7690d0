// The glTF material extensions beyond the core metallic-roughness model, read into a Material:
// KHR_materials_specular (factor, colour, textures), _ior, _transmission, _volume, _clearcoat and _sheen.
// Each value is checked (finite, in its range); a value out of range gets one error naming material and key.
#pragma once
#include <string>
#include <vector>

#include "scene/scene.h"

namespace tinygltf {
struct Material;
}

namespace vkmc {

void applyMaterialExtensions(const tinygltf::Material& gltf, Material& m, const std::vector<Texture>& textures,
                             const std::string& name, std::vector<std::string>& warnings);

}  // namespace vkmc
