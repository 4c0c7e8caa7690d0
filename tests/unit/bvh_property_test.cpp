// Property tests of the BVH build and both node layouts over adversarial geometry (adversarial_geometry.h): every
// build succeeds, every quantized 4-wide box contains its subtree exactly, and walks of the binary and the 4-wide
// layout find brute force's closest and any hits.
#include <gtest/gtest.h>

#include <functional>

#include "support/adversarial_geometry.h"

using namespace vkmc;
using namespace vkmc::test;

namespace {

// Every quantized child box of every wide node contains the tight bounds of what lies under it.
int uncontainedWideBoxes(const Bvh& bvh, const std::vector<Aabb>& orderedBounds) {
  std::function<Aabb(uint32_t)> tight = [&](uint32_t entry) {
    Aabb box;
    if (gpu::bvhIsLeaf(entry)) {
      uint32_t first = gpu::bvhLeafFirst(entry), count = gpu::bvhLeafCount(entry);
      for (uint32_t t = first; t < first + count; ++t) box.grow(orderedBounds[t]);
      return box;
    }
    for (int c = 0; c < 4; ++c)
      if (bvh.wideNodes[entry].texels[3][c] != gpu::kBvhEmptySlot) box.grow(tight(bvh.wideNodes[entry].texels[3][c]));
    return box;
  };
  int bad = 0;
  for (const BvhWideNode& node : bvh.wideNodes)
    for (int c = 0; c < 4; ++c) {
      if (node.texels[3][c] == gpu::kBvhEmptySlot) continue;
      Aabb q = wideChildBox(node, c), t = tight(node.texels[3][c]);
      for (int a = 0; a < 3; ++a) bad += !(q.min[a] <= t.min[a]) || !(q.max[a] >= t.max[a]);
    }
  return bad;
}

// Every soup of adversarial_geometry.h, built once per process; rows are (soup, leaf size).
const std::vector<Soup>& soups() {
  static const std::vector<Soup> all = adversarialSoups();
  return all;
}

class BvhProperty : public ::testing::TestWithParam<std::tuple<size_t, uint32_t>> {};

}  // namespace

TEST_P(BvhProperty, BuildsContainsAndWalksLikeBruteForce) {
  const Soup& soup = soups()[std::get<0>(GetParam())];
  const uint32_t leafSize = std::get<1>(GetParam());
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
    HostHit closest[2] = {traceHost(bvh, pos, ray.origin, ray.direction, ray.tMax, false),
                          traceHostWide(bvh, pos, ray.origin, ray.direction, ray.tMax, false)};
    HostHit any[2] = {traceHost(bvh, pos, ray.origin, ray.direction, ray.tMax, true),
                      traceHostWide(bvh, pos, ray.origin, ray.direction, ray.tMax, true)};
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
  for (const char* out : {"e+20", "e+30", "e-20", "e-30", "zero-area"})
    floatTestsWork &= soup.name.find(out) == std::string::npos;
  if (floatTestsWork) {
    EXPECT_GT(hits, int(rays.size()) / 4) << soup.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Adversarial, BvhProperty,
                         ::testing::Combine(::testing::Range(size_t(0), soups().size()), ::testing::Values(1u, 8u)),
                         [](const auto& info) {
                           return "soup" + std::to_string(std::get<0>(info.param)) + "_leaves" +
                                  std::to_string(std::get<1>(info.param));
                         });
