// Binned SAH build over 32-byte primitive references (a triangle's box and its index), so that every pass streams
// memory instead of chasing an index: per node one binning pass over all three axes, whose bins keep boxes and
// centroid boxes (the children's bounds come with the split), and one partition pass. Nodes above a size limit
// bin on all threads; the subtrees below it build in parallel, each into its own node list, stitched in a fixed
// order. Every split is the same function of the same references, so the tree does not depend on the threads.
#include "bvh/binary_build.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <thread>

#include "bvh/parallel_chunks.h"
#include "error.h"

namespace vkmc {
namespace {

constexpr uint32_t kMaxDepth = 60;  // the GPU traversal stack holds 64 entries
constexpr uint32_t kMaxBins = 64;
constexpr uint32_t kParallelBinningMin = 1u << 15;  // smaller nodes bin on one thread: spawning costs more
constexpr uint32_t kMinSubtree = 4096;              // the subtree phase's tasks are at least this large

// Four floats in one SSE/NEON register (GCC and Clang vector extensions); lane 3 is never read as geometry.
using v4 = float __attribute__((vector_size(16)));
using v4i = int32_t __attribute__((vector_size(16)));
constexpr float kInf = std::numeric_limits<float>::infinity();

inline v4 vmin(v4 a, v4 b) { return a < b ? a : b; }
inline v4 vmax(v4 a, v4 b) { return a > b ? a : b; }

struct Box4 {
  v4 lo = {kInf, kInf, kInf, 0.0f}, hi = {-kInf, -kInf, -kInf, 0.0f};
  void grow(v4 l, v4 h) { lo = vmin(lo, l), hi = vmax(hi, h); }
  void grow(const Box4& b) { grow(b.lo, b.hi); }
  Aabb aabb() const { return Aabb{glm::vec3(lo[0], lo[1], lo[2]), glm::vec3(hi[0], hi[1], hi[2])}; }
};

// As Aabb::halfArea, in double (a float extent product overflows past ~1e19); 0 for an empty box.
double halfArea(const Box4& b) {
  double e[3];
  for (int a = 0; a < 3; ++a) e[a] = std::max(double(b.hi[a]) - double(b.lo[a]), 0.0);
  return e[0] * e[1] + e[1] * e[2] + e[2] * e[0];
}

struct PrimRef {
  v4 lo, hi;  // the triangle's box; lo's lane 3 holds the triangle's index, hi's is 0
  uint32_t index() const { return uint32_t(std::bit_cast<v4i>(lo)[3]); }
  // Halves first: lo + hi could overflow.
  v4 centroid() const {
    v4 l = std::bit_cast<v4>(std::bit_cast<v4i>(lo) & v4i{-1, -1, -1, 0});
    return l * v4{0.5f, 0.5f, 0.5f, 0.0f} + hi * v4{0.5f, 0.5f, 0.5f, 0.0f};
  }
};
static_assert(sizeof(PrimRef) == 32);

// Centroid bins along each axis. An axis whose extent is 0 (or whose bins / extent is no finite float) has
// scale 0: everything falls in bin 0 and it offers no split. NaN lands in bin 0 too. Binning and partition use
// this one function, so the partition's sides hold exactly the bins' counts.
struct BinGrid {
  v4 origin{}, scale{}, last{};
  bool usable[3] = {false, false, false};
  BinGrid(const Box4& centroids, uint32_t bins) {
    last = v4{1, 1, 1, 0} * float(bins - 1);
    for (int a = 0; a < 3; ++a) {
      double extent = double(centroids.hi[a]) - double(centroids.lo[a]);
      float k = extent > 0.0 ? float(bins / extent) : 0.0f;
      usable[a] = std::isfinite(k) && k > 0.0f;
      origin[a] = centroids.lo[a];
      scale[a] = usable[a] ? k : 0.0f;
    }
  }
  v4i binsOf(v4 centroid) const {
    v4 f = vmin(vmax((centroid - origin) * scale, v4{}), last);
    return __builtin_convertvector(f, v4i);
  }
};

struct Bin {
  Box4 box, centroids;
  uint32_t count = 0;
};
using AxisBins = std::array<std::array<Bin, kMaxBins>, 3>;

void binRange(const PrimRef* refs, uint32_t n, const BinGrid& grid, uint32_t bins, AxisBins& out) {
  for (auto& axis : out) std::fill_n(axis.begin(), bins, Bin{});
  for (uint32_t i = 0; i < n; ++i) {
    const PrimRef& r = refs[i];
    v4 c = r.centroid();
    v4i b = grid.binsOf(c);
    for (int a = 0; a < 3; ++a) {
      Bin& bin = out[a][b[a]];
      bin.box.grow(r.lo, r.hi);
      bin.centroids.grow(c, c);
      ++bin.count;
    }
  }
}

struct Task {
  uint32_t node = 0, first = 0, count = 0, depth = 0;
  Box4 box, centroids;
};

class Splitter {
 public:
  Splitter(std::vector<PrimRef>& refs, const BvhOptions& options) : refs_(refs), options_(options) {}

