// Vertex attributes reaching Scene (TEXCOORD_0/1, COLOR_0, tangents), quantized positions (KHR_mesh_quantization),
// morph targets at their default weights, EXT_mesh_gpu_instancing and skins in bind pose.
#include <gtest/gtest.h>

#include "error.h"
#include "scene/gltf_loader.h"
#include "scene/gltf_primitive.h"
#include "support/gltf_builder.h"
#include "support/test_scenes.h"

using namespace vkmc;
using vkmc::test::GltfBuilder;

namespace {
std::filesystem::path dir() {
  static auto d = test::makeTempDir("attributes");
  return d;
}

// The unit quad (z = 0, facing +z, u along x and v along y): its POSITION, index and TEXCOORD accessors.
struct Quad {
  int position, indices, uv;
};
Quad addQuad(GltfBuilder& b) {
  std::vector<float> p = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  std::vector<float> uv = {0, 0, 1, 0, 1, 1, 0, 1};
  std::vector<uint16_t> idx = {0, 1, 2, 0, 2, 3};
  return {b.accessor(p, 5126, "VEC3", 4, R"("min":[0,0,0],"max":[1,1,0])"), b.accessor(idx, 5123, "SCALAR", 6),
          b.accessor(uv, 5126, "VEC2", 4)};
}

std::string meshJson(const std::string& primitives) { return R"("meshes":[{"primitives":[)" + primitives + "]}]"; }
std::string primitive(const std::string& attributes, int indices, int material = -1) {
  return R"({"attributes":{)" + attributes + R"(},"indices":)" + std::to_string(indices) +
         (material >= 0 ? R"(,"material":)" + std::to_string(material) : "") + "}";
}
const std::string kNormalMapped = R"("materials":[{"normalTexture":{"index":0}}],"textures":[{}])";
}  // namespace

TEST(GltfAttributes, UntexturedScenesCarryNoAttributeArrays) {
  Scene s = loadGltf(test::writeGltf(dir(), "plain", test::quadSpec()));
  EXPECT_TRUE(s.uv0.empty() && s.uv1.empty() && s.tangents.empty() && s.colors.empty());
}

TEST(GltfAttributes, TexcoordsAndColorsArePerCornerWithDefaultsForPrimitivesLackingThem) {
  GltfBuilder b;
  Quad q = addQuad(b);
  std::vector<uint8_t> rgb = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
  int color = b.accessor(rgb, 5121, "VEC3", 4, R"("normalized":true)");
  std::string plain = primitive(R"("POSITION":)" + std::to_string(q.position), q.indices);
  std::string rich = primitive(R"("POSITION":)" + std::to_string(q.position) + R"(,"TEXCOORD_0":)" + std::to_string(q.uv) +
                                   R"(,"COLOR_0":)" + std::to_string(color),
                               q.indices);
  Scene s = loadGltf(b.write(dir(), "uvcolor", R"("nodes":[{"mesh":0}],)" + meshJson(plain + "," + rich)));
  ASSERT_EQ(s.triangleCount(), 4u);
  ASSERT_EQ(s.uv0.size(), 12u);
  ASSERT_EQ(s.colors.size(), 12u);
  EXPECT_TRUE(s.uv1.empty());
  EXPECT_TRUE(s.tangents.empty()) << "no material has a normal texture";
  for (size_t c = 0; c < 6; ++c) {
    EXPECT_EQ(s.uv0[c], glm::vec2(0.0f));
    EXPECT_EQ(s.colors[c], glm::vec4(1.0f));
  }
  for (size_t c = 6; c < 12; ++c) EXPECT_EQ(s.uv0[c], glm::vec2(s.positions[c])) << "u along x, v along y";
  EXPECT_EQ(s.colors[6], glm::vec4(1, 0, 0, 1));  // vertex 0, alpha 1 for VEC3
  EXPECT_EQ(s.colors[7], glm::vec4(0, 1, 0, 1));
}

