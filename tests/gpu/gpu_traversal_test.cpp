// The GPU traversal kernel returns the same closest and any hits as brute force on random rays.
#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <random>
#include <set>

#include "../shaders/shared/geometry.h"
#include "support/adversarial_geometry.h"
#include "bvh/bvh.h"
#include "render/gpu_scene.h"
#include "bench/ray_tracer.h"

using namespace vkmc;

namespace {
// One device for every test and row here, as a renderer keeps one.
vk::Context& context() {
  static vk::Context ctx;
  return ctx;
}

// A soup as a scene of one material.
Scene sceneOf(const test::Soup& soup) {
  Scene scene;
  scene.materials.push_back(Material{});
  for (size_t i = 0; i < soup.positions.size(); ++i) {
    scene.positions.push_back(soup.positions[i]);
    scene.normals.push_back(glm::vec3(0, 1, 0));
    scene.bounds.grow(soup.positions[i]);
    if (i % 3 == 0) scene.materialIds.push_back(0);
  }
  return scene;
}

// Rays whose closest hit, and whose any-hit answer (hit or miss), differ from brute force over the soup's
// triangles in the BVH's order. A walk cut short comes back as t = NaN and counts as wrong.
std::pair<int, int> wrongHits(RayTracer& tracer, const std::vector<glm::vec3>& ordered, const std::vector<test::Ray>& rays) {
  std::vector<gpu::TestRay> gpuRays;
  for (const test::Ray& r : rays) gpuRays.push_back({glm::vec4(r.origin, r.tMax), glm::vec4(r.direction, 0.0f)});
  std::vector<glm::vec4> closest = tracer.trace(gpuRays, false), any = tracer.trace(gpuRays, true);
  int closestWrong = 0, anyWrong = 0;
  for (size_t r = 0; r < rays.size(); ++r) {
    HostHit want = test::bruteForce(ordered, rays[r]);
    HostHit got{closest[r].x, closest[r].y, closest[r].z, glm::floatBitsToUint(closest[r].w)};
    closestWrong += !test::sameClosestHit(got, want);
    anyWrong += (glm::floatBitsToUint(any[r].w) != gpu::kMissPrimitive) != (want.triangle != gpu::kMissPrimitive);
  }
  return {closestWrong, anyWrong};
}

// A pile of `count` triangles (corners(i) gives triangle i), one per leaf.
struct Pile {
  Scene scene;
  Bvh bvh;
};
Pile pileOfLeaves(uint32_t count, const std::function<std::array<glm::vec3, 3>(uint32_t)>& corners) {
  Pile p;
  p.scene.materials.push_back(Material{});
  std::vector<Aabb> bounds(count);
  for (uint32_t i = 0; i < count; ++i) {
    for (glm::vec3 v : corners(i)) {
      p.scene.positions.push_back(v);
      p.scene.normals.push_back(glm::vec3(0, 0, 1));
      p.scene.bounds.grow(v);
      bounds[i].grow(v);
    }
    p.scene.materialIds.push_back(0);
  }
  BvhOptions oneTrianglePerLeaf;
  oneTrianglePerLeaf.maxLeafSize = 1;
  p.bvh = buildBvh(bounds, oneTrianglePerLeaf);
  return p;
}
}  // namespace

