// The coordinate-precision warning's scale (scene/coordinate_precision.h): the largest coordinate or triangle over
// the small triangles' size, slivers and scale-free scenes aside.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/coordinate_precision.h"

using namespace vkmc;

namespace {
void addTriangle(Scene& s, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  s.positions.insert(s.positions.end(), {a, b, c});
  s.materialIds.push_back(0);
}
// n unit triangles near the origin, and one of size `big` centred at `offset`.
Scene sceneWith(int n, float big, glm::vec3 offset = glm::vec3(0.0f)) {
  Scene s;
  for (int i = 0; i < n; ++i) addTriangle(s, glm::vec3(i, 0, 0), glm::vec3(i + 1, 0, 0), glm::vec3(i, 1, 0));
  addTriangle(s, offset + glm::vec3(-big, 0, -big), offset + glm::vec3(big, 0, -big), offset + glm::vec3(0, 0, big));
  return s;
}
}  // namespace

TEST(CoordinatePrecision, TheScaleIsTheLargestOverTheSmallTriangles) {
  // The big triangle's longest edge (sqrt(5) 1e3) over the unit triangles' (sqrt(2)).
  EXPECT_NEAR(coordinateScale(sceneWith(20, 1e3f)), std::sqrt(5e6) / std::sqrt(2.0), 0.1);
  EXPECT_FALSE(coordinatePrecisionWarning(sceneWith(20, 1e5f)));
  EXPECT_TRUE(coordinatePrecisionWarning(sceneWith(20, 1e6f)));
  // Small triangles far from the origin: their coordinates set the scale.
  EXPECT_TRUE(coordinatePrecisionWarning(sceneWith(20, 1.0f, glm::vec3(5e6f, 0.0f, 0.0f))));
  // A scene of huge triangles only is precise at its own scale.
  Scene huge;
  addTriangle(huge, glm::vec3(-3e9f, 0, -3e9f), glm::vec3(3e9f, 0, -3e9f), glm::vec3(0, 0, 3e9f));
  EXPECT_FALSE(coordinatePrecisionWarning(huge));
  EXPECT_FALSE(coordinatePrecisionWarning(Scene{}));
}

// A tenth of the triangles may be slivers (edges of 1e-9) without setting the scale.
TEST(CoordinatePrecision, SliversDoNotSetTheScale) {
  Scene s = sceneWith(40, 1e3f);
  for (int i = 0; i < 3; ++i) addTriangle(s, glm::vec3(0), glm::vec3(1e-9f, 0, 0), glm::vec3(0, 1e-9f, 0));
  EXPECT_LT(coordinateScale(s), 1e4);
}
