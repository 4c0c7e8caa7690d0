// KHR_lights_punctual: the lights a node instances, in world space (the definitions come from the model's root
// extension, which tinygltf parses into model.lights).
#pragma once
#include <glm/glm.hpp>

#include <tiny_gltf.h>

#include "scene/scene.h"

namespace vkmc {

// Appends the light that node `nodeIndex` instances (extensions.KHR_lights_punctual.light), if any, placed by the
// node's world transform: at its origin, shining along its -Z. Throws Error with one line on invalid input
// (a missing light, non-finite or negative intensity or color, cone angles outside 0 <= inner < outer <= pi/2).
// A light that sets `range` adds one warning per scene: it is ignored (inverse-square falloff is exact).
void addNodePunctualLight(const tinygltf::Model& model, int nodeIndex, const glm::mat4& world, Scene& scene);

}  // namespace vkmc
