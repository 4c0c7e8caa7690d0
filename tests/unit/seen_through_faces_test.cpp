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
  test::addQuad(open, vec3(20, 0, -1), vec3(1, 0, 0), vec3(0, 1, 0), 0);  // out of view: the scene is not emptied
  EXPECT_EQ(removeSeenThroughFaces(open, eye, 48, 48).triangles, 2u) << "unhidden, it is looked through";
}

TEST(SeenThroughFaces, ASceneTheEyeSeesOnlyFromBehindIsKeptWhole) {
  // Removing both triangles would leave nothing to build a BVH on; the culled faces show the backdrop anyway.
  Scene s = withMaterials({Material{}});
  test::addQuad(s, vec3(-1, -1, -1), vec3(0, 2, 0), vec3(2, 0, 0), 0);
  EXPECT_EQ(removeSeenThroughFaces(s, lookAtCamera(vec3(0, 0, 5), vec3(0.0f), 30.0f), 16, 16).triangles, 0u);
  EXPECT_EQ(s.triangleCount(), 2u);
}

TEST(SeenThroughFaces, ASingleSidedLampSeenFromBehindIsPassedAndKept) {
  // The kernels' camera ray passes the lamp's back, so the wall behind it is looked through too; the lamp stays.
  Material lamp;
  lamp.emission = vec3(1.0f);
  Scene s = withMaterials({Material{}, lamp});
  test::addQuad(s, vec3(-3, -3, 0), vec3(0, 6, 0), vec3(6, 0, 0), 1);   // the lamp, facing away, filling the view
  test::addQuad(s, vec3(-3, -3, -1), vec3(0, 6, 0), vec3(6, 0, 0), 0);  // a wall behind it, facing away too
  test::addQuad(s, vec3(20, 0, -1), vec3(1, 0, 0), vec3(0, 1, 0), 0);   // out of view
  EXPECT_EQ(removeSeenThroughFaces(s, lookAtCamera(vec3(0, 0, 5), vec3(0.0f), 30.0f), 32, 32).triangles, 2u);
  ASSERT_EQ(s.triangleCount(), 4u);
  EXPECT_EQ(s.materialIds[0], 1u) << "the lamp is kept";
  EXPECT_EQ(s.materialIds[1], 1u);
}

TEST(SeenThroughFaces, TheRaysCoverTheImagesFieldOfViewInEveryShapeAndProjection) {
  // A back-facing sliver near the right edge of a 2000 x 6 strip: a grid of its own aspect ratio would miss it.
  Scene strip = withMaterials({Material{}});
  const Camera eye = lookAtCamera(vec3(0, 0, 5), vec3(0.0f), 10.0f);  // half height 0.437 at z = 0
  const float halfWidth = 0.437f * 2000.0f / 6.0f;
  test::addQuad(strip, vec3(0.95f * halfWidth, -1, 0), vec3(0, 2, 0), vec3(0.04f * halfWidth, 0, 0), 0);
  test::addQuad(strip, vec3(0, 50, -1), vec3(1, 0, 0), vec3(0, 1, 0), 0);  // out of view
  EXPECT_EQ(removeSeenThroughFaces(strip, eye, 2000, 6).triangles, 2u);
  // Orthographic: parallel rays across the camera's extent (ymag 2) find a back face off the axis.
  Camera ortho = eye;
  ortho.kind = CameraKind::Orthographic;
  ortho.xmag = ortho.ymag = 2.0f;
  Scene side = withMaterials({Material{}});
  test::addQuad(side, vec3(1.2f, 1.2f, 0), vec3(0, 0.5f, 0), vec3(0.5f, 0, 0), 0);
  test::addQuad(side, vec3(0, 50, -1), vec3(1, 0, 0), vec3(0, 1, 0), 0);
  EXPECT_EQ(removeSeenThroughFaces(side, ortho, 64, 64).triangles, 2u);
}

TEST(SeenThroughFaces, PerCornerArraysStayParallelToTheTrianglesKept) {
  // Two materials (triangle i's is i % 2) and every per-corner array, each corner tagged with its index before.
  Scene s = withMaterials({Material{}, Material{}});
  addBox(s, true, 0);
  for (size_t t = 0; t < s.triangleCount(); ++t) s.materialIds[t] = uint32_t(t % 2);
  for (size_t c = 0; c < s.positions.size(); ++c) {
    s.uv0.push_back(glm::vec2(float(c), 0.0f));
    s.uv1.push_back(glm::vec2(0.0f, float(c)));
    s.tangents.push_back(glm::vec4(float(c), 0, 0, 1));
    s.colors.push_back(glm::vec4(float(c)));
  }
  const std::vector<vec3> positions = s.positions, normals = s.normals;
  ASSERT_EQ(removeSeenThroughFaces(s, frontAbove(), 64, 64).triangles, 6u);
  for (std::vector<glm::vec2>* uv : {&s.uv0, &s.uv1}) ASSERT_EQ(uv->size(), s.positions.size());
  ASSERT_EQ(s.tangents.size(), s.positions.size());
  ASSERT_EQ(s.colors.size(), s.positions.size());
  ASSERT_EQ(s.normals.size(), s.positions.size());
  for (size_t c = 0; c < s.positions.size(); ++c) {
    const size_t before = size_t(s.uv0[c].x);
    EXPECT_EQ(s.positions[c], positions[before]) << "corner " << c;
    EXPECT_EQ(s.normals[c], normals[before]);
    EXPECT_EQ(size_t(s.uv1[c].y), before);
    EXPECT_EQ(size_t(s.tangents[c].x), before);
    EXPECT_EQ(size_t(s.colors[c].x), before);
    EXPECT_EQ(s.materialIds[c / 3], uint32_t((before / 3) % 2)) << "the triangle kept its material";
  }
}
