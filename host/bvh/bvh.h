// Binned-SAH BVH over triangles, flattened to the GPU layout: each node holds its two children's boxes.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

#include "scene/scene.h"

namespace vkmc {

// GPU node: four RGBA32F texels. Child c: (min.xyz, ref) and (max.xyz, count), ref/count as float bits.
// count > 0: leaf, triangles [ref, ref + count) of the reordered triangle array; count == 0: inner node ref.
struct BvhGpuNode {
  glm::vec4 texels[4];  // lo0, hi0, lo1, hi1
};
static_assert(sizeof(BvhGpuNode) == 64);

// 4-wide GPU node, collapsed from the binary tree (the traversal kernels walk this one): seven RGBA32F texels,
// the four child boxes in SoA form (lo.x, hi.x, lo.y, hi.y, lo.z, hi.z) and the four child entries as float
// bits: a wide node index, a leaf entry (kBvhLeafTag | (count - 1) << 27 | first, count <= 8, so never a NaN
// pattern) or kBvhEmptySlot. Fewer, wider steps than the binary walk, and 4 box tests as vec4 arithmetic.
struct BvhWideNode {
  glm::vec4 texels[7];
};
static_assert(sizeof(BvhWideNode) == 112);
inline constexpr uint32_t kBvhLeafTag = 0x80000000u;
inline constexpr uint32_t kBvhEmptySlot = 0x7f7fffffu;  // FLT_MAX's bits: no NaN on the way through a float texel

struct BvhStats {
  uint32_t innerNodes = 0;
  uint32_t leaves = 0;
  uint32_t maxDepth = 0;
  uint32_t maxLeafSize = 0;
  double averageLeafSize = 0.0;
  double sahCost = 0.0;  // expected cost per ray, inner traversal cost 1, triangle test cost 1
  double buildSeconds = 0.0;
};

struct BvhOptions {
  uint32_t bins = 16;
  uint32_t maxLeafSize = 8;
  float traversalCost = 1.0f;
  float triangleCost = 1.0f;
  // Full sweep SAH: every split position along every axis (centroid-sorted), O(n log^2 n); the reference the
  // binned build's quality is measured against, not the production build.
  bool fullSweep = false;
};

struct Bvh {
  std::vector<BvhGpuNode> nodes;     // binary layout, node 0 is the root (host traversal, statistics)
  std::vector<BvhWideNode> wideNodes;   // 4-wide layout, node 0 is the root (GPU traversal)
  std::vector<uint32_t> triangleOrder;  // GPU triangle i is input triangle triangleOrder[i]
  BvhStats stats;
};

// bounds: one box per triangle. Deterministic; single-threaded.
Bvh buildBvh(std::span<const Aabb> bounds, const BvhOptions& options = {});

// Host reference traversal over the GPU layout (tests, tools). Returns t < 0 on a miss.
struct HostHit {
  float t = -1.0f;
  float b1 = 0.0f, b2 = 0.0f;
  uint32_t triangle = 0xffffffffu;
};
HostHit traceHost(const Bvh& bvh, std::span<const glm::vec3> orderedPositions, glm::vec3 origin, glm::vec3 dir, float tMax,
                  bool anyHit);

}  // namespace vkmc