TEST(GltfAttributes, TangentsAreGeneratedForNormalMapsAndFlipUnderMirroring) {
  GltfBuilder b;
  Quad q = addQuad(b);
  std::string prim =
      primitive(R"("POSITION":)" + std::to_string(q.position) + R"(,"TEXCOORD_0":)" + std::to_string(q.uv), q.indices, 0);
  for (bool mirror : {false, true}) {
    std::string node = mirror ? R"("nodes":[{"mesh":0,"scale":[-1,1,1]}],)" : R"("nodes":[{"mesh":0}],)";
    Scene s = loadGltf(b.write(dir(), mirror ? "tangent_mirror" : "tangent", node + kNormalMapped + "," + meshJson(prim)));
    ASSERT_EQ(s.tangents.size(), s.positions.size());
    for (size_t c = 0; c < s.tangents.size(); ++c) {
      EXPECT_NEAR(s.tangents[c].x, mirror ? -1.0f : 1.0f, 1e-5f) << "the tangent follows u, through the node transform";
      EXPECT_NEAR(glm::dot(glm::vec3(s.tangents[c]), s.normals[c]), 0.0f, 1e-5f);
      // The bitangent cross(n, t) * w points up the image, against v (v runs along +y here), in either case.
      EXPECT_LT((glm::cross(s.normals[c], glm::vec3(s.tangents[c])) * s.tangents[c].w).y, -0.99f) << "mirror " << mirror;
    }
  }
}

TEST(GltfAttributes, StoredTangentsAreTransformedAndReorthogonalized) {
  GltfBuilder b;
  Quad q = addQuad(b);
  std::vector<float> t = {1, 0, 0.5f, -1, 1, 0, 0.5f, -1, 1, 0, 0.5f, -1, 1, 0, 0.5f, -1};  // not perpendicular to +z
  int tangent = b.accessor(t, 5126, "VEC4", 4);
  std::string prim =
      primitive(R"("POSITION":)" + std::to_string(q.position) + R"(,"TANGENT":)" + std::to_string(tangent), q.indices, 0);
  Scene s =
      loadGltf(b.write(dir(), "tangent_stored",
                       R"("nodes":[{"mesh":0,"rotation":[0,0,0.7071068,0.7071068]}],)" + kNormalMapped + "," + meshJson(prim)));
  ASSERT_EQ(s.tangents.size(), 6u);
  EXPECT_NEAR(s.tangents[0].y, 1.0f, 1e-5f) << "+x rotated 90 degrees about z, z part removed";
  EXPECT_NEAR(s.tangents[0].z, 0.0f, 1e-5f);
  EXPECT_EQ(s.tangents[0].w, -1.0f);
}

TEST(GltfAttributes, QuantizedPositionsLoad) {
  // KHR_mesh_quantization: unsigned short positions (not normalized) scaled down by the node, normalized byte normals.
  GltfBuilder b;
  std::vector<uint16_t> p = {0, 0, 0, 0, 1000, 0, 0, 0, 1000, 1000, 0, 0, 0, 1000, 0, 0};  // x y z + pad, stride 8
  std::vector<int8_t> n = {0, 0, 127, 0, 0, 0, 127, 0, 0, 0, 127, 0, 0, 0, 127, 0};
  int position = b.accessor(b.view(p, 8), 5123, "VEC3", 4);
  int normal = b.accessor(b.view(n, 4), 5120, "VEC3", 4, R"("normalized":true)");
  std::vector<uint8_t> idx = {0, 1, 2, 0, 2, 3};
  int indices = b.accessor(idx, 5121, "SCALAR", 6);
  std::string prim = primitive(R"("POSITION":)" + std::to_string(position) + R"(,"NORMAL":)" + std::to_string(normal), indices);
  Scene s = loadGltf(b.write(dir(), "quantized",
                             R"("extensionsUsed":["KHR_mesh_quantization"],"extensionsRequired":["KHR_mesh_quantization"],
    "nodes":[{"mesh":0,"scale":[0.001,0.001,0.001]}],)" +
                                 meshJson(prim)));
  ASSERT_EQ(s.triangleCount(), 2u);
  EXPECT_NEAR(s.bounds.max.x, 1.0f, 1e-6f);
  EXPECT_NEAR(s.bounds.max.y, 1.0f, 1e-6f);
  EXPECT_NEAR(s.normals[0].z, 1.0f, 1e-6f);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(GltfAttributes, MorphTargetsApplyAtTheirDefaultWeights) {
  GltfBuilder b;
  Quad q = addQuad(b);
  std::vector<float> up = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  int delta = b.accessor(up, 5126, "VEC3", 4);
  std::string prim = R"({"attributes":{"POSITION":)" + std::to_string(q.position) + R"(},"indices":)" +
                     std::to_string(q.indices) + R"(,"targets":[{"POSITION":)" + std::to_string(delta) + "}]}";
  std::string mesh = R"("meshes":[{"primitives":[)" + prim + R"(],"weights":[0.5]}])";
  Scene s =
      loadGltf(b.write(dir(), "morph", R"("nodes":[{"mesh":0},{"mesh":0,"weights":[2],"translation":[5,0,0]}],)" + mesh, "0,1"));
  ASSERT_EQ(s.triangleCount(), 4u);
  EXPECT_FLOAT_EQ(s.positions[0].z, 0.5f) << "mesh.weights";
  EXPECT_FLOAT_EQ(s.positions[6].z, 2.0f) << "node.weights override mesh.weights";
}

