// Emitter quads (host/render/emitter_pairs.h): two halves of one material sharing a diagonal pair up, with the
// first's apex opposite the shared edge; triangles of other materials, non-parallelograms and non-candidates do not.
#include <gtest/gtest.h>

#include <random>

#include "../shaders/shared/light_sampling.h"
#include "render/emitter_pairs.h"

using namespace vkmc;

namespace {
void addQuad(std::vector<glm::vec3>& p, glm::vec3 o, glm::vec3 u, glm::vec3 v) {
  for (glm::vec3 c : {o, o + u, o + u + v, o, o + u + v, o + v}) p.push_back(c);
}
}  // namespace

TEST(EmitterPairs, QuadsPairAndTheApexFacesTheSharedEdge) {
  std::vector<glm::vec3> p;
  addQuad(p, {0, 2, 0}, {0.5f, 0, 0}, {0, 0, 0.4f});                                      // triangles 0, 1: a quad
  addQuad(p, {3, 2, 0}, {0.5f, 0, 0}, {0, 0, 0.4f});                                      // 2, 3: another, another material
  p.insert(p.end(), {glm::vec3(6, 2, 0), glm::vec3(7, 2, 0), glm::vec3(7, 2, 1)});        // 4
  p.insert(p.end(), {glm::vec3(6, 2, 0), glm::vec3(7, 2, 1), glm::vec3(6.2f, 2, 1.5f)});  // 5: shares 4's edge, no parallelogram
  std::vector<uint8_t> candidate(6, 1);
  std::vector<uint32_t> material = {0, 0, 1, 1, 0, 0};
  std::vector<EmitterPair> pairs = findEmitterPairs(p, candidate, material);
  ASSERT_EQ(pairs.size(), 2u);
  for (const EmitterPair& e : pairs) {
    const glm::vec3* a = &p[3 * e.first];
    glm::vec3 p0 = a[(e.apex + 2) % 3], p1 = a[e.apex], p2 = a[(e.apex + 1) % 3];
    const glm::vec3* b = &p[3 * e.second];
    int shared = 0;
    for (int j = 0; j < 3; ++j) shared += (b[j] == p0 || b[j] == p2) ? 1 : 0;
    EXPECT_EQ(shared, 2) << "the second half holds the shared edge p0-p2";
    for (int j = 0; j < 3; ++j)
      if (b[j] != p0 && b[j] != p2) {
        EXPECT_LT(glm::length(b[j] - (p0 + p2 - p1)), 1e-6f) << "the far corner";
      }
  }
  EXPECT_EQ(pairs[0].first, 0u);
  EXPECT_EQ(pairs[0].second, 1u);
  EXPECT_EQ(pairs[1].first, 2u);
  std::vector<glm::vec3> flipped = p;
  std::swap(flipped[3 * 1 + 1], flipped[3 * 1 + 2]);  // triangle 1 faces the other way
  EXPECT_EQ(findEmitterPairs(flipped, candidate, material).size(), 1u);
  material[1] = 7;   // halves of different materials stay apart
  candidate[3] = 0;  // a textured or alpha-tested half is no candidate
  EXPECT_TRUE(findEmitterPairs(p, candidate, material).empty());
}

// The quad's point from u (light_sampling.h): on the first half below the diagonal and the second above, each the
// parallelogram point p1 + u.x (p0 - p1) + u.y (p2 - p1), so u uniform gives a point uniform on the quad and each
// half probability 1/2; the weights are a convex combination of the half's own corners.
TEST(EmitterPairs, TheQuadPointIsTheParallelogramsAndLandsOnItsHalf) {
  const glm::vec3 p0(0.3f, 2.0f, -0.1f), p1(-0.2f, 2.1f, 0.4f), p2(0.9f, 1.7f, 0.6f), w = p0 + p2 - p1;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  int second = 0;
  for (int i = 0; i < 100000; ++i) {
    glm::vec2 u(unit(rng), unit(rng));
    glm::vec3 wt = gpu::emitterQuadWeights(u);
    bool onSecond = gpu::emitterQuadSecondHalf(u);
    second += onSecond;
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(wt[k] >= 0.0f && wt[k] <= 1.0f) << "u " << u.x << "," << u.y;
    ASSERT_NEAR(wt.x + wt.y + wt.z, 1.0f, 1e-6f);
    glm::vec3 point = wt.x * p0 + wt.y * p2 + wt.z * (onSecond ? w : p1);
    glm::vec3 want = p1 + u.x * (p0 - p1) + u.y * (p2 - p1);
    ASSERT_LT(glm::length(point - want), 1e-5f) << "u " << u.x << "," << u.y;
  }
  EXPECT_NEAR(second / 100000.0, 0.5, 5 * std::sqrt(0.25 / 100000));  // 5 sigma
}
