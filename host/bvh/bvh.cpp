// The GPU layouts of the binary SAH tree (binary_build.h): flattened depth first, collapsed to quantized 4-wide
// nodes; and the host reference traversals of both.
#include "bvh/bvh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>

#include "../shaders/shared/geometry.h"
#include "bvh/binary_build.h"
#include "bvh/parallel_chunks.h"
#include "error.h"

namespace vkmc {
namespace {

float asFloat(uint32_t u) { return std::bit_cast<float>(u); }
uint32_t asUint(float f) { return std::bit_cast<uint32_t>(f); }

// The count a root leaf's node gives its other, empty child (its box is empty: the host walks skip it by count).
constexpr uint32_t kRootLeafEmptyHalf = 0xffffffffu;

void writeChild(BvhGpuNode& gpu, int c, const Aabb& box, uint32_t ref, uint32_t count) {
  gpu.texels[2 * c] = glm::vec4(box.min, asFloat(ref));
  gpu.texels[2 * c + 1] = glm::vec4(box.max, asFloat(count));
}

// The binary layout's boxes one float outwards (after the wide collapse has read them tight): strictly beyond
// their triangles, as the quantized wide boxes are (see quantizeBoxes for why).
void widenByOneFloat(std::vector<BvhGpuNode>& nodes, unsigned threads) {
  const float inf = std::numeric_limits<float>::infinity();
  parallelChunks(nodes.size(), 16384, threads, [&](size_t begin, size_t end) {
    for (size_t n = begin; n < end; ++n)
      for (int c = 0; c < 2; ++c) {
        glm::vec4 &lo = nodes[n].texels[2 * c], &hi = nodes[n].texels[2 * c + 1];
        if (!(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z)) continue;  // the empty half of a root leaf
        for (int a = 0; a < 3; ++a) lo[a] = std::nextafter(lo[a], -inf), hi[a] = std::nextafter(hi[a], inf);
      }
  });
}

// x - origin as d + e exactly (Knuth's TwoSum): a float's difference from the grid origin is not always a double
// (6e-17 against -1 needs 77 bits), so plane positions are compared through this pair, never through d alone.
struct ExactOffset {
  double d, e;
};
ExactOffset exactOffset(float x, float origin) {
  double a = x, b = -double(origin), d = a + b, bv = d - a;
  return {d, (a - (d - bv)) + (b - bv)};
}
// Whether the plane origin + qs (qs = steps * step, exact in double) lies strictly below / above x. When
// qs != d the rounded d already orders them (a double strictly between d + e and d would be nearer than d).
bool planeBelow(double qs, ExactOffset o) { return qs < o.d || (qs == o.d && o.e > 0.0); }
bool planeAbove(double qs, ExactOffset o) { return qs > o.d || (qs == o.d && o.e < 0.0); }

// The grid of a wide node and its children's boxes in 8-bit steps, rounded strictly outwards and checked exactly:
// every decoded plane lies beyond its child as a real number. Strictly, because a ray with a zero direction
// component that starts exactly on a box's far plane gets a far distance of 0 and culls the box: its triangles,
// which it can touch on an edge, lie strictly inside the quantized box, so such a ray cannot touch them.
// Entries are left empty.
template <typename Child>
BvhWideNode quantizeBoxes(std::span<const Child> children) {
  BvhWideNode out{};
  Aabb all;
  for (const Child& c : children) all.grow(c.box);
  using namespace gpu;
  out.texels[kBvhWideXyPlanesTexel] =
      glm::uvec4(kBvhWideEmptyLoWord, kBvhWideEmptyHiWord, kBvhWideEmptyLoWord, kBvhWideEmptyHiWord);
  out.texels[kBvhWideZPlanesTexel] = glm::uvec4(kBvhWideEmptyLoWord, kBvhWideEmptyHiWord, 0u, 0u);
  out.texels[kBvhWideChildTexel] = glm::uvec4(kBvhEmptySlot);
  glm::uvec3 exponents(0u);
  for (int axis = 0; axis < 3; ++axis) {
    // One float below the lowest child, so that plane 0 is strictly below it too (unless that overflows); never
    // a denormal, which a GPU that flushes denormals would read as 0 (the next normal float down instead).
    float below = std::nextafter(all.min[axis], -std::numeric_limits<float>::infinity());
    if (std::abs(below) < std::numeric_limits<float>::min())
      below = all.min[axis] > 0.0f ? 0.0f : -std::numeric_limits<float>::min();
    const float origin = std::isfinite(below) ? below : all.min[axis];
    out.texels[kBvhWideGridTexel][axis] = asUint(origin);
    // Start from the smallest power of two with 255 steps >= the extent (an estimate: the extent's double may
    // be rounded), within the normal floats; one step coarser whenever a child's top does not fit.
    int e = 0;
    std::frexp((double(all.max[axis]) - double(origin)) / 255.0, &e);
    // Never finer than the float spacing of the node's coordinates: every plane is then a float, as the GPU
    // decodes it.
    int magnitude = 0;
    std::frexp(double(std::max(std::abs(all.min[axis]), std::abs(all.max[axis]))), &magnitude);
    int biased = std::clamp(std::max(e, magnitude - 24) + 127, 1, 254);
    std::array<uint32_t, 4> qlo{}, qhi{};
    for (;; ++biased) {
      if (biased > 254) throw Error("internal error: a BVH node's extent does not fit the quantized grid");
      const double step = std::ldexp(1.0, biased - 127);
      bool fits = true;
      for (size_t i = 0; i < children.size() && fits; ++i) {
        ExactOffset lo = exactOffset(children[i].box.min[axis], origin);
        ExactOffset hi = exactOffset(children[i].box.max[axis], origin);
        double guessLo = std::floor(lo.d / step), guessHi = std::ceil(hi.d / step);
        int l = int(std::clamp(guessLo + 1.0, 0.0, 255.0)), h = int(std::clamp(guessHi - 1.0, 0.0, 256.0));
        while (l > 0 && !planeBelow(l * step, lo)) --l;  // l = 0 is the origin: below every child
        while (h <= 255 && !planeAbove(h * step, hi)) ++h;
        fits = h <= 255;
        qlo[i] = uint32_t(l), qhi[i] = uint32_t(h);
      }
      if (fits) break;
    }
    exponents[axis] = uint32_t(biased);
    uint32_t& loWord = axis < 2 ? out.texels[kBvhWideXyPlanesTexel][2 * axis] : out.texels[kBvhWideZPlanesTexel][0];
    uint32_t& hiWord = axis < 2 ? out.texels[kBvhWideXyPlanesTexel][2 * axis + 1] : out.texels[kBvhWideZPlanesTexel][1];
    for (uint32_t i = 0; i < children.size(); ++i) {
      loWord = bvhWideSetPlaneSteps(loWord, i, qlo[i]);
      hiWord = bvhWideSetPlaneSteps(hiWord, i, qhi[i]);
    }
  }
  out.texels[kBvhWideGridTexel].w = bvhWideStepExponents(exponents);
  return out;
}

// The 4-wide tree's depth in inner nodes, and the most entries a walk can pend (BvhStats::wideMaxPending).
void wideDepthAndPending(const std::vector<BvhWideNode>& wide, uint32_t& maxDepth, uint32_t& maxPending) {
  maxDepth = maxPending = 0;
  if (wide.empty()) return;
  struct Visit {
    uint32_t node, depth, pendingAbove;  // inner nodes from the root down to it; entries its ancestors pend
  };
  std::vector<Visit> stack{{0u, 1u, 0u}};
  while (!stack.empty()) {
    Visit v = stack.back();
    stack.pop_back();
    uint32_t children = 0;
    for (int c = 0; c < 4; ++c) children += wide[v.node].texels[gpu::kBvhWideChildTexel][c] != gpu::kBvhEmptySlot;
    const uint32_t pending = v.pendingAbove + (children > 0 ? children - 1 : 0);
    maxDepth = std::max(maxDepth, v.depth);
    maxPending = std::max(maxPending, pending);
    for (int c = 0; c < 4; ++c) {
      uint32_t entry = wide[v.node].texels[gpu::kBvhWideChildTexel][c];
      if (entry != gpu::kBvhEmptySlot && !gpu::bvhIsLeaf(entry)) stack.push_back({entry, v.depth + 1, pending});
    }
  }
}

// Collapses the binary GPU layout into 4-wide nodes: a node's children are its binary children, the inner one
// with the largest surface opened in turn until there are four (Wald et al. 2008's collapse). The shape is planned
// in one pass; the boxes, the costly part, are quantized on every thread.
// wideSahCost: the 4-wide tree's expected wide node steps plus triangle tests per ray (cost 1 each).
// A child of the collapse is a slot of a binary node: 2 * node + side. The plan keeps slots, not boxes (it is as
// many entries as wide nodes, and its memory is most of the collapse's time).
struct BinarySlots {
  const std::vector<BvhGpuNode>& binary;
  uint32_t count(uint32_t slot) const { return asUint(binary[slot / 2].texels[2 * (slot % 2) + 1].w); }
  uint32_t ref(uint32_t slot) const { return asUint(binary[slot / 2].texels[2 * (slot % 2)].w); }
  Aabb box(uint32_t slot) const {
    const glm::vec4* t = &binary[slot / 2].texels[2 * (slot % 2)];
    return Aabb{glm::vec3(t[0]), glm::vec3(t[1])};
  }
};

// A wide node's plan: its children's slots.
struct WidePlan {
  std::array<uint32_t, 4> slot, entry;  // entry: the wide node of an inner child
  uint32_t size = 0;
};

// The wide nodes' boxes quantized from their plans, on every thread.
std::vector<BvhWideNode> quantizeWideNodes(const BinarySlots& slots, const std::vector<WidePlan>& plans, unsigned threads) {
  struct Child {
    Aabb box;
  };
  std::vector<BvhWideNode> wide(plans.size());
  parallelChunks(plans.size(), 4096, threads, [&](size_t begin, size_t end) {
    for (size_t w = begin; w < end; ++w) {
      const WidePlan& plan = plans[w];
      std::array<Child, 4> children;
      for (uint32_t i = 0; i < plan.size; ++i) children[i].box = slots.box(plan.slot[i]);
      wide[w] = quantizeBoxes(std::span<const Child>(children.data(), plan.size));
      for (uint32_t i = 0; i < plan.size; ++i) {
        const uint32_t slot = plan.slot[i];
        wide[w].texels[gpu::kBvhWideChildTexel][i] =
            slots.count(slot) > 0 ? gpu::bvhLeafEntry(slots.ref(slot), slots.count(slot)) : plan.entry[i];
      }
    }
  });
  return wide;
}

std::vector<BvhWideNode> collapseToWide(const std::vector<BvhGpuNode>& binary, unsigned threads, double& wideSahCost) {
  const BinarySlots slots{binary};
  auto count = [&](uint32_t slot) { return slots.count(slot); };
  auto ref = [&](uint32_t slot) { return slots.ref(slot); };
  auto box = [&](uint32_t slot) { return slots.box(slot); };
  using Plan = WidePlan;
  std::vector<Plan> plans(1);
  plans.reserve(binary.size());                                // a wide node per binary inner node at most
  std::vector<std::pair<uint32_t, uint32_t>> tasks{{0u, 0u}};  // (binary node, wide node)
  wideSahCost = 0.0;
  double rootArea = 1.0;
  while (!tasks.empty()) {
    auto [node, w] = tasks.back();
    tasks.pop_back();
    Plan plan;
    std::array<double, 4> area{};
    auto addChildrenOf = [&](uint32_t n) {
      for (uint32_t slot = 2 * n; slot < 2 * n + 2; ++slot) {
        if (count(slot) == kRootLeafEmptyHalf) continue;
        area[plan.size] = count(slot) ? 0.0 : box(slot).halfArea();
        plan.slot[plan.size++] = slot;
      }
    };
    addChildrenOf(node);
    while (plan.size < 4) {
      int open = -1;
      for (int i = 0; i < int(plan.size); ++i)
        if (count(plan.slot[i]) == 0 && (open < 0 || area[i] > area[open])) open = i;
      if (open < 0) break;
      uint32_t inner = ref(plan.slot[open]);
      for (uint32_t i = open; i + 1 < plan.size; ++i) plan.slot[i] = plan.slot[i + 1], area[i] = area[i + 1];
      --plan.size;
      addChildrenOf(inner);
    }
    for (uint32_t i = 0; i < plan.size; ++i) {
      const uint32_t slot = plan.slot[i];
      if (count(slot) > 0) {
        if (count(slot) > gpu::kBvhMaxLeafSize || ref(slot) >= gpu::kBvhLeafFirstLimit)
          throw Error("BVH leaf of " + std::to_string(count(slot)) + " triangles at " + std::to_string(ref(slot)) +
                      " does not fit the 4-wide node layout");
        continue;
      }
      plan.entry[i] = static_cast<uint32_t>(plans.size());
      plans.emplace_back();
      tasks.push_back({ref(slot), plan.entry[i]});
    }
    plans[w] = plan;
    Aabb nodeBox;
    for (uint32_t i = 0; i < plan.size; ++i) {
      nodeBox.grow(box(plan.slot[i]));
      if (count(plan.slot[i]) > 0) wideSahCost += box(plan.slot[i]).halfArea() * count(plan.slot[i]);
    }
    wideSahCost += nodeBox.halfArea();
    if (w == 0) rootArea = std::max(nodeBox.halfArea(), 1e-300);
  }
  wideSahCost /= rootArea;
  return quantizeWideNodes(slots, plans, threads);
}

}  // namespace

Bvh buildBvh(std::span<const Aabb> bounds, const BvhOptions& options) {
  auto start = std::chrono::steady_clock::now();
  BinaryTree tree = buildBinaryTree(bounds, options);
  const std::vector<BuildNode>& nodes = tree.nodes;

  Bvh bvh;
  bvh.triangleOrder = std::move(tree.order);
  // Inner build nodes become GPU nodes in depth-first order; a root leaf gets a node with one empty child.
  std::vector<uint32_t> gpuIndex(nodes.size(), 0);
  std::vector<uint32_t> stack{0};
  std::vector<uint32_t> innerOrder;
  while (!stack.empty()) {
    uint32_t n = stack.back();
    stack.pop_back();
    if (nodes[n].count > 0 && n != 0) continue;
    gpuIndex[n] = static_cast<uint32_t>(innerOrder.size());
    innerOrder.push_back(n);
    if (nodes[n].count == 0) {
      stack.push_back(nodes[n].child[1]);
      stack.push_back(nodes[n].child[0]);
    }
  }
  bvh.nodes.resize(innerOrder.size());
  BvhStats& s = bvh.stats;
  double rootArea = std::max(nodes[0].bounds.halfArea(), 1e-300);
  for (size_t g = 0; g < innerOrder.size(); ++g) {
    const BuildNode& node = nodes[innerOrder[g]];
    BvhGpuNode& gpu = bvh.nodes[g];
    if (node.count > 0) {  // root leaf
      writeChild(gpu, 0, node.bounds, node.first, node.count);
      writeChild(gpu, 1, Aabb{}, 0, kRootLeafEmptyHalf);
      s.leaves = 1;
      s.maxLeafSize = node.count;
      s.sahCost = options.triangleCost * node.count;
      continue;
    }
    ++s.innerNodes;
    s.sahCost += options.traversalCost * node.bounds.halfArea() / rootArea;
    for (int c = 0; c < 2; ++c) {
      const BuildNode& child = nodes[node.child[c]];
      if (child.count > 0) {
        writeChild(gpu, c, child.bounds, child.first, child.count);
        ++s.leaves;
        s.maxLeafSize = std::max(s.maxLeafSize, child.count);
        s.sahCost += options.triangleCost * child.count * child.bounds.halfArea() / rootArea;
      } else {
        writeChild(gpu, c, child.bounds, gpuIndex[node.child[c]], 0);
      }
    }
  }
  s.maxDepth = tree.maxDepth;
  s.buildThreads = tree.threads;
  s.averageLeafSize = s.leaves ? static_cast<double>(bounds.size()) / s.leaves : 0.0;
  bvh.wideNodes = collapseToWide(bvh.nodes, tree.threads, s.wideSahCost);
  wideDepthAndPending(bvh.wideNodes, s.wideMaxDepth, s.wideMaxPending);
  widenByOneFloat(bvh.nodes, tree.threads);
  s.buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return bvh;
}

namespace {

// The host walks' shared pieces: the slab test as the GPU does it (far distance widened by 2 gamma(3)) and a
// leaf's triangles against the best hit so far.
bool slabHit(const Aabb& box, glm::vec3 origin, glm::vec3 inv, float tBest) {
  glm::vec3 t0 = (box.min - origin) * inv, t1 = (box.max - origin) * inv;
  glm::vec3 tn = glm::min(t0, t1), tf = glm::max(t0, t1);
  float near = std::max(std::max(tn.x, tn.y), std::max(tn.z, 0.0f));
  float far = std::min(std::min(tf.x, tf.y) * gpu::kSlabWiden, std::min(tf.z * gpu::kSlabWiden, tBest));
  return near <= far;
}

bool intersectLeaf(const gpu::RayShear& shear, std::span<const glm::vec3> pos, uint32_t first, uint32_t count, float& tBest,
                   HostHit& best, bool anyHit) {
  for (uint32_t tri = first; tri < first + count; ++tri) {
    glm::vec3 h = gpu::intersectTriangle(shear, pos[3 * tri], pos[3 * tri + 1], pos[3 * tri + 2], tBest);
    if (h.x > 0.0f) {
      tBest = h.x;
      best = {h.x, h.y, h.z, tri};
      if (anyHit) return true;
    }
  }
  return false;
}

}  // namespace

HostHit traceHost(const Bvh& bvh, std::span<const glm::vec3> pos, glm::vec3 origin, glm::vec3 dir, float tMax, bool anyHit) {
  gpu::RayShear shear = gpu::makeRayShear(origin, dir);
  glm::vec3 inv = gpu::safeInverse(dir);
  HostHit best;
  float tBest = tMax;
  std::vector<uint32_t> stack{0};
  while (!stack.empty()) {
    const BvhGpuNode& node = bvh.nodes[stack.back()];
    stack.pop_back();
    for (int c = 0; c < 2; ++c) {
      if (!slabHit(Aabb{glm::vec3(node.texels[2 * c]), glm::vec3(node.texels[2 * c + 1])}, origin, inv, tBest)) continue;
      uint32_t ref = asUint(node.texels[2 * c].w), count = asUint(node.texels[2 * c + 1].w);
      if (count == kRootLeafEmptyHalf) continue;
      if (count == 0)
        stack.push_back(ref);
      else if (intersectLeaf(shear, pos, ref, count, tBest, best, anyHit))
        return best;
    }
  }
  return best;
}

HostHit traceHostWide(const Bvh& bvh, std::span<const glm::vec3> pos, glm::vec3 origin, glm::vec3 dir, float tMax, bool anyHit) {
  gpu::RayShear shear = gpu::makeRayShear(origin, dir);
  glm::vec3 inv = gpu::safeInverse(dir);
  HostHit best;
  float tBest = tMax;
  std::vector<uint32_t> stack{0};
  while (!stack.empty()) {
    const BvhWideNode& node = bvh.wideNodes[stack.back()];
    stack.pop_back();
    for (int c = 0; c < 4; ++c) {
      uint32_t entry = node.texels[gpu::kBvhWideChildTexel][c];
      if (entry == gpu::kBvhEmptySlot || !slabHit(wideChildBox(node, c), origin, inv, tBest)) continue;
      if (!gpu::bvhIsLeaf(entry))
        stack.push_back(entry);
      else if (intersectLeaf(shear, pos, gpu::bvhLeafFirst(entry), gpu::bvhLeafCount(entry), tBest, best, anyHit))
        return best;
    }
  }
  return best;
}

float walkHost(const Bvh& bvh, std::span<const glm::vec3> pos, glm::vec3 origin, glm::vec3 dir, float tMax,
               const HostVisit& visit) {
  gpu::RayShear shear = gpu::makeRayShear(origin, dir);
  glm::vec3 inv = gpu::safeInverse(dir);
  std::vector<uint32_t> stack{0};
  while (!stack.empty() && !bvh.nodes.empty()) {
    const BvhGpuNode& node = bvh.nodes[stack.back()];
    stack.pop_back();
    for (int c = 0; c < 2; ++c) {
      if (!slabHit(Aabb{glm::vec3(node.texels[2 * c]), glm::vec3(node.texels[2 * c + 1])}, origin, inv, tMax)) continue;
      uint32_t ref = asUint(node.texels[2 * c].w), count = asUint(node.texels[2 * c + 1].w);
      if (count == kRootLeafEmptyHalf) continue;
      if (count == 0) {
        stack.push_back(ref);
        continue;
      }
      for (uint32_t tri = ref; tri < ref + count; ++tri) {
        const glm::vec3* p = &pos[3 * tri];
        glm::vec3 h = gpu::intersectTriangle(shear, p[0], p[1], p[2], tMax);
        if (h.x <= 0.0f) continue;
        // From behind exactly as the kernels' cull test decides it: the culled test misses where the plain one hit.
        const bool fromBehind = gpu::intersectTriangle(shear, p[0], p[1], p[2], tMax, true).x <= 0.0f;
        tMax = visit(tri, h.x, fromBehind, tMax);
      }
    }
  }
  return tMax;
}

// origin + qs rounded to a float outwards (down for a low plane, up for a high one): the decoded box contains
// the exact plane, so containment checks on it are exact.
float roundedPlane(float origin, double qs, bool up) {
  double s = double(origin) + qs, bv = s - origin, err = (double(origin) - (s - bv)) + (qs - bv);  // exact: s + err
  float f = float(s);
  double fMinusS = double(f) - s;  // exact (Sterbenz): f is within a rounding of s
  if (up && fMinusS < err) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  if (!up && fMinusS > err) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}

Aabb wideChildBox(const BvhWideNode& node, int i) {
  Aabb box;
  using namespace gpu;
  if (node.texels[kBvhWideChildTexel][i] == kBvhEmptySlot) return box;
  const glm::uvec4 grid = node.texels[kBvhWideGridTexel];
  const glm::vec3 step = bvhWideStep(grid.w);  // powers of two: exact in double too
  for (uint32_t axis = 0; axis < 3; ++axis) {
    glm::uvec2 words = bvhWidePlaneWords(node.texels[kBvhWideXyPlanesTexel], node.texels[kBvhWideZPlanesTexel], axis);
    float origin = asFloat(grid[axis]);
    box.min[axis] = roundedPlane(origin, double(bvhWidePlaneSteps(words.x)[i]) * double(step[axis]), false);
    box.max[axis] = roundedPlane(origin, double(bvhWidePlaneSteps(words.y)[i]) * double(step[axis]), true);
  }
  return box;
}

bool walksCanOutgrowRegisterStack(const BvhStats& stats) { return stats.wideMaxPending > registerStackEntries(stats); }

uint32_t registerStackEntries(const BvhStats& stats) {
  for (uint32_t entries : {4u, 8u})
    if (stats.wideMaxPending <= entries) return entries;
  return gpu::kBvhRegisterStackEntries;
}

}  // namespace vkmc
