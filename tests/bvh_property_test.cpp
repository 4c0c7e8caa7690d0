// Property tests of the BVH build and both node layouts over adversarial geometry (adversarial_geometry.h): every
// build succeeds, every quantized 4-wide box contains its subtree exactly, and walks of the binary and the 4-wide
// layout find brute force's closest and any hits.
#include <gtest/gtest.h>

#include <functional>

#include "adversarial_geometry.h"

using namespace vkmc;
using namespace vkmc::test;

namespace {

// The 4-wide layout walked on the host, with each child box decoded exactly as the node encodes it.
HostHit traceWide(const Bvh& bvh, const std::vector<glm::vec3>& pos, const Ray& ray, bool anyHit) {
  gpu::RayShear shear = gpu::makeRayShear(ray.origin, ray.direction);
  glm::vec3 inv = gpu::safeInverse(ray.direction);
  HostHit best;
  float tBest = ray.tMax;
  std::vector<uint32_t> stack{0};
  while (!stack.empty()) {
    const BvhWideNode& node = bvh.wideNodes[stack.back()];
    stack.pop_back();
    for (int c = 0; c < 4; ++c) {
      uint32_t entry = node.texels[3][c];
      if (entry == kBvhEmptySlot) continue;
      Aabb box = wideChildBox(node, c);
      glm::vec3 t0 = (box.min - ray.origin) * inv, t1 = (box.max - ray.origin) * inv;
      glm::vec3 tn = glm::min(t0, t1), tf = glm::max(t0, t1);
      float near = std::max(std::max(tn.x, tn.y), std::max(tn.z, 0.0f));
      float far = std::min(std::min(tf.x, tf.y) * gpu::kSlabWiden, std::min(tf.z * gpu::kSlabWiden, tBest));
      if (!(near <= far)) continue;
      if (!(entry & kBvhLeafTag)) {
        stack.push_back(entry);
        continue;
      }
      uint32_t first = entry & 0x07ffffffu, count = ((entry >> 27) & 0xfu) + 1u;
      for (uint32_t tri = first; tri < first + count; ++tri) {
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

// Every quantized child box of every wide node contains the tight bounds of what lies under it.
int uncontainedWideBoxes(const Bvh& bvh, const std::vector<Aabb>& orderedBounds) {
  std::function<Aabb(uint32_t)> tight = [&](uint32_t entry) {
    Aabb box;
    if (entry & kBvhLeafTag) {
      uint32_t first = entry & 0x07ffffffu, count = ((entry >> 27) & 0xfu) + 1u;
      for (uint32_t t = first; t < first + count; ++t) box.grow(orderedBounds[t]);
      return box;
    }
    for (int c = 0; c < 4; ++c)
      if (bvh.wideNodes[entry].texels[3][c] != kBvhEmptySlot) box.grow(tight(bvh.wideNodes[entry].texels[3][c]));
    return box;
  };
  int bad = 0;
  for (const BvhWideNode& node : bvh.wideNodes)
    for (int c = 0; c < 4; ++c) {
      if (node.texels[3][c] == kBvhEmptySlot) continue;
      Aabb q = wideChildBox(node, c), t = tight(node.texels[3][c]);
      for (int a = 0; a < 3; ++a) bad += !(q.min[a] <= t.min[a]) || !(q.max[a] >= t.max[a]);
    }
  return bad;
}

class BvhProperty : public ::testing::TestWithParam<Soup> {};

}  // namespace

TEST_P(BvhProperty, BuildsContainsAndWalksLikeBruteForce) {
  const Soup& soup = GetParam();
  for (uint32_t leafSize : {1u, 8u}) {
    BvhOptions options;
    options.maxLeafSize = leafSize;
    Bvh bvh;
    ASSERT_NO_THROW(bvh = buildBvh(triangleBounds(soup.positions), options)) << soup.name;
    std::vector<glm::vec3> pos = ordered(soup, bvh);
    EXPECT_EQ(uncontainedWideBoxes(bvh, triangleBounds(pos)), 0) << soup.name << ", leaves of " << leafSize;
    int closestWrong[2] = {0, 0}, anyWrong[2] = {0, 0}, hits = 0;
    std::vector<Ray> rays = raysAt(soup, 600, 7);
    for (const Ray& ray : rays) {
      HostHit want = bruteForce(pos, ray);
      hits += want.triangle != 0xffffffffu;
      HostHit closest[2] = {traceHost(bvh, pos, ray.origin, ray.direction, ray.tMax, false), traceWide(bvh, pos, ray, false)};
      HostHit any[2] = {traceHost(bvh, pos, ray.origin, ray.direction, ray.tMax, true), traceWide(bvh, pos, ray, true)};
      for (int layout = 0; layout < 2; ++layout) {
        closestWrong[layout] += !sameClosestHit(closest[layout], want);
        anyWrong[layout] += (any[layout].triangle != 0xffffffffu) != (want.triangle != 0xffffffffu);
      }
    }
    EXPECT_EQ(closestWrong[0], 0) << soup.name << ": binary layout, closest hits";
    EXPECT_EQ(closestWrong[1], 0) << soup.name << ": 4-wide layout, closest hits";
    EXPECT_EQ(anyWrong[0], 0) << soup.name << ": binary layout, any hits";
    EXPECT_EQ(anyWrong[1], 0) << soup.name << ": 4-wide layout, any hits";
    // Where float ray tests work at all (not at 1e+-20 and beyond, where their products under- or overflow),
    // the rays aimed at triangles hit.
    bool floatTestsWork = true;
    for (const char* out : {"e+20", "e+30", "e-20", "e-30", "zero-area"}) floatTestsWork &= soup.name.find(out) == std::string::npos;
    if (floatTestsWork) EXPECT_GT(hits, int(rays.size()) / 4) << soup.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Adversarial, BvhProperty, ::testing::ValuesIn(adversarialSoups()),
                         [](const ::testing::TestParamInfo<Soup>& info) { return "soup" + std::to_string(info.index); });
