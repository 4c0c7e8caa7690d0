// The core material factors read into a Material (scene/gltf_material.cpp): each checked against its range in the
// glTF 2.0 schema, a value just past a bound by rounding taken as the bound, and one error line naming the
// material and the key for a value out of range.
#include <gtest/gtest.h>

#include "scene/gltf_loader.h"
#include "support/test_scenes.h"

using namespace vkmc;
using vkmc::test::GltfSpec;

namespace {
std::filesystem::path dir() {
  static auto d = test::makeTempDir("gltf_material");
  return d;
}

std::string quadWith(const std::string& name, const std::string& materialJson) {
  GltfSpec spec = test::quadSpec();
  spec.materialJson = materialJson;
  return test::writeGltf(dir(), name, spec);
}
}  // namespace

TEST(GltfMaterial, CoreFactorsAreRead) {
  Scene s = loadGltf(quadWith("core", R"({"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.25,1,0.75],
      "metallicFactor":0.3,"roughnessFactor":0.6},"emissiveFactor":[0.2,0.4,1],"alphaMode":"MASK","alphaCutoff":0.25,
      "extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":10}}})"));
  const Material& m = s.materials[0];
  EXPECT_EQ(m.baseColor, glm::vec3(0.5f, 0.25f, 1.0f));
  EXPECT_FLOAT_EQ(m.alpha, 0.75f);
  EXPECT_FLOAT_EQ(m.metallic, 0.3f);
  EXPECT_FLOAT_EQ(m.roughness, 0.6f);
  EXPECT_EQ(m.emission, glm::vec3(2.0f, 4.0f, 10.0f));
  EXPECT_EQ(m.alphaMode, AlphaMode::Mask);
  EXPECT_FLOAT_EQ(m.alphaCutoff, 0.25f);
}

TEST(GltfMaterial, ValuesPastABoundByRoundingAreTheBound) {
  Scene s = loadGltf(quadWith("rounding", R"({"pbrMetallicRoughness":{"baseColorFactor":[1.000001,1,1,1],
      "metallicFactor":-0.000001,"roughnessFactor":1.000001}})"));
  const Material& m = s.materials[0];
  EXPECT_EQ(m.baseColor.x, 1.0f);
  EXPECT_EQ(m.metallic, 0.0f);
  EXPECT_EQ(m.roughness, 1.0f);
}

// An emissiveFactor above the schema's 1 (older Blender exporters wrote a strength there): rendered as given, as
// viewers render it, with a warning naming the material.
TEST(GltfMaterial, AnEmissiveFactorAboveOneIsUsedWithAWarning) {
  Scene s = loadGltf(quadWith("emissive_above_one", R"({"emissiveFactor":[0,5,2]})"));
  EXPECT_EQ(s.materials[0].emission, glm::vec3(0.0f, 5.0f, 2.0f));
  bool warned = false;
  for (const std::string& w : s.warnings) warned |= w.find("material 0: emissiveFactor = 5 is above") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(GltfMaterial, ValuesOutsideTheSchemasRangesAreNamedOnOneLine) {
  struct Row {
    const char* material;
    const char* message;
  } rows[] = {
      {R"({"pbrMetallicRoughness":{"baseColorFactor":[1.5,1,1,1]}})", "material 0: baseColorFactor = 1.5 is outside [0, 1]"},
      {R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,2]}})", "material 0: baseColorFactor's alpha = 2"},
      {R"({"pbrMetallicRoughness":{"baseColorFactor":[1,-0.5,1,1]}})", "baseColorFactor = -0.5 is outside"},
      {R"({"pbrMetallicRoughness":{"metallicFactor":1e30}})", "material 0: metallicFactor = 1e+30 is outside [0, 1]"},
      {R"({"pbrMetallicRoughness":{"roughnessFactor":-2}})", "material 0: roughnessFactor = -2"},
      {R"({"emissiveFactor":[0,-5,0]})", "material 0: emissiveFactor = -5 is outside [0, inf]"},
      {R"({"emissiveFactor":[1,1,1],"extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":-1}}})",
       "emissiveStrength = -1 is outside [0, inf]"},
      {R"({"emissiveFactor":[1,1,1],"extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":"bright"}}})",
       "emissiveStrength is not a finite number"},
      {R"({"emissiveFactor":[1,1,1],"extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":1e300}}})",
       "overflows float"},
      {R"({"alphaMode":"MASK","alphaCutoff":-0.5})", "material 0: alphaCutoff = -0.5 is outside [0, inf]"},
      {R"({"alphaMode":"GLASS"})", "material 0: alphaMode 'GLASS' is not OPAQUE, MASK or BLEND"},
  };
  int i = 0;
  for (const Row& row : rows) {
    std::string error = test::loadError(quadWith("bad" + std::to_string(i++), row.material));
    EXPECT_NE(error.find(row.message), std::string::npos) << row.material << " -> " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
}
