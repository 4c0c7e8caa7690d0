#include "scene/gltf_skin.h"

#include <cmath>
#include <cstring>
#include <string>

#include "error.h"
#include "scene/gltf_accessors.h"

namespace vkmc {

std::vector<glm::mat4> jointMatrices(const tinygltf::Model& model, int skinIndex, const std::vector<glm::mat4>& world) {
  if (skinIndex < 0 || size_t(skinIndex) >= model.skins.size())
    throw Error("skin " + std::to_string(skinIndex) + " does not exist");
  const tinygltf::Skin& skin = model.skins[skinIndex];
  const std::string what = "skin " + std::to_string(skinIndex);
  std::vector<glm::mat4> inverseBind(skin.joints.size(), glm::mat4(1.0f));
  if (skin.inverseBindMatrices >= 0) {
    AccessorView v = viewAccessor(model, skin.inverseBindMatrices, "inverseBindMatrices");
    if (v.type != TINYGLTF_TYPE_MAT4 || v.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || v.count < skin.joints.size())
      throw Error(what + ": inverseBindMatrices is not a float MAT4 accessor of one matrix a joint");
    for (size_t j = 0; j < skin.joints.size(); ++j) std::memcpy(&inverseBind[j], v.data + j * v.stride, sizeof(glm::mat4));
  }
  std::vector<glm::mat4> joints(skin.joints.size());
  for (size_t j = 0; j < skin.joints.size(); ++j) {
    const int node = skin.joints[j];
    if (node < 0 || size_t(node) >= world.size()) throw Error(what + ": joint " + std::to_string(j) + " is not a node");
    joints[j] = world[node] * inverseBind[j];
  }
  return joints;
}

std::vector<bool> applySkin(PrimitiveData& data, const std::vector<glm::mat4>& joints) {
  const size_t n = data.positions.size();
  if (n == 0) return {};
  const size_t sets = data.joints.size() / n;
  if (sets == 0 || data.joints.size() != sets * n || data.weights.size() != sets * n)
    throw Error("a skinned mesh's primitive lacks JOINTS_0 and WEIGHTS_0 for every vertex");
  std::vector<bool> mirrored(n, false);
  for (size_t v = 0; v < n; ++v) {
    glm::mat4 m(0.0f);
    float total = 0.0f;
    for (size_t i = v; i < sets * n; i += n) {  // the vertex's influences, four a set
      for (int k = 0; k < 4; ++k) {
        const float w = data.weights[i][k];
        if (w == 0.0f) continue;
        if (data.joints[i][k] >= joints.size())
          throw Error("vertex " + std::to_string(v) + " names joint " + std::to_string(data.joints[i][k]) + " of a skin of " +
                      std::to_string(joints.size()));
        m += w * joints[data.joints[i][k]];
        total += w;
      }
    }
    // Weights should sum to 1; exporters round them, and a vertex with none stays where its bind pose puts it.
    m = total > 0.0f ? m / total : glm::mat4(1.0f);
    data.positions[v] = glm::vec3(m * glm::vec4(data.positions[v], 1.0f));
    const glm::mat3 linear(m);
    mirrored[v] = glm::determinant(linear) < 0.0f;  // a mirroring skeleton swaps handedness (and the winding)
    if (!data.normals.empty()) data.normals[v] = glm::transpose(glm::inverse(linear)) * data.normals[v];
    if (!data.tangents.empty() && !data.tangentsPerCorner)
      data.tangents[v] = glm::vec4(linear * glm::vec3(data.tangents[v]), mirrored[v] ? -data.tangents[v].w : data.tangents[v].w);
  }
  return mirrored;
}

}  // namespace vkmc
