// glTF loading: indices of every width, transforms, materials and extensions, and every malformed input
// rejected with a clear message.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>

#include "error.h"
#include "scene/gltf_loader.h"
#include "support/test_scenes.h"

#include <nlohmann/json.hpp>

using namespace vkmc;
using vkmc::test::GltfSpec;

namespace {
std::filesystem::path dir() {
  static auto d = test::makeTempDir("loader");
  return d;
}
}  // namespace

// Index component types: 5121 u8, 5123 u16, 5125 u32.
class IndexWidth : public ::testing::TestWithParam<int> {};

TEST_P(IndexWidth, LoadsIndexedQuad) {
  const int ct = GetParam();
  GltfSpec s = test::quadSpec();
  s.indexComponentType = ct;
  Scene scene = loadGltf(test::writeGltf(dir(), "quad" + std::to_string(ct), s));
  EXPECT_EQ(scene.triangleCount(), 2u);
  EXPECT_EQ(scene.degenerateTriangles, 0u);
}

INSTANTIATE_TEST_SUITE_P(GltfLoader, IndexWidth, ::testing::Values(5121, 5123, 5125), [](const auto& info) {
  return info.param == 5121 ? std::string("u8") : info.param == 5123 ? std::string("u16") : std::string("u32");
});

// The world a file declares on its scene (extras.vkmc_world): the studio where it declares none, or something else.
TEST(GltfLoader, ReadsTheWorldTheSceneDeclares) {
  const std::string quad = test::writeGltf(dir(), "world", test::quadSpec());
  auto loadDeclaring = [&](const nlohmann::json* world) {
    std::ifstream in(quad);
    nlohmann::json gltf = nlohmann::json::parse(in);
    gltf["scenes"][0].erase("extras");
    if (world) gltf["scenes"][0]["extras"]["vkmc_world"] = *world;
    std::ofstream(quad) << gltf.dump();
    return loadGltf(quad);
  };
  EXPECT_EQ(loadDeclaring(nullptr).world, World::Studio);
  const nlohmann::json lightsOnly = "lights-only", white = "white", studio = "studio", odd = "dark", number = 3;
  EXPECT_EQ(loadDeclaring(&lightsOnly).world, World::LightsOnly);
  EXPECT_EQ(loadDeclaring(&white).world, World::White);
  EXPECT_EQ(loadDeclaring(&studio).world, World::Studio);
  for (const nlohmann::json* unknown : {&odd, &number}) {
    const Scene s = loadDeclaring(unknown);
    EXPECT_EQ(s.world, World::Studio);
    ASSERT_FALSE(s.warnings.empty());
    EXPECT_NE(s.warnings.back().find("vkmc_world"), std::string::npos);
  }
}

TEST(GltfLoader, LoadsNonIndexedAndAppliesNodeTransforms) {
  GltfSpec s = test::quadSpec();
  s.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0};
  s.indices.clear();
  s.nodeExtra = R"("translation":[10,0,0],"scale":[2,2,2])";
  Scene scene = loadGltf(test::writeGltf(dir(), "flat", s));
  ASSERT_EQ(scene.triangleCount(), 1u);
  EXPECT_FLOAT_EQ(scene.positions[1].x, 12.0f);
  EXPECT_FLOAT_EQ(scene.bounds.max.y, 2.0f);
}

TEST(GltfLoader, MirroringTransformKeepsFrontFaces) {
  GltfSpec s = test::quadSpec();
  s.nodeExtra = R"("scale":[-1,1,1])";
  Scene scene = loadGltf(test::writeGltf(dir(), "mirror", s));
  glm::vec3 n = glm::cross(scene.positions[1] - scene.positions[0], scene.positions[2] - scene.positions[0]);
  EXPECT_GT(n.z, 0.0f) << "a mirrored +z-facing quad must still face +z";
}

TEST(GltfLoader, ReadsMaterialFactorsAndExtensions) {
  GltfSpec s = test::quadSpec();
  s.materialJson = R"({"pbrMetallicRoughness":{"baseColorFactor":[0.2,0.3,0.4,1],"metallicFactor":0.1,"roughnessFactor":0.7},
    "emissiveFactor":[1,0.5,0.25],"doubleSided":true,
    "extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":8},"KHR_materials_specular":{"specularFactor":0}}})";
  Scene scene = loadGltf(test::writeGltf(dir(), "material", s));
  const Material& m = scene.materials[scene.materialIds[0]];
  EXPECT_FLOAT_EQ(m.baseColor.y, 0.3f);
  EXPECT_FLOAT_EQ(m.emission.x, 8.0f);
  EXPECT_FLOAT_EQ(m.emission.z, 2.0f);
  EXPECT_FLOAT_EQ(m.specular, 0.0f);
  EXPECT_FLOAT_EQ(m.roughness, 0.7f);
  EXPECT_TRUE(m.doubleSided);
}

