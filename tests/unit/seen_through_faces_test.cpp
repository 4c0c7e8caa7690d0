// Single-sided faces the camera looks through (host/bvh/seen_through_faces.h): removed for every ray where the eye
// passes them; kept where a camera ray meets a front face first (solids, occluded walls), on two-sided and
// emissive materials, and with every per-corner array kept parallel.
#include <gtest/gtest.h>

#include "bvh/seen_through_faces.h"
#include "scene/camera_rig.h"
#include "support/render_helpers.h"

using namespace vkmc;
using glm::vec3;

namespace {
// Unit box [-1,1]^3 as six quads; inward: normals towards the centre (a room), else outwards (a solid). Quad q is
// triangles 2q and 2q+1: 0 -X, 1 +X, 2 -Y (floor), 3 +Y (ceiling), 4 -Z, 5 +Z.
void addBox(Scene& s, bool inward, uint32_t material) {
  struct Face {
    vec3 o, u, v;
  };
  const Face outward[6] = {{vec3(-1, -1, -1), vec3(0, 0, 2), vec3(0, 2, 0)}, {vec3(1, -1, -1), vec3(0, 2, 0), vec3(0, 0, 2)},
                           {vec3(-1, -1, -1), vec3(2, 0, 0), vec3(0, 0, 2)}, {vec3(-1, 1, -1), vec3(0, 0, 2), vec3(2, 0, 0)},
                           {vec3(-1, -1, -1), vec3(0, 2, 0), vec3(2, 0, 0)}, {vec3(-1, -1, 1), vec3(2, 0, 0), vec3(0, 2, 0)}};
  for (const Face& f : outward) inward ? test::addQuad(s, f.o, f.v, f.u, material) : test::addQuad(s, f.o, f.u, f.v, material);
}

Scene withMaterials(std::initializer_list<Material> materials) {
  Scene s;
  s.materials = materials;
  return s;
}

// From above the +Z side, looking at the box's centre: the eye sees the +Z and +Y faces' outer sides.
Camera frontAbove() { return lookAtCamera(vec3(3.0f, 4.0f, 6.0f), vec3(0.0f), 50.0f); }

bool hasFace(const Scene& s, vec3 normal) {
  for (size_t i = 0; i < s.normals.size(); i += 3)
    if (glm::dot(s.normals[i], normal) > 0.999f) return true;
  return false;
}
}  // namespace

TEST(SeenThroughFaces, ASolidSeenFromOutsideKeepsEveryFace) {
  Scene s = withMaterials({Material{}});
  addBox(s, false, 0);
  EXPECT_EQ(removeSeenThroughFaces(s, frontAbove(), 64, 64).triangles, 0u);
  EXPECT_EQ(s.triangleCount(), 12u);
}

TEST(SeenThroughFaces, ARoomSeenFromOutsideLosesTheWallsTheEyePassesAndKeepsTheRest) {
  Scene s = withMaterials({Material{}});
  addBox(s, true, 0);
  SeenThrough r = removeSeenThroughFaces(s, frontAbove(), 64, 64);
  EXPECT_EQ(r.triangles, 6u) << "+X, +Y and +Z: the sides facing the eye from outside";
  EXPECT_EQ(r.rays, 64u * 64u);
  EXPECT_FALSE(hasFace(s, vec3(0, 0, -1))) << "the near wall (+Z, facing in) is gone";
  EXPECT_FALSE(hasFace(s, vec3(0, -1, 0))) << "the ceiling, seen from above, is gone";
  EXPECT_TRUE(hasFace(s, vec3(0, 1, 0))) << "the floor stays";
  EXPECT_TRUE(hasFace(s, vec3(0, 0, 1))) << "the far wall stays";
  ASSERT_EQ(s.positions.size(), 3 * s.triangleCount());
  ASSERT_EQ(s.normals.size(), 3 * s.triangleCount());
}

TEST(SeenThroughFaces, TwoSidedAndEmissiveFacesStay) {
  Material twoSided;
  twoSided.doubleSided = true;
  Material lamp;
  lamp.emission = vec3(1.0f);
  for (const Material& m : {twoSided, lamp}) {
    Scene s = withMaterials({m});
    addBox(s, true, 0);
    EXPECT_EQ(removeSeenThroughFaces(s, frontAbove(), 32, 32).triangles, 0u);
    EXPECT_EQ(s.triangleCount(), 12u);
  }
}

TEST(SeenThroughFaces, AWallHiddenBehindAFrontFaceStays) {
  // A quad facing the camera in front of a larger one facing away: every ray reaching the far quad has met the
  // near one's front, so the far quad is never looked through.
  Scene s = withMaterials({Material{}});
  const Camera eye = lookAtCamera(vec3(0, 0, 5), vec3(0.0f), 10.0f);
  test::addQuad(s, vec3(-3, -3, 0), vec3(6, 0, 0), vec3(0, 6, 0), 0);   // faces +Z: towards the camera
  test::addQuad(s, vec3(-1, -1, -1), vec3(0, 2, 0), vec3(2, 0, 0), 0);  // faces -Z: away, but behind the first
  EXPECT_EQ(removeSeenThroughFaces(s, eye, 48, 48).triangles, 0u);
  Scene open = withMaterials({Material{}});
  test::addQuad(open, vec3(-1, -1, -1), vec3(0, 2, 0), vec3(2, 0, 0), 0);
  EXPECT_EQ(removeSeenThroughFaces(open, eye, 48, 48).triangles, 2u) << "alone, it is looked through";
}

TEST(SeenThroughFaces, PerCornerArraysStayParallelToTheTrianglesKept) {
  Scene s = withMaterials({Material{}});
  addBox(s, true, 0);
  for (size_t c = 0; c < s.positions.size(); ++c) s.uv0.push_back(glm::vec2(float(c), 0.0f));
  s.colors.assign(s.positions.size(), glm::vec4(1.0f));
  const std::vector<vec3> before = s.positions;
  removeSeenThroughFaces(s, frontAbove(), 64, 64);
  ASSERT_EQ(s.uv0.size(), s.positions.size());
  ASSERT_EQ(s.colors.size(), s.positions.size());
  for (size_t c = 0; c < s.positions.size(); ++c)
    EXPECT_EQ(s.positions[c], before[size_t(s.uv0[c].x)]) << "corner " << c << " kept its own attributes";
}
