// Cameras for rendering: the file's, an automatic one framing the scene, or a look-from/look-at override.
#pragma once
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace vkmc {

// Pinhole or orthographic ray generator basis; right/up are scaled to the image's half extents.
struct CameraRig {
  glm::vec3 origin;
  glm::vec3 forward;
  glm::vec3 right;
  glm::vec3 up;
  bool orthographic = false;
};

// Looks at the bounding box's centre from a three-quarter view above its front (glTF's "front" is +Z): 30 degrees
// round towards +X, 25 degrees up, 45 degree vertical field of view, far enough that the bounding sphere fits
// the narrower image axis.
Camera autoCamera(const Aabb& bounds, float aspect);
Camera lookAtCamera(glm::vec3 from, glm::vec3 at, float yfovDegrees);
CameraRig makeCameraRig(const Camera& camera, uint32_t width, uint32_t height);

}  // namespace vkmc
