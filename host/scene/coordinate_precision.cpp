#include "scene/coordinate_precision.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vkmc {

double coordinateScale(const Scene& scene) {
  const size_t triangles = scene.triangleCount();
  if (triangles == 0) return 0.0;
  std::vector<float> edge(triangles);
  float largest = 0.0f;
  for (size_t t = 0; t < triangles; ++t) {
    const glm::vec3* v = &scene.positions[3 * t];
    edge[t] = std::max({glm::length(v[1] - v[0]), glm::length(v[2] - v[1]), glm::length(v[0] - v[2])});
    for (int k = 0; k < 3; ++k) largest = std::max({largest, std::abs(v[k].x), std::abs(v[k].y), std::abs(v[k].z)});
    largest = std::max(largest, edge[t]);
  }
  auto tenth = edge.begin() + ptrdiff_t(triangles / 10);
  std::nth_element(edge.begin(), tenth, edge.end());
  return *tenth > 0.0f ? double(largest) / double(*tenth) : 0.0;
}

std::optional<std::string> coordinatePrecisionWarning(const Scene& scene) {
  const double scale = coordinateScale(scene);
  if (!(scale > kPrecisionScaleLimit)) return std::nullopt;
  char line[400];
  std::snprintf(line, sizeof(line),
                "the scene's coordinates or triangles reach %.2g times its small triangles' size: float hit points "
                "there err by about that times 1e-7 of it, and hits near a huge triangle are missed, so light and "
                "shadow may render wrong (a huge ground, or a scene far from the origin): scale its large triangles "
                "down, split them, or move the scene to the origin",
                scale);
  return line;
}

}  // namespace vkmc
