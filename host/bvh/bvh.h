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

// 4-wide GPU node, collapsed from the binary tree (the traversal kernels walk this one): four RGBA32UI texels,
// one cache line. The child boxes are quantized to 8 bits per plane on a grid over the node's box, rounded
// outwards so a child's box only grows (Ylitie et al. 2017); 64 bytes instead of 112 for float planes, and 4
// fetches per step instead of 7, which is what a node step costs on llvmpipe.
//   texel 0: the grid's origin xyz (float bits), w: its step exponents, biased as a float's (step = 2^(e - 127)),
//            in bytes 0, 1, 2 for x, y, z
//   texel 1: the planes lo.x, hi.x, lo.y, hi.y, each a uint with child i's step count in byte i
//   texel 2: the planes lo.z, hi.z; zw unused
//   texel 3: the four child entries: a wide node index, a leaf entry (kBvhLeafTag | (count - 1) << 27 | first,
//            count <= 8) or kBvhEmptySlot
// Plane value = origin + steps * step. Fewer, wider steps than the binary walk, and 4 box tests as vec4 arithmetic.
struct BvhWideNode {
  glm::uvec4 texels[4];
};
static_assert(sizeof(BvhWideNode) == 64);
// The box of child `i` (empty when the slot is), exactly as the node encodes it.
Aabb wideChildBox(const BvhWideNode& node, int i);
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
// The same over the 4-wide layout, each child box decoded exactly as its node encodes it (wideChildBox).
HostHit traceHostWide(const Bvh& bvh, std::span<const glm::vec3> orderedPositions, glm::vec3 origin, glm::vec3 dir, float tMax,
                      bool anyHit);

}  // namespace vkmc
