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
    glm::vec3 extent = centroidBox.extent();
    float bestCost = std::numeric_limits<float>::infinity();
    int bestAxis = -1;
    uint32_t bestBin = 0;
    std::array<Aabb, 64> binBox;
    std::array<uint32_t, 64> binCount;
    std::array<float, 64> rightArea;
    std::array<uint32_t, 64> rightCount;
    for (int axis = 0; axis < 3; ++axis) {
      if (!(extent[axis] > 0.0f)) continue;
      float scale = static_cast<float>(bins) / extent[axis];
      std::fill_n(binBox.begin(), bins, Aabb{});
      std::fill_n(binCount.begin(), bins, 0u);
      for (uint32_t i = first; i < first + count; ++i) {
        uint32_t tri = order_[i];
        uint32_t b = std::min(bins - 1, static_cast<uint32_t>((centroids_[tri][axis] - centroidBox.min[axis]) * scale));
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
        float cost = acc.halfArea() * static_cast<float>(n) + rightArea[b + 1] * static_cast<float>(rightCount[b + 1]);
        if (cost < bestCost) {
          bestCost = cost;
          bestAxis = axis;
          bestBin = b + 1;
        }
      }
    }
    float parentArea = box.halfArea();
    float leafCost = options_.triangleCost * static_cast<float>(count);
    float splitCost = options_.traversalCost + options_.triangleCost * bestCost / std::max(parentArea, 1e-30f);
    if (bestAxis < 0) {
      if (!mustSplit) return 0;
      return count / 2;  // all centroids coincide: split by index
    }
    if (!mustSplit && splitCost >= leafCost) return 0;
    float scale = static_cast<float>(bins) / extent[bestAxis];
    auto mid = std::partition(order_.begin() + first, order_.begin() + first + count, [&](uint32_t tri) {
      uint32_t b = std::min(bins - 1, static_cast<uint32_t>((centroids_[tri][bestAxis] - centroidBox.min[bestAxis]) * scale));
      return b < bestBin;
    });
    uint32_t left = static_cast<uint32_t>(mid - (order_.begin() + first));
    return (left == 0 || left == count) ? count / 2 : left;
  }

  // Every split between centroid-sorted neighbours along every axis (ties broken by index: deterministic).
  uint32_t sweepSplit(uint32_t first, uint32_t count, const Aabb& box, bool mustSplit) {
    float bestCost = std::numeric_limits<float>::infinity();
    uint32_t bestLeft = 0;
    std::vector<uint32_t> sorted(count), best;
    std::vector<float> rightArea(count);
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
        float cost = acc.halfArea() * static_cast<float>(i) + rightArea[i] * static_cast<float>(count - i);
        if (cost < bestCost) {
          bestCost = cost;
          bestLeft = i;
          improved = true;
        }
      }
      if (improved) best = sorted;
    }
    float leafCost = options_.triangleCost * static_cast<float>(count);
    float splitCost = options_.traversalCost + options_.triangleCost * bestCost / std::max(box.halfArea(), 1e-30f);
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

