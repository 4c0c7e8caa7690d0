// tinybvh's GPU layouts of a scene's triangles, built by tinybvh's own builders, as plain arrays to upload. The only
// file that includes tiny_bvh.h (its implementation too), so its SIMD switches and warnings stay in one unit.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace vkmc {

// BVH_GPU: Aila-Laine nodes (64 bytes: both children's boxes; 4 vec4 each), primitive indices, and the vertices
// the kernel reads through them (the scene's, 3 vec4 per triangle).
struct TinybvhAilaLaine {
  std::vector<glm::vec4> nodes, vertices;
  std::vector<uint32_t> indices;
  double buildSeconds = 0;  // BVH build and conversion
};

// BVH8_CWBVH: compressed 8-wide nodes (80 bytes, 5 vec4 each) and leaf triangles (e1, e2, v0; v0.w: the triangle).
struct TinybvhCwbvh {
  std::vector<glm::vec4> nodes, triangles;
  double buildSeconds = 0;  // BVH build, leaf split to 3, 8-wide collapse, compression
};

// hq: tinybvh's BuildHQ (SBVH, spatial splits; what its GPU speed tests use) instead of its default binned SAH
// build (Build, AVX where compiled in).
TinybvhAilaLaine buildTinybvhAilaLaine(const Scene& scene, bool hq);
TinybvhCwbvh buildTinybvhCwbvh(const Scene& scene, bool hq);

}  // namespace vkmc
