#include "scene/framing.h"

#include <algorithm>
#include <cmath>

namespace vkmc {

FramedBounds framingBounds(const Scene& scene) {
  FramedBounds out{scene.bounds, false};
  auto flat = [&](size_t t) {
    const glm::dvec3 a(scene.positions[3 * t]), b(scene.positions[3 * t + 1]), c(scene.positions[3 * t + 2]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double length = glm::length(n);
    return length > 0.0 && std::isfinite(length) && std::abs(n.y) > kGroundFlatness * length;
  };
  Aabb standing;  // everything but the flat triangles
  for (size_t t = 0; t < scene.triangleCount(); ++t)
    if (!flat(t))
      for (int k = 0; k < 3; ++k) standing.grow(scene.positions[3 * t + k]);
  for (const ThinSegment& s : scene.thinSegments) standing.grow(s.a), standing.grow(s.b);
  if (!standing.valid()) return out;
  // A ground lies below what stands on it: flat triangles above the standing part's middle (a roof, a canopy) stay.
  const float middle = standing.center().y;
  for (size_t t = 0; t < scene.triangleCount(); ++t)
    if (flat(t) && (scene.positions[3 * t].y + scene.positions[3 * t + 1].y + scene.positions[3 * t + 2].y) / 3.0f > middle)
      for (int k = 0; k < 3; ++k) standing.grow(scene.positions[3 * t + k]);
  auto horizontal = [](const Aabb& b) { return std::max(b.extent().x, b.extent().z); };
  if (!(horizontal(scene.bounds) > kGroundShrink * horizontal(standing))) return out;
  out.bounds = standing;
  out.groundLeftOut = true;
  return out;
}

}  // namespace vkmc