  // Splits `t` into `left` and `right` (their node fields unset), or returns false to make it a leaf.
  // `scratch` holds the bins (15 KiB: one per thread, not per node).
  bool split(const Task& t, Task& left, Task& right, unsigned threads, AxisBins& scratch) const {
    if (t.count <= 1 || t.depth >= kMaxDepth) return false;
    const bool mustSplit = t.count > options_.maxLeafSize;
    uint32_t leftCount = options_.fullSweep ? sweepSplit(t, mustSplit) : binnedSplit(t, mustSplit, threads, scratch, left, right);
    if (leftCount == 0) return false;
    if (leftCount != kBoundsKnown) {  // the sweep, and splits by index: bounds by a pass
      left = boundsOf(t.first, leftCount);
      right = boundsOf(t.first + leftCount, t.count - leftCount);
    }
    left.depth = right.depth = t.depth + 1;
    return true;
  }

  Task boundsOf(uint32_t first, uint32_t count) const {
    Task t;
    t.first = first, t.count = count;
    for (uint32_t i = first; i < first + count; ++i) {
      v4 c = refs_[i].centroid();
      t.box.grow(refs_[i].lo, refs_[i].hi);
      t.centroids.grow(c, c);
    }
    return t;
  }

 private:
  static constexpr uint32_t kBoundsKnown = 0xffffffffu;

  // Returns 0 for a leaf, kBoundsKnown when `left` and `right` are filled in from the bins, or the left count of
  // a split by index.
  uint32_t binnedSplit(const Task& t, bool mustSplit, unsigned threads, AxisBins& binned, Task& left, Task& right) const {
    // A small node needs fewer bins (filling 16 empty ones per axis cost more than binning four triangles).
    const uint32_t bins = std::clamp(std::min(options_.bins, std::bit_ceil(t.count)), 2u, kMaxBins);
    const BinGrid grid(t.centroids, bins);
    binInParallel(t, grid, bins, threads, binned);
    double bestCost = std::numeric_limits<double>::infinity();
    int bestAxis = -1;
    uint32_t bestBin = 0;
    // Only the boundaries after non-empty bins are distinct splits (most bins of a small node are empty).
    std::array<uint32_t, kMaxBins> used;
    std::array<double, kMaxBins> rightArea;
    std::array<uint32_t, kMaxBins> rightCount;
    for (int a = 0; a < 3; ++a) {
      if (!grid.usable[a]) continue;
      uint32_t m = 0;
      for (uint32_t b = 0; b < bins; ++b)
        if (binned[a][b].count > 0) used[m++] = b;
      Box4 acc;
      uint32_t n = 0;
      for (uint32_t j = m; j-- > 1;) {
        acc.grow(binned[a][used[j]].box);
        n += binned[a][used[j]].count;
        rightArea[j] = halfArea(acc);
        rightCount[j] = n;
      }
      acc = Box4{};
      n = 0;
      for (uint32_t j = 0; j + 1 < m; ++j) {
        acc.grow(binned[a][used[j]].box);
        n += binned[a][used[j]].count;
        double cost = halfArea(acc) * n + rightArea[j + 1] * rightCount[j + 1];
        if (cost < bestCost) bestCost = cost, bestAxis = a, bestBin = used[j] + 1;
      }
    }
    if (bestAxis < 0) return mustSplit ? t.count / 2 : 0;  // all centroids coincide: split by index
    const double leafCost = double(options_.triangleCost) * t.count;
    const double splitCost = options_.traversalCost + options_.triangleCost * bestCost / std::max(halfArea(t.box), 1e-300);
    if (!mustSplit && splitCost >= leafCost) return 0;
    PrimRef* begin = refs_.data() + t.first;
    PrimRef* mid = std::partition(begin, begin + t.count,
                                  [&](const PrimRef& r) { return uint32_t(grid.binsOf(r.centroid())[bestAxis]) < bestBin; });
    left = Task{}, right = Task{};
    for (uint32_t b = 0; b < bins; ++b) {
      Task& side = b < bestBin ? left : right;
      side.box.grow(binned[bestAxis][b].box);
      side.centroids.grow(binned[bestAxis][b].centroids);
      side.count += binned[bestAxis][b].count;
    }
    if (uint32_t(mid - begin) != left.count) throw Error("internal error: a BVH partition disagrees with its bins");
    left.first = t.first, right.first = t.first + left.count;
    return kBoundsKnown;
  }

