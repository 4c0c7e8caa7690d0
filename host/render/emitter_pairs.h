// Emissive triangles that make a quad (two of one material sharing a diagonal, near a parallelogram), found so
// that light sampling can treat each pair as one light: one 2D sample then places the point on either half, so
// the choice of half and the position on it are stratified together (shading.glsl, sampleEmissiveTriangle). Most
// area lights in scenes are such quads; the Cornell box's is one.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace vkmc {

struct EmitterPair {
  uint32_t first, second;  // triangle indices (BVH order)
  uint32_t apex;           // the corner of `first` opposite the shared edge (0-2)
};

// positions: 3 per triangle (BVH order); candidate[t]: triangle t emits, untextured, opaque, positive area;
// material[t] its material. Each triangle joins at most one pair. Pairs must share an edge bit for bit, have
// areas within 0.1%, facing the same way, and the second's free vertex within 1e-3 of the edge length of the
// parallelogram's corner.
std::vector<EmitterPair> findEmitterPairs(std::span<const glm::vec3> positions, std::span<const uint8_t> candidate,
                                          std::span<const uint32_t> material);

}  // namespace vkmc
