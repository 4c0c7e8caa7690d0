// Skins in the default pose (scene/gltf_skin.cpp): each vertex moved by its joints' world transforms times their
// inverse bind matrices, blended by its weights; the skinned mesh's own node transform not applied; bad joints
// refused with one line.
#include <gtest/gtest.h>

#include <cstring>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/gltf_loader.h"
#include "support/gltf_builder.h"
#include "support/test_scenes.h"

using namespace vkmc;
using vkmc::test::GltfBuilder;

namespace {

std::filesystem::path dir() {
  static auto d = test::makeTempDir("gltf_skin");
  return d;
}

// One triangle: corner 0 bound to joint 0, corner 1 to joint 1, corner 2 half to each. Joint 0 sits at the
// origin; joint 1 is translated by (0, 10, 0) and its inverse bind matrix by (0, -2, 0), so it moves its vertices
// by (0, 8, 0). The mesh's node is translated by (100, 0, 0), which a skinned mesh ignores.
// With secondSet, corner 0 has half its weight in JOINTS_1/WEIGHTS_1, on joint 1.
std::string skinned(const std::string& name, const std::string& joints = "[1,2]", uint8_t secondJoint = 1,
                    const std::string& rootScale = "[1,1,1]", bool secondSet = false) {
  GltfBuilder b;
  std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::vector<uint8_t> jointIds = {0, 0, 0, 0, secondJoint, 0, 0, 0, 0, secondJoint, 0, 0};
  std::vector<float> weights = {secondSet ? 0.5f : 1.0f, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0};
  std::string extra;
  if (secondSet) {
    const int j1 = b.accessor(std::vector<uint8_t>{1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, 5121, "VEC4", 3);
    const int w1 = b.accessor(std::vector<float>{0.5f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, 5126, "VEC4", 3);
    extra = R"(,"JOINTS_1":)" + std::to_string(j1) + R"(,"WEIGHTS_1":)" + std::to_string(w1);
  }
  glm::mat4 inverseBind[2] = {glm::mat4(1.0f), glm::translate(glm::mat4(1.0f), glm::vec3(0, -2, 0))};
  std::vector<float> matrices(32);
  std::memcpy(matrices.data(), inverseBind, sizeof(inverseBind));
  int p = b.accessor(positions, 5126, "VEC3", 3), j = b.accessor(jointIds, 5121, "VEC4", 3);
  int w = b.accessor(weights, 5126, "VEC4", 3), m = b.accessor(matrices, 5126, "MAT4", 2);
  std::string body = R"("nodes":[{"mesh":0,"skin":0,"translation":[100,0,0]},{"name":"root","children":[2],"scale":)" +
                     rootScale + R"(},
      {"name":"arm","translation":[0,10,0]}],"meshes":[{"primitives":[{"attributes":{"POSITION":)" +
                     std::to_string(p) + R"(,"JOINTS_0":)" + std::to_string(j) + R"(,"WEIGHTS_0":)" + std::to_string(w) + extra +
                     R"(}}]}],"skins":[{"joints":)" + joints + R"(,"inverseBindMatrices":)" + std::to_string(m) + "}]";
  return b.write(dir(), name, body, "0,1");
}

}  // namespace

TEST(GltfSkin, VerticesFollowTheirJointsInTheDefaultPose) {
  Scene s = loadGltf(skinned("pose"));
  ASSERT_EQ(s.triangleCount(), 1u);
  EXPECT_EQ(s.positions[0], glm::vec3(0, 0, 0)) << "joint 0: identity, and no node translation";
  EXPECT_EQ(s.positions[1], glm::vec3(1, 8, 0)) << "joint 1: world (0, 10, 0) times inverse bind (0, -2, 0)";
  EXPECT_EQ(s.positions[2], glm::vec3(0, 5, 0)) << "half of each";
  for (const std::string& w : s.warnings) EXPECT_EQ(w.find("skin"), std::string::npos) << w;
}

TEST(GltfSkin, BadJointsAreRefusedWithOneLine) {
  EXPECT_NE(test::loadError(skinned("missing_node", "[1,9]")).find("skin 0: joint 1 is not a node"), std::string::npos);
  EXPECT_NE(test::loadError(skinned("past_skin", "[1,2]", 7)).find("names joint 7 of a skin of 2"), std::string::npos);
}

// A skeleton mirrored by its root's scale (1, 1, -1), as converters write: the triangle keeps its facing by
// swapping its winding (corners 1 and 2), as a mirroring node transform does.
TEST(GltfSkin, AMirroringSkeletonSwapsTheWinding) {
  Scene s = loadGltf(skinned("mirrored", "[1,2]", 1, "[1,1,-1]"));
  ASSERT_EQ(s.triangleCount(), 1u);
  EXPECT_EQ(s.positions[0], glm::vec3(0, 0, 0));
  EXPECT_EQ(s.positions[1], glm::vec3(0, 5, 0)) << "the corners after the first swapped";
  EXPECT_EQ(s.positions[2], glm::vec3(1, 8, 0));
}

// Influences past the first four (JOINTS_1 and WEIGHTS_1) count as the first do.
TEST(GltfSkin, EverySetOfInfluencesCounts) {
  Scene s = loadGltf(skinned("two_sets", "[1,2]", 1, "[1,1,1]", true));
  ASSERT_EQ(s.triangleCount(), 1u);
  EXPECT_EQ(s.positions[0], glm::vec3(0, 4, 0)) << "half on joint 0 (set 0), half on joint 1 (set 1)";
  EXPECT_EQ(s.positions[1], glm::vec3(1, 8, 0));
}
