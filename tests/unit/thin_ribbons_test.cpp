// Points and lines as camera-facing ribbons (host/scene/thin_ribbons.h): one pixel wide at each end's depth,
// front face towards the camera, colours per end, points as squares in the image plane, segments cut at the
// camera.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/camera_rig.h"
#include "scene/thin_ribbons.h"

using namespace vkmc;
using glm::vec3;

namespace {
// A camera at the origin looking down -Z with a 90-degree vertical field of view: a pixel of a 100-pixel-high
// image is 0.02 across at distance 1.
Camera wideCamera() { return lookAtCamera(vec3(0.0f), vec3(0, 0, -1), 90.0f); }

vec3 faceNormal(const Scene& s, size_t tri) {
  const vec3* p = &s.positions[3 * tri];
  return glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
}
}  // namespace

TEST(ThinRibbons, ALineIsOnePixelWideAtEachEndAndFacesTheCamera) {
  Scene s;
  s.thinSegments.push_back({vec3(-1, 0, -5), vec3(3, 0, -5), glm::vec4(1, 0, 0, 1), glm::vec4(0, 0, 1, 1), 0});
  EXPECT_EQ(addThinRibbons(s, wideCamera(), 100), 1u);
  ASSERT_EQ(s.triangleCount(), 2u);
  EXPECT_TRUE(s.thinSegments.empty());
  // Corners a -+ side, b +- side: the ribbon's width at a and at b is a pixel at that depth.
  const vec3 a0 = s.positions[0], a1 = s.positions[1], b1 = s.positions[2], b0 = s.positions[5];
  EXPECT_NEAR(glm::length(a1 - a0), 0.1f, 1e-6f);  // depth 5
  EXPECT_NEAR(glm::length(b1 - b0), 0.1f, 1e-6f);
  EXPECT_NEAR(glm::length(0.5f * (a0 + a1) - vec3(-1, 0, -5)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(0.5f * (b0 + b1) - vec3(3, 0, -5)), 0.0f, 1e-6f);
  for (size_t t = 0; t < 2; ++t) {
    vec3 centroid = (s.positions[3 * t] + s.positions[3 * t + 1] + s.positions[3 * t + 2]) / 3.0f;
    EXPECT_GT(glm::dot(faceNormal(s, t), -centroid), 0.0f) << "front face towards the camera";
    EXPECT_EQ(s.normals[3 * t], faceNormal(s, t));
  }
  ASSERT_EQ(s.colors.size(), 6u);
  EXPECT_EQ(s.colors[0], glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(s.colors[2], glm::vec4(0, 0, 1, 1));
}

TEST(ThinRibbons, APointIsASquarePixelInTheImagePlane) {
  Scene s;
  s.positions = {vec3(0, 0, -1), vec3(1, 0, -1), vec3(0, 1, -1)};  // a triangle already there keeps its corners
  s.normals = {vec3(0, 0, 1), vec3(0, 0, 1), vec3(0, 0, 1)};
  s.materialIds = {0};
  s.uv0 = {glm::vec2(0.5f), glm::vec2(0.5f), glm::vec2(0.5f)};
  s.thinSegments.push_back({vec3(0, 0, -10), vec3(0, 0, -10), glm::vec4(1.0f), glm::vec4(1.0f), 3});
  EXPECT_EQ(addThinRibbons(s, wideCamera(), 100), 1u);
  ASSERT_EQ(s.triangleCount(), 3u);
  EXPECT_EQ(s.materialIds[1], 3u);
  EXPECT_TRUE(s.colors.empty()) << "white ends add no colour array";
  ASSERT_EQ(s.uv0.size(), 9u) << "attribute arrays stay parallel to the corners";
  for (size_t c = 3; c < 9; ++c) {
    EXPECT_NEAR(s.positions[c].z, -10.0f, 1e-6f);
    EXPECT_NEAR(std::abs(s.positions[c].x), 0.1f, 1e-6f);  // half of a pixel at distance 10: 0.2
    EXPECT_NEAR(std::abs(s.positions[c].y), 0.1f, 1e-6f);
  }
  EXPECT_NEAR(faceNormal(s, 1).z, 1.0f, 1e-6f);
}

TEST(ThinRibbons, ASegmentReachingBehindTheCameraIsCutInFrontOfIt) {
  Scene s;
  s.thinSegments.push_back({vec3(1, 0, -4), vec3(1, 0, 4), glm::vec4(1.0f), glm::vec4(1.0f), 0});  // through z = 0
  s.thinSegments.push_back({vec3(1, 0, 1), vec3(1, 0, 4), glm::vec4(1.0f), glm::vec4(1.0f), 0});   // wholly behind
  EXPECT_EQ(addThinRibbons(s, wideCamera(), 100), 1u);
  ASSERT_EQ(s.triangleCount(), 2u);
  for (const vec3& p : s.positions) EXPECT_LE(p.z, -0.004f + 1e-6f) << "nothing at or behind the camera";
}

TEST(ThinRibbons, AnOrthographicCamerasPixelIsTheSameEverywhere) {
  Camera c;
  c.kind = CameraKind::Orthographic;
  c.ymag = 2.0f;  // a 4-unit-high view over 200 pixels: 0.02 each
  Scene s;
  s.thinSegments.push_back({vec3(-1, 0, -1), vec3(1, 0, -100), glm::vec4(1.0f), glm::vec4(1.0f), 0});
  addThinRibbons(s, c, 200);
  ASSERT_EQ(s.triangleCount(), 2u);
  EXPECT_NEAR(glm::length(s.positions[1] - s.positions[0]), 0.02f, 1e-6f);
  EXPECT_NEAR(glm::length(s.positions[2] - s.positions[5]), 0.02f, 1e-6f);
}
