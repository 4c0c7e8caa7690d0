// What the automatic camera frames (scene/framing.h): a huge flat ground is left out, anything else is kept.
#include <gtest/gtest.h>

#include "scene/framing.h"

using namespace vkmc;

namespace {

void addTriangle(Scene& s, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  for (glm::vec3 p : {a, b, c}) s.positions.push_back(p), s.normals.push_back(glm::vec3(0, 1, 0)), s.bounds.grow(p);
  s.materialIds.push_back(0);
}

// A unit cube's worth of upright triangles (two walls) standing at the origin.
void addSubject(Scene& s) {
  addTriangle(s, {0, 0, 0}, {1, 0, 0}, {1, 1, 0});
  addTriangle(s, {0, 0, 0}, {0, 1, 1}, {0, 0, 1});
}

void addGround(Scene& s, float half) {
  addTriangle(s, {-half, 0, -half}, {half, 0, half}, {half, 0, -half});
  addTriangle(s, {-half, 0, -half}, {-half, 0, half}, {half, 0, half});
}

}  // namespace

TEST(Framing, AHugeFlatGroundIsLeftOut) {
  Scene s;
  addSubject(s);
  addGround(s, 200.0f);
  const FramedBounds f = framingBounds(s);
  EXPECT_TRUE(f.groundLeftOut);
  EXPECT_EQ(f.bounds.min, glm::vec3(0, 0, 0));
  EXPECT_EQ(f.bounds.max, glm::vec3(1, 1, 1));
}

TEST(Framing, AGroundOfTheSubjectsSizeAndAFlatSceneAreKept) {
  Scene modest;
  addSubject(modest);
  addGround(modest, 3.0f);  // 6 wide: under 8 times the subject's width
  EXPECT_FALSE(framingBounds(modest).groundLeftOut);
  EXPECT_EQ(framingBounds(modest).bounds.max, glm::vec3(3, 1, 3));
  Scene flat;
  addGround(flat, 200.0f);  // nothing else: the ground is the subject
  EXPECT_FALSE(framingBounds(flat).groundLeftOut);
  EXPECT_EQ(framingBounds(flat).bounds.max.x, 200.0f);
}

// A huge flat canopy above the subject is not a ground: it stays in the frame.
TEST(Framing, AFlatCanopyAboveIsNotAGround) {
  Scene s;
  addSubject(s);
  addTriangle(s, {-200, 5, -200}, {200, 5, 200}, {200, 5, -200});
  EXPECT_FALSE(framingBounds(s).groundLeftOut);
}
