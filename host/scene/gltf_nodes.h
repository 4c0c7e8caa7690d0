// A glTF node's local transform (its matrix, or translation x rotation x scale) and every node's world transform
// in the default pose (from the parent links of `children`), which skins read their joints from.
#pragma once
#include <tiny_gltf.h>

#include <glm/glm.hpp>
#include <vector>

namespace vkmc {

glm::mat4 localTransform(const tinygltf::Node& node);
// Throws vkmc::Error for a node with two parents or a cycle; nodes outside any hierarchy are their own roots.
std::vector<glm::mat4> worldTransforms(const tinygltf::Model& model);

}  // namespace vkmc
