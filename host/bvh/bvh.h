// Binned-SAH BVH over triangles, flattened to the GPU layout: each node holds its two children's boxes.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "../shaders/shared/bvh_layout.h"
#include "scene/scene.h"

namespace vkmc {

// The node layouts the kernels read, each four texels (shaders/shared/bvh_layout.h defines the encodings).
struct BvhGpuNode {
  glm::vec4 texels[gpu::kBvhNodeTexels];  // binary: lo0, hi0, lo1, hi1
};
static_assert(sizeof(BvhGpuNode) == 64);

// 4-wide node, collapsed from the binary tree (the traversal kernels walk this one): 64 bytes instead of 112 for
// float planes, and 4 fetches per step instead of 7, which is what a node step costs on llvmpipe.
struct BvhWideNode {
  glm::uvec4 texels[gpu::kBvhNodeTexels];
};
static_assert(sizeof(BvhWideNode) == 64);
// The box of child `i` (empty when the slot is), exactly as the node encodes it.
Aabb wideChildBox(const BvhWideNode& node, int i);

struct BvhStats {
  uint32_t innerNodes = 0;
  uint32_t leaves = 0;
  uint32_t maxDepth = 0;
  uint32_t maxLeafSize = 0;
  double averageLeafSize = 0.0;
  double sahCost = 0.0;       // expected cost per ray, inner traversal cost 1, triangle test cost 1
  double wideSahCost = 0.0;   // the same for the 4-wide tree the kernels walk: wide node steps plus triangle tests
  uint32_t wideMaxDepth = 0;  // inner nodes on the 4-wide tree's longest root-to-leaf path
  // The most entries a walk of the 4-wide tree can hold on its stack: over root-to-node paths, the sum of each
  // inner node's children less the one entered next (what a ray that hits every box pushes).
  uint32_t wideMaxPending = 0;
  double buildSeconds = 0.0;
  uint32_t buildThreads = 1;
};

struct BvhOptions {
  uint32_t bins = 16;
  uint32_t maxLeafSize = 8;
  float traversalCost = 1.0f;
  float triangleCost = 1.0f;
  // Full sweep SAH: every split position along every axis (centroid-sorted), O(n log^2 n); the reference the
  // binned build's quality is measured against, not the production build.
  bool fullSweep = false;
  uint32_t threads = 0;  // 0: every hardware thread; the tree is the same for any count
};

struct Bvh {
  std::vector<BvhGpuNode> nodes;        // binary layout, node 0 is the root (host traversal, statistics)
  std::vector<BvhWideNode> wideNodes;   // 4-wide layout, node 0 is the root (GPU traversal)
  std::vector<uint32_t> triangleOrder;  // GPU triangle i is input triangle triangleOrder[i]
  BvhStats stats;
};

// bounds: one box per triangle. Deterministic, whatever options.threads is.
Bvh buildBvh(std::span<const Aabb> bounds, const BvhOptions& options = {});

// Whether some walk of the 4-wide tree can outgrow the kernels' register stack (gpu::kBvhRegisterStackEntries), so
// that the deep passes must be there (stats.wideMaxPending is more).
bool walksCanOutgrowRegisterStack(const BvhStats& stats);
// The register stack the kernels are built with (SPEC_REGISTER_STACK): 4 or 8 entries where no walk of the tree
// can hold more, else gpu::kBvhRegisterStackEntries. A smaller stack is fewer instructions every walk step (the
// trace loop's 941 -> 886 with 8, 841 with 4); one that walks can outgrow needs the deep passes, which cost more
// than that (docs/journal/performance.md, "A register stack sized to the tree").
uint32_t registerStackEntries(const BvhStats& stats);

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

// Every triangle the segment (0, tMax) crosses, in walk order, for host queries that need more than the closest
// hit: visit(triangle, t, fromBehind, tMax) returns the segment's new end (a hit that stops the ray its t, one it
// passes tMax), so no box beyond the nearest stop is entered. Triangles are in the BVH's order (triangleOrder maps
// them back). Returns the segment's final end.
using HostVisit = std::function<float(uint32_t triangle, float t, bool fromBehind, float tMax)>;
float walkHost(const Bvh& bvh, std::span<const glm::vec3> orderedPositions, glm::vec3 origin, glm::vec3 dir, float tMax,
               const HostVisit& visit);

}  // namespace vkmc