TEST(GpuTraversal, ClosestAndAnyHitAgreeWithBruteForce) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  Scene scene;
  scene.materials.push_back(Material{});
  for (int i = 0; i < 5000; ++i) {
    glm::vec3 c(u(rng) * 5, u(rng) * 5, u(rng) * 5);
    float size = 0.05f + 0.4f * std::abs(u(rng));
    glm::vec3 p[3];
    for (auto& v : p) v = c + size * glm::vec3(u(rng), u(rng), u(rng));
    glm::vec3 n = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
    for (auto& v : p) {
      scene.positions.push_back(v);
      scene.normals.push_back(n);
      scene.bounds.grow(v);
    }
    scene.materialIds.push_back(0);
  }
  std::vector<Aabb> bounds = scene.triangleBounds();
  Bvh bvh = buildBvh(bounds);
  std::vector<glm::vec3> ordered;
  for (uint32_t t : bvh.triangleOrder)
    for (int k = 0; k < 3; ++k) ordered.push_back(scene.positions[3 * t + k]);

  vk::Context& ctx = context();
  GpuScene gpuScene(ctx, scene, bvh);
  RayTracer tracer(ctx, gpuScene);
  std::vector<gpu::TestRay> rays;
  for (int r = 0; r < 20000; ++r) {
    glm::vec3 o(u(rng) * 8, u(rng) * 8, u(rng) * 8);
    glm::vec3 d = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)));
    if (r % 97 == 0) d = glm::vec3(0.0f, 0.0f, r % 2 ? 1.0f : -1.0f);  // axis-aligned: zero components
    rays.push_back({glm::vec4(o, r % 3 == 0 ? 3.0f : 1e30f), glm::vec4(d, 0.0f)});
  }
  std::vector<glm::vec4> closest = tracer.trace(rays, false);
  std::vector<glm::vec4> any = tracer.trace(rays, true);
  int mismatches = 0, anyMismatches = 0, hits = 0;
  for (size_t r = 0; r < rays.size(); ++r) {
    glm::vec3 o(rays[r].origin), d(rays[r].direction);
    gpu::RayShear shear = gpu::makeRayShear(o, d);
    float tBest = rays[r].origin.w;
    uint32_t best = gpu::kMissPrimitive;
    for (uint32_t i = 0; i < ordered.size() / 3; ++i) {
      glm::vec3 h = gpu::intersectTriangle(shear, ordered[3 * i], ordered[3 * i + 1], ordered[3 * i + 2], tBest);
      if (h.x > 0.0f) tBest = h.x, best = i;
    }
    uint32_t got = glm::floatBitsToUint(closest[r].w);
    hits += best != gpu::kMissPrimitive;
    if (got != best) {
      // Two triangles within float rounding of each other along the ray are a tie, not an error.
      bool tie = best != gpu::kMissPrimitive && got != gpu::kMissPrimitive && std::abs(closest[r].x - tBest) <= 1e-5f * tBest;
      if (!tie) ++mismatches;
    } else if (best != gpu::kMissPrimitive) {
      EXPECT_NEAR(closest[r].x, tBest, 1e-5f * tBest);
    }
    bool anyHit = glm::floatBitsToUint(any[r].w) != gpu::kMissPrimitive;
    if (anyHit != (best != gpu::kMissPrimitive)) ++anyMismatches;
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(anyMismatches, 0);
  EXPECT_GT(hits, 2000);
}

// llvmpipe ends shader loops after 65535 iterations without an error (docs/journal/performance.md, "the loop limiter"); a
// walk that did not end on its own comes back with t = NaN. A ray through the common box of a pile of coincident
// triangles, one per leaf, missing them all, visits every leaf: it must come back as a miss, not as a cut or a
// false hit. Every child box is hit, so the walk outgrows the 12-entry register stack and runs in the deep pass.
class PileOfLeaves : public ::testing::TestWithParam<uint32_t> {};

