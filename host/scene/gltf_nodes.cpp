#include "scene/gltf_nodes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <string>

#include "error.h"

namespace vkmc {

glm::mat4 localTransform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = static_cast<float>(node.matrix[i]);
    return m;
  }
  glm::mat4 m(1.0f);
  if (node.translation.size() == 3)
    m = glm::translate(m, glm::vec3(node.translation[0], node.translation[1], node.translation[2]));
  if (node.rotation.size() == 4) {
    glm::quat q(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]), static_cast<float>(node.rotation[1]),
                static_cast<float>(node.rotation[2]));
    m *= glm::mat4_cast(glm::normalize(q));
  }
  if (node.scale.size() == 3) m = glm::scale(m, glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
  return m;
}

std::vector<glm::mat4> worldTransforms(const tinygltf::Model& model) {
  const size_t n = model.nodes.size();
  std::vector<int> parent(n, -1);
  for (size_t i = 0; i < n; ++i)
    for (int child : model.nodes[i].children) {
      if (child < 0 || size_t(child) >= n) throw Error("node " + std::to_string(i) + " has a child that does not exist");
      if (parent[child] >= 0) throw Error("node " + std::to_string(child) + " has two parents");
      parent[child] = int(i);
    }
  std::vector<glm::mat4> world(n);
  std::vector<char> done(n, 0);
  for (size_t i = 0; i < n; ++i) {
    std::vector<int> chain;  // from node i up to the first ancestor already done (or a root)
    for (int k = int(i); k >= 0 && !done[k]; k = parent[k]) {
      if (chain.size() > n) throw Error("the node hierarchy has a cycle");
      chain.push_back(k);
    }
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      const int p = parent[*it];
      world[*it] = (p >= 0 ? world[p] : glm::mat4(1.0f)) * localTransform(model.nodes[*it]);
      done[*it] = 1;
    }
  }
  return world;
}

}  // namespace vkmc
