// Binned SAH build (Wald 2007): centroid bins on all three axes, in-place partition, explicit work stack.
#include "bvh/bvh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>

#include "../shaders/shared/geometry.h"
#include "error.h"

namespace vkmc {
namespace {

constexpr uint32_t kMaxDepth = 60;  // the GPU traversal stack holds 64 entries

struct BuildNode {
  Aabb bounds;
  uint32_t first = 0, count = 0;  // leaf range, count > 0
  uint32_t child[2] = {0, 0};     // inner node
};

// The centroid's bin: clamped in double before the conversion (a float-to-int cast of inf or NaN is UB).
uint32_t binOf(float centroid, float min, double scale, uint32_t bins) {
  double b = (double(centroid) - double(min)) * scale;
  return b >= double(bins - 1) ? bins - 1 : b > 0.0 ? static_cast<uint32_t>(b) : 0u;
}

float asFloat(uint32_t u) { return std::bit_cast<float>(u); }
uint32_t asUint(float f) { return std::bit_cast<uint32_t>(f); }

class Builder {
 public:
  Builder(std::span<const Aabb> bounds, const BvhOptions& options) : bounds_(bounds), options_(options) {
    centroids_.resize(bounds.size());
    for (size_t i = 0; i < bounds.size(); ++i) centroids_[i] = bounds[i].center();
    order_.resize(bounds.size());
    for (uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
  }

  std::vector<BuildNode> nodes;
  std::vector<uint32_t> order_;
  uint32_t maxDepth = 0;

  void build() {
    nodes.reserve(2 * bounds_.size() / std::max(1u, options_.maxLeafSize / 2) + 1);
    nodes.push_back({});
    struct Task {
      uint32_t node, first, count, depth;
    };
    std::vector<Task> stack{{0, 0, static_cast<uint32_t>(order_.size()), 0}};
    while (!stack.empty()) {
      Task task = stack.back();
      stack.pop_back();
      maxDepth = std::max(maxDepth, task.depth);
      Aabb box, centroidBox;
      for (uint32_t i = task.first; i < task.first + task.count; ++i) {
        box.grow(bounds_[order_[i]]);
        centroidBox.grow(centroids_[order_[i]]);
      }
      nodes[task.node].bounds = box;
      uint32_t mid = split(task.first, task.count, box, centroidBox, task.depth);
      if (mid == 0) {
        nodes[task.node].first = task.first;
        nodes[task.node].count = task.count;
        continue;
      }
      uint32_t left = static_cast<uint32_t>(nodes.size());
      nodes.push_back({});
      nodes.push_back({});
      nodes[task.node].child[0] = left;
      nodes[task.node].child[1] = left + 1;
      stack.push_back({left + 1, task.first + mid, task.count - mid, task.depth + 1});
      stack.push_back({left, task.first, mid, task.depth + 1});
    }
  }

 private:
  // Returns the size of the left part, or 0 to make a leaf.
  uint32_t split(uint32_t first, uint32_t count, const Aabb& box, const Aabb& centroidBox, uint32_t depth) {
    if (count <= 1) return 0;
    bool mustSplit = count > options_.maxLeafSize;
    if (depth >= kMaxDepth) return 0;
    if (options_.fullSweep) return sweepSplit(first, count, box, mustSplit);
    const uint32_t bins = options_.bins;
    // In double: a float extent can overflow (+-3e38) or be denormal, and bins / extent then is inf.
    glm::dvec3 extent = glm::dvec3(centroidBox.max) - glm::dvec3(centroidBox.min);
    double bestCost = std::numeric_limits<double>::infinity();
    int bestAxis = -1;
    uint32_t bestBin = 0;
    std::array<Aabb, 64> binBox;
    std::array<uint32_t, 64> binCount;
    std::array<double, 64> rightArea;
    std::array<uint32_t, 64> rightCount;
    for (int axis = 0; axis < 3; ++axis) {
      if (!(extent[axis] > 0.0f)) continue;
      double scale = bins / extent[axis];
      std::fill_n(binBox.begin(), bins, Aabb{});
      std::fill_n(binCount.begin(), bins, 0u);
      for (uint32_t i = first; i < first + count; ++i) {
        uint32_t tri = order_[i];
        uint32_t b = binOf(centroids_[tri][axis], centroidBox.min[axis], scale, bins);
        binBox[b].grow(bounds_[tri]);
        ++binCount[b];
      }
      Aabb acc;
      uint32_t n = 0;
      for (uint32_t b = bins - 1; b > 0; --b) {
        acc.grow(binBox[b]);
        n += binCount[b];
        rightArea[b] = acc.halfArea();
        rightCount[b] = n;
      }
      acc = Aabb{};
      n = 0;
      for (uint32_t b = 0; b + 1 < bins; ++b) {
        acc.grow(binBox[b]);
        n += binCount[b];
        if (n == 0 || rightCount[b + 1] == 0) continue;
        double cost = acc.halfArea() * n + rightArea[b + 1] * rightCount[b + 1];
        if (cost < bestCost) {
          bestCost = cost;
          bestAxis = axis;
          bestBin = b + 1;
        }
      }
    }
    double parentArea = box.halfArea();
    double leafCost = double(options_.triangleCost) * count;
    double splitCost = options_.traversalCost + options_.triangleCost * bestCost / std::max(parentArea, 1e-300);
    if (bestAxis < 0) {
      if (!mustSplit) return 0;
      return count / 2;  // all centroids coincide: split by index
    }
    if (!mustSplit && splitCost >= leafCost) return 0;
    double scale = bins / extent[bestAxis];
    auto mid = std::partition(order_.begin() + first, order_.begin() + first + count, [&](uint32_t tri) {
      return binOf(centroids_[tri][bestAxis], centroidBox.min[bestAxis], scale, bins) < bestBin;
    });
    uint32_t left = static_cast<uint32_t>(mid - (order_.begin() + first));
    return (left == 0 || left == count) ? count / 2 : left;
  }

  // Every split between centroid-sorted neighbours along every axis (ties broken by index: deterministic).
  uint32_t sweepSplit(uint32_t first, uint32_t count, const Aabb& box, bool mustSplit) {
    double bestCost = std::numeric_limits<double>::infinity();
    uint32_t bestLeft = 0;
    std::vector<uint32_t> sorted(count), best;
    std::vector<double> rightArea(count);
    for (int axis = 0; axis < 3; ++axis) {
      std::copy(order_.begin() + first, order_.begin() + first + count, sorted.begin());
      std::sort(sorted.begin(), sorted.end(), [&](uint32_t a, uint32_t b) {
        float ca = centroids_[a][axis], cb = centroids_[b][axis];
        return ca < cb || (ca == cb && a < b);
      });
      Aabb acc;
      for (uint32_t i = count; i-- > 0;) {
        acc.grow(bounds_[sorted[i]]);
        rightArea[i] = acc.halfArea();
      }
      acc = Aabb{};
      bool improved = false;
      for (uint32_t i = 1; i < count; ++i) {
        acc.grow(bounds_[sorted[i - 1]]);
        double cost = acc.halfArea() * i + rightArea[i] * (count - i);
        if (cost < bestCost) {
          bestCost = cost;
          bestLeft = i;
          improved = true;
        }
      }
      if (improved) best = sorted;
    }
    double leafCost = double(options_.triangleCost) * count;
    double splitCost = options_.traversalCost + options_.triangleCost * bestCost / std::max(box.halfArea(), 1e-300);
    if (!mustSplit && splitCost >= leafCost) return 0;
    std::copy(best.begin(), best.end(), order_.begin() + first);
    return bestLeft;
  }

  std::span<const Aabb> bounds_;
  BvhOptions options_;
  std::vector<glm::vec3> centroids_;
};

void writeChild(BvhGpuNode& gpu, int c, const Aabb& box, uint32_t ref, uint32_t count) {
  gpu.texels[2 * c] = glm::vec4(box.min, asFloat(ref));
  gpu.texels[2 * c + 1] = glm::vec4(box.max, asFloat(count));
}

// The binary layout's boxes one float outwards (after the wide collapse has read them tight): strictly beyond
// their triangles, as the quantized wide boxes are (see quantizeBoxes for why).
void widenByOneFloat(std::vector<BvhGpuNode>& nodes) {
  const float inf = std::numeric_limits<float>::infinity();
  for (BvhGpuNode& node : nodes)
    for (int c = 0; c < 2; ++c) {
      glm::vec4 &lo = node.texels[2 * c], &hi = node.texels[2 * c + 1];
      if (!(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z)) continue;  // the empty half of a root leaf
      for (int a = 0; a < 3; ++a) lo[a] = std::nextafter(lo[a], -inf), hi[a] = std::nextafter(hi[a], inf);
    }
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
BvhWideNode quantizeBoxes(const std::vector<Child>& children) {
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

// Collapses the binary GPU layout into 4-wide nodes: a node's children are its binary children, the inner one
// with the largest surface opened in turn until there are four (Wald et al. 2008's collapse).
std::vector<BvhWideNode> collapseToWide(const std::vector<BvhGpuNode>& binary) {
  struct Child {
    Aabb box;
    uint32_t ref = 0, count = 0;  // count 0: binary inner node `ref`
  };
  auto childrenOf = [&](uint32_t node, std::vector<Child>& out) {
    for (int c = 0; c < 2; ++c) {
      const glm::vec4 lo = binary[node].texels[2 * c], hi = binary[node].texels[2 * c + 1];
      uint32_t count = asUint(hi.w);
      if (count == 0xffffffffu) continue;  // the empty half of a root leaf
      out.push_back({Aabb{glm::vec3(lo), glm::vec3(hi)}, asUint(lo.w), count});
    }
  };
  std::vector<BvhWideNode> wide(1);
  std::vector<std::pair<uint32_t, uint32_t>> tasks{{0u, 0u}};  // (binary node, wide node)
  while (!tasks.empty()) {
    auto [node, w] = tasks.back();
    tasks.pop_back();
    std::vector<Child> children;
    childrenOf(node, children);
    while (children.size() < 4) {
      int open = -1;
      for (int i = 0; i < int(children.size()); ++i)
        if (children[i].count == 0 && (open < 0 || children[i].box.halfArea() > children[open].box.halfArea())) open = i;
      if (open < 0) break;
      uint32_t inner = children[open].ref;
      children.erase(children.begin() + open);
      childrenOf(inner, children);
    }
    BvhWideNode out = quantizeBoxes(children);
    for (size_t i = 0; i < children.size(); ++i) {
      const Child& c = children[i];
      uint32_t entry;
      if (c.count > 0) {
        if (c.count > gpu::kBvhMaxLeafSize || c.ref >= gpu::kBvhLeafFirstLimit)
          throw Error("BVH leaf of " + std::to_string(c.count) + " triangles at " + std::to_string(c.ref) +
                      " does not fit the 4-wide node layout");
        entry = gpu::bvhLeafEntry(c.ref, c.count);
      } else {
        entry = static_cast<uint32_t>(wide.size());
        wide.emplace_back();
        tasks.push_back({c.ref, entry});
      }
      out.texels[gpu::kBvhWideChildTexel][i] = entry;
    }
    wide[w] = out;
  }
  return wide;
}

}  // namespace

Bvh buildBvh(std::span<const Aabb> bounds, const BvhOptions& options) {
  auto start = std::chrono::steady_clock::now();
  Builder builder(bounds, options);
  builder.build();
  const std::vector<BuildNode>& nodes = builder.nodes;

  Bvh bvh;
  bvh.triangleOrder = std::move(builder.order_);
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
      writeChild(gpu, 1, Aabb{}, 0, 0xffffffffu);
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
  s.maxDepth = builder.maxDepth;
  s.averageLeafSize = s.leaves ? static_cast<double>(bounds.size()) / s.leaves : 0.0;
  bvh.wideNodes = collapseToWide(bvh.nodes);
  widenByOneFloat(bvh.nodes);
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

}  // namespace vkmc
