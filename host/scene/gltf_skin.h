// Skins in the default pose (glTF 2.0 section 3.7.3): each vertex moved by its joints' matrices, world(joint) x
// inverseBindMatrix, blended by its weights (linear blend skinning). The skinned mesh's own node transform is not
// applied, as the spec says; the result is in world space.
#pragma once
#include <tiny_gltf.h>

#include <glm/glm.hpp>
#include <vector>

#include "scene/gltf_primitive.h"

namespace vkmc {

// One matrix per joint of skin `skin`; throws vkmc::Error for a joint or accessor that does not exist or fit.
std::vector<glm::mat4> jointMatrices(const tinygltf::Model& model, int skin, const std::vector<glm::mat4>& worldTransforms);

// Positions, normals and tangents of `data` (with its joints and weights) into world space, a mirroring vertex's
// tangent handedness flipped. Returns which vertices the skin mirrors (their triangles' winding is the caller's to
// swap). Throws vkmc::Error for a joint index past `joints`.
std::vector<bool> applySkin(PrimitiveData& data, const std::vector<glm::mat4>& joints);

}  // namespace vkmc