  // Bins of a large node in parallel chunks, merged (min, max and sums: the same bins in any order).
  void binInParallel(const Task& t, const BinGrid& grid, uint32_t bins, unsigned threads, AxisBins& out) const {
    const PrimRef* refs = refs_.data() + t.first;
    if (threads <= 1 || t.count < kParallelBinningMin) return binRange(refs, t.count, grid, bins, out);
    const uint32_t chunk = (t.count + threads - 1) / threads;
    std::vector<AxisBins> partial(threads);
    parallelChunks(t.count, chunk, threads, [&](size_t begin, size_t end) {
      binRange(refs + begin, uint32_t(end - begin), grid, bins, partial[begin / chunk]);
    });
    binRange(refs, 0, grid, bins, out);  // empty bins to merge into
    for (const AxisBins& p : partial)
      for (int a = 0; a < 3; ++a)
        for (uint32_t b = 0; b < bins; ++b) {
          out[a][b].box.grow(p[a][b].box);
          out[a][b].centroids.grow(p[a][b].centroids);
          out[a][b].count += p[a][b].count;
        }
  }

  // Every split between centroid-sorted neighbours along every axis (ties broken by index: deterministic); the
  // reference the binned build's quality is measured against. Returns the left count, 0 for a leaf.
  uint32_t sweepSplit(const Task& t, bool mustSplit) const {
    double bestCost = std::numeric_limits<double>::infinity();
    uint32_t bestLeft = 0;
    std::vector<PrimRef> sorted(refs_.begin() + t.first, refs_.begin() + t.first + t.count), best;
    std::vector<double> rightArea(t.count);
    for (int a = 0; a < 3; ++a) {
      std::sort(sorted.begin(), sorted.end(), [&](const PrimRef& x, const PrimRef& y) {
        float cx = x.centroid()[a], cy = y.centroid()[a];
        return cx < cy || (cx == cy && x.index() < y.index());
      });
      Box4 acc;
      for (uint32_t i = t.count; i-- > 0;) {
        acc.grow(sorted[i].lo, sorted[i].hi);
        rightArea[i] = halfArea(acc);
      }
      acc = Box4{};
      bool improved = false;
      for (uint32_t i = 1; i < t.count; ++i) {
        acc.grow(sorted[i - 1].lo, sorted[i - 1].hi);
        double cost = halfArea(acc) * i + rightArea[i] * (t.count - i);
        if (cost < bestCost) bestCost = cost, bestLeft = i, improved = true;
      }
      if (improved) best = sorted;
    }
    const double leafCost = double(options_.triangleCost) * t.count;
    const double splitCost = options_.traversalCost + options_.triangleCost * bestCost / std::max(halfArea(t.box), 1e-300);
    if (!mustSplit && splitCost >= leafCost) return 0;
    std::copy(best.begin(), best.end(), refs_.begin() + t.first);
    return bestLeft;
  }

