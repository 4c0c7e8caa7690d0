// Tangent generation (MikkTSpace): directions from the UV layout, handedness from the bitangent, orthogonality to
// the normal, per-corner frames across a mirrored seam, and degenerate UVs.
#include "scene/tangent_space.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vkmc;

namespace {
// A unit quad in z = 0 facing +z; u along x, v along y (or mirrored in u).
const std::vector<glm::vec3> kQuad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
const std::vector<uint32_t> kTriangles = {0, 1, 2, 0, 2, 3};
const std::vector<glm::vec3> kUp(4, glm::vec3(0, 0, 1));
}  // namespace

// glTF's uv origin is the image's top-left corner: a texture shown upright on the quad has v running down (-y),
// and the normal map's +Y (up the image) is +y: bitangent = cross(n, t) w = -dP/dv.
TEST(TangentSpace, TangentFollowsUAndTheBitangentPointsUpTheImage) {
  std::vector<glm::vec2> upright = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};  // v runs along -y
  for (const glm::vec4& t : generateTangents(kQuad, kUp, upright, kTriangles)) {
    EXPECT_NEAR(t.x, 1.0f, 1e-6f);
    EXPECT_EQ(t.w, 1.0f) << "bitangent cross(n, t) = +y, up the image";
  }
  std::vector<glm::vec2> flipped = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // v runs along +y: the image upside down
  for (const glm::vec4& t : generateTangents(kQuad, kUp, flipped, kTriangles)) {
    EXPECT_NEAR(t.x, 1.0f, 1e-6f);
    EXPECT_EQ(t.w, -1.0f) << "up the image is -y = -cross(n, t)";
  }
  std::vector<glm::vec2> mirrored = {{1, 1}, {0, 1}, {0, 0}, {1, 0}};  // u runs along -x, v along -y
  for (const glm::vec4& t : generateTangents(kQuad, kUp, mirrored, kTriangles)) {
    EXPECT_NEAR(t.x, -1.0f, 1e-6f);
    EXPECT_EQ(t.w, -1.0f) << "cross(n, t) = -y but up the image is +y";
  }
}

TEST(TangentSpace, TangentsAreOrthogonalToTiltedNormalsAndUnit) {
  std::vector<glm::vec2> uv = {{0, 0}, {2, 0}, {2, 3}, {0, 3}};
  std::vector<glm::vec3> tilted(4, glm::normalize(glm::vec3(0.3f, 0.2f, 1.0f)));
  std::vector<glm::vec4> t = generateTangents(kQuad, tilted, uv, kTriangles);
  ASSERT_EQ(t.size(), kTriangles.size()) << "one tangent per corner";
  for (size_t i = 0; i < t.size(); ++i) {
    EXPECT_NEAR(glm::length(glm::vec3(t[i])), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(glm::vec3(t[i]), tilted[kTriangles[i]]), 0.0f, 1e-5f);
    EXPECT_GT(t[i].x, 0.9f);
  }
}

TEST(TangentSpace, DegenerateOrMissingUvsGiveSomePerpendicular) {
  std::vector<glm::vec2> collapsed(4, glm::vec2(0.5f));
  for (const auto& uv : {collapsed, std::vector<glm::vec2>{}})
    for (const glm::vec4& t : generateTangents(kQuad, {}, uv, kTriangles)) {  // no normals: face normals are used
      EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-5f);
      EXPECT_NEAR(t.z, 0.0f, 1e-6f);
      EXPECT_EQ(t.w, 1.0f);
    }
  for (glm::vec3 n : {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::normalize(glm::vec3(1, -2, 0.1f))})
    EXPECT_NEAR(glm::dot(anyPerpendicular(n), n), 0.0f, 1e-6f);
}

// Two quads side by side sharing the seam's vertices (x = 1), the right one's texture mirrored in u (u runs 0 to
// 0.5 and back): the shared vertices' corners take each side's frame, +x on the left and -x on the right, with
// opposite handedness, as MikkTSpace splits them (an average across the seam would be perpendicular to both).
TEST(TangentSpace, AMirroredSeamGivesEachSideItsOwnFrame) {
  const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  const std::vector<glm::vec2> uv = {{0, 1}, {0.5f, 1}, {0, 1}, {0, 0}, {0.5f, 0}, {0, 0}};
  const std::vector<uint32_t> tri = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4};
  std::vector<glm::vec4> t = generateTangents(p, std::vector<glm::vec3>(6, glm::vec3(0, 0, 1)), uv, tri);
  ASSERT_EQ(t.size(), tri.size());
  for (size_t i = 0; i < t.size(); ++i) {
    bool right = i >= 6;
    EXPECT_NEAR(t[i].x, right ? -1.0f : 1.0f, 1e-5f) << "corner " << i << " (vertex " << tri[i] << ")";
    EXPECT_EQ(t[i].w, right ? -1.0f : 1.0f) << "corner " << i;
  }
}