TEST(GltfLoader, SkipsAndCountsZeroAreaTriangles) {
  GltfSpec s = test::quadSpec();
  s.positions.insert(s.positions.end(), {5, 5, 5, 6, 6, 6, 7, 7, 7});  // collinear
  s.indices.insert(s.indices.end(), {4, 5, 6, 0, 0, 1});               // sliver and repeated vertex
  Scene scene = loadGltf(test::writeGltf(dir(), "degenerate", s));
  EXPECT_EQ(scene.triangleCount(), 2u);
  EXPECT_EQ(scene.degenerateTriangles, 2u);
  EXPECT_FALSE(scene.warnings.empty());
}

TEST(GltfLoader, SkipsNonTrianglePrimitivesWithAWarning) {
  GltfSpec s = test::quadSpec();
  s.mode = 1;  // lines
  EXPECT_NE(test::loadError(test::writeGltf(dir(), "lines", s)).find("no triangles"), std::string::npos);
}

namespace {
struct Malformed {
  std::string name;
  GltfSpec spec;
  std::string expect;
};
void PrintTo(const Malformed& c, std::ostream* os) { *os << c.name; }

std::vector<Malformed> malformedInputs() {
  std::vector<Malformed> cases;
  {
    GltfSpec s = test::quadSpec();
    s.positions[4] = std::numeric_limits<float>::quiet_NaN();
    cases.push_back({"nan", s, "NaN or infinite position"});
  }
  {
    GltfSpec s = test::quadSpec();
    s.indices[2] = 9;
    cases.push_back({"index", s, "index 9 out of range"});
  }
  {
    GltfSpec s = test::quadSpec();
    s.positionCountOverride = 100;
    cases.push_back({"accessor", s, "runs past the end"});
  }
  {
    GltfSpec s = test::quadSpec();
    s.writeBin = false;
    cases.push_back({"nobin", s, "cannot load"});
  }
  {
    GltfSpec s = test::quadSpec();
    // A finite strength whose float (and product with the factor) overflows to infinity, which the loader must catch.
    s.materialJson = R"({"emissiveFactor":[1,1,1],"extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":1e39}}})";
    cases.push_back({"infemission", s, "overflows float"});
  }
  {
    GltfSpec s = test::quadSpec();
    s.materialJson = R"({"pbrMetallicRoughness":{"baseColorFactor":[1e999,0,0,1]}})";
    cases.push_back({"overflow", s, "number overflow"});
  }
  return cases;
}

class MalformedInput : public ::testing::TestWithParam<Malformed> {};
}  // namespace

TEST_P(MalformedInput, IsRejectedWithOneLine) {
  const Malformed& c = GetParam();
  std::string msg = test::loadError(test::writeGltf(dir(), c.name, c.spec));
  EXPECT_NE(msg.find(c.expect), std::string::npos) << c.name << ": got '" << msg << "'";
  EXPECT_EQ(msg.find('\n'), std::string::npos) << c.name << ": message is not one line";
}

INSTANTIATE_TEST_SUITE_P(GltfLoader, MalformedInput, ::testing::ValuesIn(malformedInputs()),
                         [](const auto& info) { return info.param.name; });

TEST(GltfLoader, RejectsTruncatedFiles) {
  auto path = dir() / "truncated.gltf";
  std::ofstream(path) << R"({"asset":{"version":"2.0"},"meshes":[{"primitives":[{"attrib)";
  std::string msg = test::loadError(path.string());
  EXPECT_NE(msg.find("cannot load"), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos);
  auto glb = dir() / "truncated.glb";
  std::ofstream(glb, std::ios::binary) << std::string("glTF\x02\x00\x00\x00\xff\x00\x00\x00", 12);
  EXPECT_NE(test::loadError(glb.string()).find("cannot load"), std::string::npos);
  EXPECT_NE(test::loadError((dir() / "absent.gltf").string()).find("cannot open"), std::string::npos);
}

TEST(GltfLoader, RejectsExponentialInstancingQuickly) {
  // 40 levels, each node referencing the next twice: 2^40 instances of one quad.
  GltfSpec q = test::quadSpec();
  std::string path = test::writeGltf(dir(), "bomb_base", q);
  std::ifstream in(path);
  std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string nodes = R"("nodes":[)";
  for (int i = 0; i < 40; ++i) nodes += "{\"children\":[" + std::to_string(i + 1) + "," + std::to_string(i + 1) + "]},";
  nodes += R"({"mesh":0}],)";
  size_t a = json.find("\"nodes\":[{"), b = json.find("],", a) + 2;
  json.replace(a, b - a, nodes);
  auto bomb = dir() / "bomb.gltf";
  std::ofstream(bomb) << json;
  auto start = std::chrono::steady_clock::now();
  EXPECT_NE(test::loadError(bomb.string()).find("scene too big"), std::string::npos);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30.0);
}