TEST(GltfAttributes, SparseMorphTargetsWithoutABufferView) {
  // The usual exporter output: a target that moves one vertex, as a sparse accessor over implicit zeros.
  GltfBuilder b;
  Quad q = addQuad(b);
  std::vector<uint8_t> which = {2};
  std::vector<float> delta = {0, 0, 4};
  int indices = b.view(which), values = b.view(delta);
  int target = b.accessor(-1, 5126, "VEC3", 4,
                          R"("sparse":{"count":1,"indices":{"bufferView":)" + std::to_string(indices) +
                              R"(,"componentType":5121},"values":{"bufferView":)" + std::to_string(values) + "}}");
  std::string prim = R"({"attributes":{"POSITION":)" + std::to_string(q.position) + R"(},"indices":)" +
                     std::to_string(q.indices) + R"(,"targets":[{"POSITION":)" + std::to_string(target) + "}]}";
  Scene s = loadGltf(
      b.write(dir(), "morph_sparse", R"("nodes":[{"mesh":0}],"meshes":[{"primitives":[)" + prim + R"(],"weights":[0.5]}])"));
  ASSERT_EQ(s.triangleCount(), 2u);
  EXPECT_FLOAT_EQ(s.positions[2].z, 2.0f) << "vertex 2 moved by 0.5 x 4";
  EXPECT_FLOAT_EQ(s.positions[1].z, 0.0f);
}

