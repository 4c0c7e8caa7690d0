#include "scene/studio_environment.h"

#include <algorithm>
#include <cmath>

namespace vkmc {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Softbox {
  glm::vec3 direction;  // toward the light
  float radiusDegrees;  // its angular radius, with a soft edge of 3 degrees
  float radiance;
};

// Placed for the automatic camera, which looks from +Z turned 30 degrees toward +X and 25 degrees up.
const Softbox kSoftboxes[] = {
    {{-0.55f, 0.65f, 0.55f}, 22.0f, 6.0f},  // key: above, front left
    {{0.85f, 0.25f, 0.45f}, 28.0f, 1.5f},   // fill: low, front right
    {{0.2f, 0.55f, -0.8f}, 16.0f, 3.0f},    // rim: behind, above
};

float smoothEdge(float edge0, float edge1, float x) {
  const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// The cyclorama: 0.2 on the floor, rising across the horizon to 0.45, and to 0.6 at the zenith.
float cyclorama(float up) { return 0.2f + 0.25f * smoothEdge(-0.15f, 0.1f, up) + 0.15f * std::max(up, 0.0f); }

}  // namespace

glm::vec3 equirectangularDirection(uint32_t x, uint32_t y, uint32_t width, uint32_t height) {
  const double theta = kPi * (double(y) + 0.5) / double(height);             // 0 at the top (+Y)
  const double phi = 2.0 * kPi * ((double(x) + 0.5) / double(width) - 0.5);  // 0 at the centre (-Z)
  return glm::vec3(float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)), float(-std::sin(theta) * std::cos(phi)));
}

EnvironmentMap studioEnvironment() {
  EnvironmentMap map;
  map.width = 128, map.height = 64;
  map.source = kStudioEnvironment;
  map.radiance.resize(size_t(map.width) * map.height);
  for (uint32_t y = 0; y < map.height; ++y)
    for (uint32_t x = 0; x < map.width; ++x) {
      const glm::vec3 w = equirectangularDirection(x, y, map.width, map.height);
      float L = cyclorama(w.y);
      for (const Softbox& box : kSoftboxes) {
        const float angle =
            float(std::acos(std::clamp(double(glm::dot(w, glm::normalize(box.direction))), -1.0, 1.0)) * 180.0 / kPi);
        L = std::max(L, box.radiance * (1.0f - smoothEdge(box.radiusDegrees - 3.0f, box.radiusDegrees, angle)));
      }
      map.radiance[size_t(y) * map.width + x] = glm::vec3(L);
    }
  return map;
}

}  // namespace vkmc
