// Camera bases from glTF cameras, automatic framing and look-at overrides.
#include "scene/camera_rig.h"

#include <cmath>

#include "error.h"

namespace vkmc {

Camera lookAtCamera(glm::vec3 from, glm::vec3 at, float yfovDegrees) {
  // In double: a float length under- or overflows for tiny (1e-30) or huge scenes.
  glm::dvec3 f = glm::dvec3(at) - glm::dvec3(from);
  double length = glm::length(f);
  if (!(length > 0.0) || !std::isfinite(length)) throw Error("--look-from and --look-at must differ");
  if (!(yfovDegrees > 0.0f && yfovDegrees < 179.0f)) throw Error("--fov must be in (0, 179) degrees");
  Camera c;
  c.position = from;
  c.forward = glm::vec3(f / length);
  glm::vec3 worldUp(0.0f, 1.0f, 0.0f);
  if (std::abs(glm::dot(worldUp, c.forward)) > 0.999f) worldUp = glm::vec3(0.0f, 0.0f, -1.0f);
  c.up = glm::normalize(glm::cross(glm::cross(c.forward, worldUp), c.forward));
  c.yfov = glm::radians(yfovDegrees);
  c.name = "look-at";
  return c;
}

Camera autoCamera(const Aabb& bounds, float aspect) {
  const float yfov = glm::radians(45.0f);
  float radius = 0.5f * glm::length(bounds.extent());
  if (!(radius > 0.0f)) radius = 1.0f;
  float halfFov = 0.5f * yfov;
  if (aspect < 1.0f) halfFov = std::atan(std::tan(halfFov) * aspect);
  float distance = radius / std::sin(halfFov);
  // A three-quarter view from above, as model viewers open: 30 degrees round from the front (+Z) towards +X,
  // 25 degrees up, so flat models (a quad facing +Z, a ground plane) are never seen edge-on.
  const float azimuth = glm::radians(30.0f), elevation = glm::radians(25.0f);
  glm::vec3 toCamera(std::sin(azimuth) * std::cos(elevation), std::sin(elevation), std::cos(azimuth) * std::cos(elevation));
  Camera c = lookAtCamera(bounds.center() + toCamera * distance, bounds.center(), glm::degrees(yfov));
  c.name = "auto";
  return c;
}

CameraRig makeCameraRig(const Camera& camera, uint32_t width, uint32_t height) {
  CameraRig rig;
  float aspect = static_cast<float>(width) / static_cast<float>(height);
  rig.origin = camera.position;
  rig.forward = glm::normalize(camera.forward);
  glm::vec3 right = glm::normalize(glm::cross(rig.forward, camera.up));
  glm::vec3 up = glm::cross(right, rig.forward);
  if (camera.kind == CameraKind::Orthographic) {
    rig.orthographic = true;
    rig.right = right * (camera.ymag * aspect);
    rig.up = up * camera.ymag;
  } else {
    float tanY = std::tan(0.5f * camera.yfov);
    rig.right = right * (tanY * aspect);
    rig.up = up * tanY;
  }
  return rig;
}

}  // namespace vkmc
