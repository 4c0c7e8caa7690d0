// KHR_lights_punctual definitions and node instances, validated.
#include "scene/gltf_lights.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "error.h"

namespace vkmc {
namespace {

constexpr double kHalfPi = 1.57079632679489661923;
const char* const kRangeWarning =
    "KHR_lights_punctual: `range` is ignored (vkmc is physically based: the inverse-square falloff is exact)";

PunctualLight convertLight(const tinygltf::Light& l, int index) {
  std::string name = "light " + std::to_string(index) + (l.name.empty() ? "" : " ('" + l.name + "')");
  PunctualLight out;
  out.name = l.name;
  if (l.type == "point")
    out.kind = PunctualKind::Point;
  else if (l.type == "spot")
    out.kind = PunctualKind::Spot;
  else if (l.type == "directional")
    out.kind = PunctualKind::Directional;
  else
    throw Error(name + ": unknown type '" + l.type + "' (point, spot or directional)");
  glm::dvec3 color(1.0);
  if (!l.color.empty()) {
    if (l.color.size() != 3) throw Error(name + ": color must have 3 components");
    color = glm::dvec3(l.color[0], l.color[1], l.color[2]);
  }
  for (int c = 0; c < 3; ++c)
    if (!std::isfinite(color[c]) || color[c] < 0.0) throw Error(name + ": color must be finite and non-negative");
  if (!std::isfinite(l.intensity) || l.intensity < 0.0) throw Error(name + ": intensity must be finite and non-negative");
  glm::dvec3 intensity = color * l.intensity;
  if (!glm::all(glm::lessThanEqual(intensity, glm::dvec3(3.0e38)))) throw Error(name + ": color x intensity overflows float");
  out.intensity = glm::vec3(intensity);
  if (out.kind == PunctualKind::Spot) {
    double inner = l.spot.innerConeAngle, outer = l.spot.outerConeAngle;
    if (!(inner >= 0.0 && inner < outer && outer <= kHalfPi))
      throw Error(name + ": spot cone angles must satisfy 0 <= innerConeAngle < outerConeAngle <= pi/2 (got " +
                  std::to_string(inner) + ", " + std::to_string(outer) + ")");
    out.innerConeAngle = float(inner);
    out.outerConeAngle = float(outer);
  }
  return out;
}

}  // namespace

void addNodePunctualLight(const tinygltf::Model& model, int nodeIndex, const glm::mat4& world, Scene& scene) {
  const tinygltf::Node& node = model.nodes[nodeIndex];
  auto ext = node.extensions.find("KHR_lights_punctual");
  if (ext == node.extensions.end()) return;
  std::string where = "node " + std::to_string(nodeIndex);
  if (!ext->second.IsObject() || !ext->second.Has("light") || !ext->second.Get("light").IsNumber())
    throw Error(where + ": KHR_lights_punctual without a light index");
  double index = ext->second.Get("light").GetNumberAsDouble();
  if (!(index >= 0.0 && index < double(model.lights.size())) || index != std::floor(index))
    throw Error(where + ": KHR_lights_punctual light " + std::to_string(index) + " does not exist (" +
                std::to_string(model.lights.size()) + " defined)");
  const tinygltf::Light& def = model.lights[size_t(index)];
  PunctualLight light = convertLight(def, int(index));
  light.position = glm::vec3(world[3]);
  glm::vec3 forward = -glm::vec3(world[2]);  // the node's -Z in world space
  float len = glm::length(forward);
  if (!std::isfinite(light.position.x) || !std::isfinite(light.position.y) || !std::isfinite(light.position.z) ||
      !std::isfinite(len) || !(len > 0.0f))
    throw Error(where + ": its transform places light " + std::to_string(size_t(index)) + " at a non-finite or degenerate pose");
  light.direction = forward / len;
  if (def.range > 0.0 && std::find(scene.warnings.begin(), scene.warnings.end(), kRangeWarning) == scene.warnings.end())
    scene.warnings.push_back(kRangeWarning);
  scene.punctualLights.push_back(light);
}

}  // namespace vkmc