  std::vector<PrimRef>& refs_;
  const BvhOptions& options_;
};

void writeLeaf(BuildNode& node, const Task& t) {
  node.bounds = t.box.aabb();
  node.first = t.first, node.count = t.count;
}

// Builds the tree under `root` into `nodes` (root at nodes[0] when nodes starts empty), splitting only nodes
// larger than `limit` and handing the others to `deferred` (with their node index); returns the deepest depth.
uint32_t buildTop(const Splitter& splitter, Task root, uint32_t limit, unsigned threads, std::vector<BuildNode>& nodes,
                  std::vector<Task>* deferred) {
  uint32_t maxDepth = 0;
  auto scratch = std::make_unique<AxisBins>();
  root.node = static_cast<uint32_t>(nodes.size());
  nodes.push_back({});
  std::vector<Task> stack{root};
  while (!stack.empty()) {
    Task t = stack.back();
    stack.pop_back();
    if (deferred && t.count <= limit) {
      deferred->push_back(t);
      continue;
    }
    maxDepth = std::max(maxDepth, t.depth);
    Task left, right;
    if (!splitter.split(t, left, right, threads, *scratch)) {
      writeLeaf(nodes[t.node], t);
      continue;
    }
    left.node = static_cast<uint32_t>(nodes.size());
    right.node = left.node + 1;
    nodes.push_back({});
    nodes.push_back({});
    nodes[t.node].bounds = t.box.aabb();
    nodes[t.node].child[0] = left.node, nodes[t.node].child[1] = right.node;
    stack.push_back(right);
    stack.push_back(left);
  }
  return maxDepth;
}

}  // namespace

BinaryTree buildBinaryTree(std::span<const Aabb> bounds, const BvhOptions& options) {
  const uint32_t n = static_cast<uint32_t>(bounds.size());
  BinaryTree tree;
  tree.threads = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  std::vector<PrimRef> refs(n);
  for (uint32_t i = 0; i < n; ++i) {
    const Aabb& b = bounds[i];
    refs[i].lo = v4{b.min.x, b.min.y, b.min.z, std::bit_cast<float>(i)};
    refs[i].hi = v4{b.max.x, b.max.y, b.max.z, 0.0f};
  }
  Splitter splitter(refs, options);
  Task root = splitter.boundsOf(0, n);
  tree.nodes.reserve(2 * size_t(n) + 1);  // at most 2n - 1 nodes; only what is used is touched

  // The top of the tree, each large node binned on every thread; then the subtrees, a thread each.
  const unsigned threads = tree.threads;
  const uint32_t limit = std::max(kMinSubtree, n / (8 * threads));
  std::vector<Task> subtrees;
  tree.maxDepth = buildTop(splitter, root, limit, threads, tree.nodes, &subtrees);
  std::vector<std::vector<BuildNode>> built(subtrees.size());
  std::vector<uint32_t> depths(subtrees.size(), 0);
  std::vector<size_t> byCount(subtrees.size());  // largest first: the last task to start is a small one
  std::iota(byCount.begin(), byCount.end(), 0);
  std::stable_sort(byCount.begin(), byCount.end(), [&](size_t a, size_t b) { return subtrees[a].count > subtrees[b].count; });
  parallelChunks(byCount.size(), 1, threads, [&](size_t k, size_t) {
    size_t s = byCount[k];
    built[s].reserve(2 * size_t(subtrees[s].count));
    depths[s] = buildTop(splitter, subtrees[s], 0, 1, built[s], nullptr);
  });

  // Stitch: a subtree's root takes its reserved node; its other nodes follow the nodes so far.
  for (size_t s = 0; s < subtrees.size(); ++s) {
    const std::vector<BuildNode>& local = built[s];
    const uint32_t base = static_cast<uint32_t>(tree.nodes.size()) - 1;  // local index i >= 1 goes to base + i
    auto remap = [&](BuildNode node) {
      if (node.count == 0) node.child[0] += base, node.child[1] += base;
      return node;
    };
    tree.nodes[subtrees[s].node] = remap(local[0]);
    for (size_t i = 1; i < local.size(); ++i) tree.nodes.push_back(remap(local[i]));
    tree.maxDepth = std::max(tree.maxDepth, depths[s]);
  }
  tree.order.resize(n);
  for (uint32_t i = 0; i < n; ++i) tree.order[i] = refs[i].index();
  return tree;
}

}  // namespace vkmc