TEST(GltfAttributes, EveryGpuInstanceIsDrawnAtItsPlace) {
  GltfBuilder b;
  Quad q = addQuad(b);
  std::vector<float> t = {0, 0, 0, 10, 0, 0, 0, 20, 0};
  std::vector<float> sc = {1, 1, 1, 2, 2, 2, 1, 1, 1};
  int translation = b.accessor(t, 5126, "VEC3", 3), scale = b.accessor(sc, 5126, "VEC3", 3);
  std::string prim = primitive(R"("POSITION":)" + std::to_string(q.position), q.indices);
  std::string nodes = R"("extensionsUsed":["EXT_mesh_gpu_instancing"],"nodes":[{"mesh":0,"translation":[0,0,-1],
    "extensions":{"EXT_mesh_gpu_instancing":{"attributes":{"TRANSLATION":)" +
                      std::to_string(translation) + R"(,"SCALE":)" + std::to_string(scale) + "}}}}],";
  Scene s = loadGltf(b.write(dir(), "instanced", nodes + meshJson(prim)));
  ASSERT_EQ(s.triangleCount(), 6u);
  EXPECT_EQ(s.positions[0], glm::vec3(0, 0, -1));
  EXPECT_EQ(s.positions[7], glm::vec3(12, 0, -1)) << "instance 1: translated by 10, scaled by 2, then the node";
  EXPECT_EQ(s.positions[14], glm::vec3(1, 21, -1));
  EXPECT_TRUE(s.warnings.empty()) << s.warnings[0];
}

TEST(GltfAttributes, InstancingBombsAreRefusedBeforeAllocation) {
  GltfBuilder b;
  Quad q = addQuad(b);
  int translation = b.accessor(-1, 5126, "VEC3", size_t(1) << 40);  // a view-less accessor: 2^40 zero translations
  std::string prim = primitive(R"("POSITION":)" + std::to_string(q.position), q.indices);
  std::string nodes = R"("nodes":[{"mesh":0,"extensions":{"EXT_mesh_gpu_instancing":{"attributes":{"TRANSLATION":)" +
                      std::to_string(translation) + "}}}}],";
  std::string msg = test::loadError(b.write(dir(), "instance_bomb", nodes + meshJson(prim)));
  EXPECT_NE(msg.find("scene too big"), std::string::npos) << msg;
}

// A skinned mesh needs JOINTS_0 and WEIGHTS_0 (glTF 2.0 section 3.7.3); posed skins: tests/unit/gltf_skin_test.cpp.
TEST(GltfAttributes, ASkinnedMeshWithoutJointsIsRefusedWithOneLine) {
  GltfBuilder b;
  Quad q = addQuad(b);
  std::string prim = primitive(R"("POSITION":)" + std::to_string(q.position), q.indices);
  std::string error = test::loadError(
      b.write(dir(), "skinned",
              R"("nodes":[{"mesh":0,"skin":0,"translation":[0,0,3]},{"translation":[9,9,9]}],"skins":[{"joints":[1]}],)" +
                  meshJson(prim)));
  EXPECT_NE(error.find("lacks JOINTS_0 and WEIGHTS_0"), std::string::npos) << error;
}

TEST(GltfAttributes, PointsAndLinesBecomeSegmentsByTheirMode) {
  // Four vertices drawn in each point and line mode: POINTS 4 (each its own end twice), LINES 2, LINE_LOOP 4 (the
  // last back to the first), LINE_STRIP 3; COLOR_0 rides along. A triangle keeps the scene loadable.
  GltfBuilder b;
  Quad q = addQuad(b);
  std::vector<float> p = {0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  int pos = b.accessor(p, 5126, "VEC3", 4, R"("min":[0,0,1],"max":[1,1,1])");
  std::vector<float> rgb = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0};
  int color = b.accessor(rgb, 5126, "VEC3", 4);
  std::string prims = primitive(R"("POSITION":)" + std::to_string(q.position), q.indices);
  for (int mode : {0, 1, 2, 3})
    prims += R"(,{"attributes":{"POSITION":)" + std::to_string(pos) + R"(,"COLOR_0":)" + std::to_string(color) + R"(},"mode":)" +
             std::to_string(mode) + "}";
  Scene s = loadGltf(b.write(dir(), "modes", R"("nodes":[{"mesh":0,"translation":[0,0,2]}],)" + meshJson(prims)));
  EXPECT_EQ(s.triangleCount(), 2u);
  ASSERT_EQ(s.thinSegments.size(), 4u + 2u + 4u + 3u);
  EXPECT_EQ(s.skippedPrimitives, 0u);
  const ThinSegment& point = s.thinSegments[1];
  EXPECT_EQ(point.a, point.b);
  EXPECT_EQ(point.a, glm::vec3(1, 0, 3)) << "world space";
  EXPECT_EQ(point.colorA, glm::vec4(0, 1, 0, 1));
  const ThinSegment& line = s.thinSegments[5];  // LINES' second: vertices 2, 3
  EXPECT_EQ(line.a, glm::vec3(1, 1, 3));
  EXPECT_EQ(line.b, glm::vec3(0, 1, 3));
  EXPECT_EQ(s.thinSegments[9].b, glm::vec3(0, 0, 3)) << "the loop closes on its first vertex";
  EXPECT_EQ(s.thinSegments[12].a, glm::vec3(1, 1, 3)) << "the strip's last segment starts at vertex 2";
  EXPECT_EQ(s.bounds.max.z, 3.0f) << "segments count in the bounds (the automatic camera frames them)";
}

TEST(PointsAndLines, SegmentCountsPerMode) {
  EXPECT_EQ(segmentCount(0, 3), 3u);  // POINTS
  EXPECT_EQ(segmentCount(1, 5), 2u);  // LINES: an odd element is dropped
  EXPECT_EQ(segmentCount(3, 4), 3u);  // LINE_STRIP
  EXPECT_EQ(segmentCount(2, 4), 4u);  // LINE_LOOP closes back to the start
  EXPECT_EQ(segmentCount(2, 2), 1u) << "a loop of two vertices is one segment, not the same one twice";
  EXPECT_EQ(segmentCount(2, 1), 0u);
}