// The grid of a wide node and its children's boxes in 8-bit steps, rounded outwards (in double, where a float's
// difference and a power-of-two step are exact). Entries are left empty.
template <typename Child>
BvhWideNode quantizeBoxes(const std::vector<Child>& children) {
  BvhWideNode out{};
  Aabb all;
  for (const Child& c : children) all.grow(c.box);
  uint32_t exponents = 0;
  std::array<double, 3> origin{}, step{};
  for (int axis = 0; axis < 3; ++axis) {
    origin[axis] = all.min[axis];
    // The smallest power of two with 255 steps >= the extent, within the normal floats.
    int e = 0;
    std::frexp((double(all.max[axis]) - double(all.min[axis])) / 255.0, &e);
    int biased = std::clamp(e + 127, 1, 254);
    step[axis] = std::ldexp(1.0, biased - 127);
    exponents |= uint32_t(biased) << (8 * axis);
    out.texels[0][axis] = asUint(all.min[axis]);
  }
  out.texels[0].w = exponents;
  out.texels[1] = glm::uvec4(0xffffffffu, 0u, 0xffffffffu, 0u);  // empty slots: lo = 255 > hi = 0
  out.texels[2] = glm::uvec4(0xffffffffu, 0u, 0u, 0u);
  out.texels[3] = glm::uvec4(kBvhEmptySlot);
  for (size_t i = 0; i < children.size(); ++i)
    for (int axis = 0; axis < 3; ++axis) {
      double lo = std::floor((double(children[i].box.min[axis]) - origin[axis]) / step[axis]);
      double hi = std::ceil((double(children[i].box.max[axis]) - origin[axis]) / step[axis]);
      uint32_t qlo = uint32_t(std::clamp(lo, 0.0, 255.0)), qhi = uint32_t(std::clamp(hi, 0.0, 255.0));
      if (origin[axis] + qlo * step[axis] > children[i].box.min[axis] ||
          origin[axis] + qhi * step[axis] < children[i].box.max[axis])
        throw Error("internal error: a quantized BVH box does not contain its child");
      uint32_t& loWord = axis < 2 ? out.texels[1][2 * axis] : out.texels[2][0];
      uint32_t& hiWord = axis < 2 ? out.texels[1][2 * axis + 1] : out.texels[2][1];
      loWord = (loWord & ~(0xffu << (8 * i))) | (qlo << (8 * i));
      hiWord = (hiWord & ~(0xffu << (8 * i))) | (qhi << (8 * i));
    }
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
        if (c.count > 8 || c.ref >= (1u << 27)) throw Error("BVH leaf of " + std::to_string(c.count) + " triangles at " +
                                                            std::to_string(c.ref) + " does not fit the 4-wide node layout");
        entry = kBvhLeafTag | ((c.count - 1u) << 27) | c.ref;
      } else {
        entry = static_cast<uint32_t>(wide.size());
        wide.emplace_back();
        tasks.push_back({c.ref, entry});
      }
      out.texels[3][i] = entry;
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
  double rootArea = std::max(nodes[0].bounds.halfArea(), 1e-30f);
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
  s.buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return bvh;
}

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
      glm::vec3 lo = glm::vec3(node.texels[2 * c]), hi = glm::vec3(node.texels[2 * c + 1]);
      glm::vec3 t0 = (lo - origin) * inv, t1 = (hi - origin) * inv;
      glm::vec3 tn = glm::min(t0, t1), tf = glm::max(t0, t1);
      float near = std::max(std::max(tn.x, tn.y), std::max(tn.z, 0.0f));
      float far = std::min(std::min(tf.x, tf.y) * gpu::kSlabWiden, std::min(tf.z * gpu::kSlabWiden, tBest));
      if (!(near <= far)) continue;
      uint32_t ref = asUint(node.texels[2 * c].w), count = asUint(node.texels[2 * c + 1].w);
      if (count == 0) {
        stack.push_back(ref);
        continue;
      }
      for (uint32_t tri = ref; tri < ref + count; ++tri) {
        glm::vec3 h = gpu::intersectTriangle(shear, pos[3 * tri], pos[3 * tri + 1], pos[3 * tri + 2], tBest);
        if (h.x > 0.0f) {
          tBest = h.x;
          best = {h.x, h.y, h.z, tri};
          if (anyHit) return best;
        }
      }
    }
  }
  return best;
}

Aabb wideChildBox(const BvhWideNode& node, int i) {
  Aabb box;
  if (node.texels[3][i] == kBvhEmptySlot) return box;
  for (int axis = 0; axis < 3; ++axis) {
    double step = std::ldexp(1.0, int((node.texels[0].w >> (8 * axis)) & 0xffu) - 127);
    double origin = asFloat(node.texels[0][axis]);
    uint32_t lo = axis < 2 ? node.texels[1][2 * axis] : node.texels[2][0];
    uint32_t hi = axis < 2 ? node.texels[1][2 * axis + 1] : node.texels[2][1];
    box.min[axis] = float(origin + ((lo >> (8 * i)) & 0xffu) * step);
    box.max[axis] = float(origin + ((hi >> (8 * i)) & 0xffu) * step);
  }
  return box;
}

}  // namespace vkmc
