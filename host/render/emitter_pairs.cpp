// Pairing emissive triangles into quads through a map of their edges.
#include "render/emitter_pairs.h"

#include <array>
#include <bit>
#include <cmath>
#include <map>

namespace vkmc {

namespace {

using EdgeKey = std::array<uint32_t, 6>;
EdgeKey edgeKey(glm::vec3 a, glm::vec3 b) {
  EdgeKey ka{std::bit_cast<uint32_t>(a.x), std::bit_cast<uint32_t>(a.y), std::bit_cast<uint32_t>(a.z),
             std::bit_cast<uint32_t>(b.x), std::bit_cast<uint32_t>(b.y), std::bit_cast<uint32_t>(b.z)};
  EdgeKey kb{ka[3], ka[4], ka[5], ka[0], ka[1], ka[2]};
  return std::min(ka, kb);
}
bool same(glm::vec3 a, glm::vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
double area(const glm::vec3* p) { return 0.5 * glm::length(glm::dvec3(glm::cross(p[1] - p[0], p[2] - p[0]))); }

}  // namespace

std::vector<EmitterPair> findEmitterPairs(std::span<const glm::vec3> positions, std::span<const uint8_t> candidate,
                                          std::span<const uint32_t> material) {
  const uint32_t n = uint32_t(candidate.size());
  std::map<EdgeKey, std::vector<uint32_t>> byEdge;
  for (uint32_t t = 0; t < n; ++t)
    if (candidate[t])
      for (int k = 0; k < 3; ++k) byEdge[edgeKey(positions[3 * t + (k + 1) % 3], positions[3 * t + (k + 2) % 3])].push_back(t);
  std::vector<uint8_t> paired(n, 0);
  std::vector<EmitterPair> pairs;
  for (uint32_t a = 0; a < n; ++a) {
    if (!candidate[a] || paired[a]) continue;
    const glm::vec3* pa = &positions[3 * a];
    for (uint32_t k = 0; k < 3 && !paired[a]; ++k) {
      glm::vec3 p0 = pa[(k + 2) % 3], p1 = pa[k], p2 = pa[(k + 1) % 3];  // apex p1, shared edge p0-p2
      for (uint32_t b : byEdge[edgeKey(p0, p2)]) {
        if (b == a || paired[b] || material[b] != material[a]) continue;
        const glm::vec3* pb = &positions[3 * b];
        int free = -1;
        for (int j = 0; j < 3; ++j)
          if (!same(pb[j], p0) && !same(pb[j], p2)) free = j;
        if (free < 0) continue;
        glm::dvec3 corner = glm::dvec3(p0) + glm::dvec3(p2) - glm::dvec3(p1);
        double edge = glm::length(glm::dvec3(p2) - glm::dvec3(p0));
        double areaA = area(pa), areaB = area(pb);
        if (glm::length(glm::dvec3(pb[free]) - corner) > 1e-3 * edge || std::abs(areaA - areaB) > 1e-3 * areaA) continue;
        // Facing the same way: a one-sided quad whose halves disagree would waste the samples of one.
        if (glm::dot(glm::cross(pa[1] - pa[0], pa[2] - pa[0]), glm::cross(pb[1] - pb[0], pb[2] - pb[0])) <= 0.0f) continue;
        pairs.push_back({a, b, k});
        paired[a] = paired[b] = 1;
        break;
      }
    }
  }
  return pairs;
}

}  // namespace vkmc