// Zero-area triangles take the fallback frame and stay out of MikkTSpace, whose weld compares each corner with every
// earlier one of the same position: 60k corners at one point (an accessor without a buffer view reads zeros) with
// distinct uvs took it 10 s (found by the fuzzer), 180k 3 minutes. A real triangle beside them keeps its frame.
TEST(TangentSpace, ZeroAreaTrianglesGetTheFallbackAndDoNotSlowTheWeld) {
  const uint32_t collapsed = 60000;  // about 3 minutes before the fix, milliseconds after: the ctest timeout catches it
  std::vector<glm::vec3> p(3 * collapsed, glm::vec3(0.0f));
  std::vector<glm::vec2> uv;
  std::vector<uint32_t> tri;
  for (uint32_t i = 0; i < 3 * collapsed; ++i) {
    uv.push_back(glm::vec2(float(i) / float(3 * collapsed), float(i % 7) / 7.0f));
    tri.push_back(i);
  }
  const uint32_t base = uint32_t(p.size());
  p.insert(p.end(), kQuad.begin(), kQuad.end());
  for (glm::vec2 u : {glm::vec2(0, 1), glm::vec2(1, 1), glm::vec2(1, 0), glm::vec2(0, 0)}) uv.push_back(u);
  for (uint32_t k : kTriangles) tri.push_back(base + k);
  std::vector<glm::vec3> up(p.size(), glm::vec3(0, 0, 1));
  std::vector<glm::vec4> t = generateTangents(p, up, uv, tri);
  ASSERT_EQ(t.size(), tri.size());
  for (size_t i = 0; i < 3 * size_t(collapsed); ++i) ASSERT_EQ(t[i], glm::vec4(anyPerpendicular(up[0]), 1.0f)) << i;
  for (size_t i = 3 * size_t(collapsed); i < t.size(); ++i) {
    EXPECT_NEAR(t[i].x, 1.0f, 1e-6f);
    EXPECT_EQ(t[i].w, 1.0f);
  }
}

// A fan of real triangles around one apex whose corners each carry their own uv: MikkTSpace's weld compared every
// apex corner with all earlier ones (quadratic: 24 s for 60k, minutes for 150k, past the test's hang-guard timeout);
// it now sorts them (third_party/mikktspace/README.md) and takes milliseconds.
// The frames are still MikkTSpace's: tangents along the uvs' u direction, here +x on the plane z = 0.
TEST(TangentSpace, AFanOfManyCornersAtOnePositionWeldsQuickly) {
  const uint32_t blades = 150000;
  std::vector<glm::vec3> p;
  std::vector<glm::vec2> uv;
  std::vector<uint32_t> tri;
  for (uint32_t i = 0; i < blades; ++i) {
    float a0 = 6.2831853f * float(i) / float(blades), a1 = 6.2831853f * float(i + 1) / float(blades);
    glm::vec3 b(std::cos(a0), std::sin(a0), 0.0f), c(std::cos(a1), std::sin(a1), 0.0f);
    for (glm::vec3 v : {glm::vec3(0.0f), b, c}) {
      tri.push_back(uint32_t(p.size()));
      p.push_back(v);
      uv.push_back(glm::vec2(0.5f + 0.5f * v.x, 0.5f - 0.5f * v.y) + glm::vec2(0.0f, 1e-7f * float(i)));  // v down
    }
  }
  std::vector<glm::vec3> up(p.size(), glm::vec3(0, 0, 1));
  std::vector<glm::vec4> t = generateTangents(p, up, uv, tri);
  ASSERT_EQ(t.size(), tri.size());
  for (size_t i = 0; i < t.size(); i += 997) {
    EXPECT_NEAR(t[i].x, 1.0f, 1e-3f) << i;
    EXPECT_EQ(t[i].w, 1.0f) << i;
  }
}