TEST_P(PileOfLeaves, AWalkThroughEveryLeafCompletes) {
  const uint32_t count = GetParam();
  vk::Context& ctx = context();
  Pile pile = pileOfLeaves(count, [](uint32_t) {
    return std::array{glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
  });
  ASSERT_EQ(pile.bvh.stats.leaves, count);
  GpuScene gpuScene(ctx, pile.scene, pile.bvh);
  RayTracer tracer(ctx, gpuScene);
  // Inside every leaf's box (the unit square), outside every triangle (x + y > 1).
  std::vector<gpu::TestRay> rays(64, gpu::TestRay{glm::vec4(0.9f, 0.9f, 1.0f, 1e30f), glm::vec4(0, 0, -1, 0)});
  std::vector<glm::vec4> hits = tracer.trace(rays, false);
  if (count == 400000u) {
    EXPECT_EQ(tracer.deepWalks(), rays.size()) << "each walk should have run in the deep pass";
  }
  for (const glm::vec4& h : hits) {
    EXPECT_FALSE(std::isnan(h.x)) << count << " leaves: the walk was cut short";
    EXPECT_EQ(glm::floatBitsToUint(h.w), gpu::kMissPrimitive) << count << " leaves";
  }
  // And the same pile hit inside a triangle: the closest hit is found.
  rays.assign(64, gpu::TestRay{glm::vec4(0.2f, 0.2f, 1.0f, 1e30f), glm::vec4(0, 0, -1, 0)});
  hits = tracer.trace(rays, false);
  for (const glm::vec4& h : hits) EXPECT_FLOAT_EQ(h.x, 1.0f) << count << " leaves";
  // Any-hit through the same pile: its deep pass too.
  EXPECT_NE(glm::floatBitsToUint(tracer.trace(rays, true)[63].w), gpu::kMissPrimitive) << count << " leaves";
}

INSTANTIATE_TEST_SUITE_P(GpuTraversal, PileOfLeaves, ::testing::Values(1000u, 400000u),
                         [](const auto& info) { return "leaves" + std::to_string(info.param); });

// A full register stack loses no entry. A pile of triangles one above the other (z = 0, 1, ...), one per leaf,
// every box over the unit square: a ray down through (0.9, 0.9) is inside every box, so every walk pushes every
// child it does not enter and fills the stack to the tree's bound (registerStackEntries sizes it to that bound).
// It misses every triangle but one larger one, placed in turn at each height, which the walk finds only if no
// entry was dropped. Piles of 3, 12 and 48 leaves give stacks of 4, 8 and 12 entries.
TEST(GpuTraversal, AFullRegisterStackLosesNoEntry) {
  vk::Context& ctx = context();
  std::set<uint32_t> sizes;
  for (uint32_t count : {3u, 12u, 48u}) {
    for (uint32_t found = 0; found < count; ++found) {
      Pile pile = pileOfLeaves(count, [found](uint32_t i) {
        const float reach = i == found ? 2.0f : 1.0f, z = float(i);  // only the larger triangle covers (0.9, 0.9)
        return std::array{glm::vec3(0, 0, z), glm::vec3(reach, 0, z), glm::vec3(0, reach, z)};
      });
      const Bvh& bvh = pile.bvh;
      GpuScene gpuScene(ctx, pile.scene, bvh);
      sizes.insert(gpuScene.info().registerStackEntries);
      EXPECT_LE(bvh.stats.wideMaxPending, gpuScene.info().registerStackEntries) << count << " leaves";
      RayTracer tracer(ctx, gpuScene);
      const float top = float(count) + 1.0f;
      std::vector<gpu::TestRay> rays(8, gpu::TestRay{glm::vec4(0.9f, 0.9f, top, 1e30f), glm::vec4(0, 0, -1, 0)});
      glm::vec4 closest = tracer.trace(rays, false)[7], any = tracer.trace(rays, true)[7];
      EXPECT_FLOAT_EQ(closest.x, top - float(found)) << count << " leaves, the larger triangle at z = " << found;
      const uint32_t hit = glm::floatBitsToUint(closest.w);
      EXPECT_TRUE(hit < count && bvh.triangleOrder[hit] == found) << count << " leaves, at z = " << found;
      EXPECT_NE(glm::floatBitsToUint(any.w), gpu::kMissPrimitive) << count << " leaves, at z = " << found;
    }
  }
  EXPECT_EQ(sizes, (std::set<uint32_t>{4, 8, gpu::kBvhRegisterStackEntries})) << "every stack size should be filled";
}

// The adversarial soups of bvh_property_test (spheres and boxes at the origin, flat boxes, +-0 and denormals,
// far-away and mixed-scale geometry) through the GPU walks of both node layouts, against brute force.
class GpuTraversalProperty : public ::testing::TestWithParam<test::Soup> {};

TEST_P(GpuTraversalProperty, BothLayoutsAgreeWithBruteForce) {
  const test::Soup& soup = GetParam();
  Scene scene = sceneOf(soup);
  Bvh bvh = buildBvh(scene.triangleBounds());
  vk::Context& ctx = context();
  GpuScene gpuScene(ctx, scene, bvh, false, true);
  std::vector<test::Ray> rays = test::raysAt(soup, 2000, 9);
  for (bool binary : {false, true}) {
    RayTracer tracer(ctx, gpuScene, binary);
    auto [closestWrong, anyWrong] = wrongHits(tracer, test::ordered(soup, bvh), rays);
    EXPECT_EQ(closestWrong, 0) << soup.name << (binary ? ", binary layout" : ", 4-wide layout");
    EXPECT_EQ(anyWrong, 0) << soup.name << (binary ? ", binary layout" : ", 4-wide layout");
  }
}

// The walks' register stack is sized to the tree (registerStackEntries: 4, 8 or 12 entries). Soups whose trees
// choose each size are walked against brute force. Where no walk can outgrow the stack the kernel has no deep pass,
// so a walk that did would come back cut (t = NaN) and count as wrong.
TEST(GpuTraversal, EveryRegisterStackSizeAgreesWithBruteForce) {
  std::set<uint32_t> sizes;
  for (int triangles : {2, 6, 16, 60, 2000}) {
    test::Soup soup = test::randomSoup(triangles, 17, 1.0f, glm::vec3(0.0f), "random soup of " + std::to_string(triangles));
    Scene scene = sceneOf(soup);
    Bvh bvh = buildBvh(scene.triangleBounds());
    vk::Context& ctx = context();
    GpuScene gpuScene(ctx, scene, bvh);
    const uint32_t entries = gpuScene.info().registerStackEntries;
    EXPECT_EQ(entries, registerStackEntries(bvh.stats)) << soup.name;
    sizes.insert(entries);
    RayTracer tracer(ctx, gpuScene);
    auto [closestWrong, anyWrong] = wrongHits(tracer, test::ordered(soup, bvh), test::raysAt(soup, 4000, 23));
    EXPECT_EQ(closestWrong, 0) << soup.name << ", a stack of " << entries;
    EXPECT_EQ(anyWrong, 0) << soup.name << ", a stack of " << entries;
  }
  EXPECT_EQ(sizes, (std::set<uint32_t>{4, 8, gpu::kBvhRegisterStackEntries})) << "every stack size should be walked";
}

INSTANTIATE_TEST_SUITE_P(Adversarial, GpuTraversalProperty, ::testing::ValuesIn(test::adversarialSoups()),
                         [](const ::testing::TestParamInfo<test::Soup>& info) { return "soup" + std::to_string(info.index); });
