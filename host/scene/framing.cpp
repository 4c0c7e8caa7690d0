#include "scene/framing.h"

#include <algorithm>
#include <cmath>

namespace vkmc {

FramedBounds framingBounds(const Scene& scene) {
  FramedBounds out{scene.bounds, false};
  Aabb standing;  // everything but the flat triangles
  for (size_t t = 0; t < scene.triangleCount(); ++t) {
    const glm::dvec3 a(scene.positions[3 * t]), b(scene.positions[3 * t + 1]), c(scene.positions[3 * t + 2]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double length = glm::length(n);
    if (length > 0.0 && std::isfinite(length) && std::abs(n.y) > kGroundFlatness * length) continue;
    for (int k = 0; k < 3; ++k) standing.grow(scene.positions[3 * t + k]);
  }
  for (const ThinSegment& s : scene.thinSegments) standing.grow(s.a), standing.grow(s.b);
  if (!standing.valid()) return out;
  auto horizontal = [](const Aabb& b) { return std::max(b.extent().x, b.extent().z); };
  if (!(horizontal(scene.bounds) > kGroundShrink * horizontal(standing))) return out;
  out.bounds = standing;
  out.groundLeftOut = true;
  return out;
}

}  // namespace vkmc
