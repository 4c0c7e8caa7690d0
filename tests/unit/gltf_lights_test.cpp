// KHR_lights_punctual loading (host/scene/gltf_lights.cpp): definitions, node placement along -Z, validation.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "error.h"
#include "scene/gltf_loader.h"
#include "support/test_scenes.h"

using namespace vkmc;

namespace {
// A unit quad whose node (translated to 1,2,3 and turned 90 degrees about +X) instances light 0 of `lights`.
std::string writeLitQuad(const std::string& name, const std::string& lights, int lightIndex = 0) {
  static const std::filesystem::path dir = test::makeTempDir("gltf_lights");
  test::GltfSpec spec = test::quadSpec();
  spec.nodeExtra = R"("translation":[1,2,3],"rotation":[0.70710678,0,0,0.70710678],)"
                   R"("extensions":{"KHR_lights_punctual":{"light":)" +
                   std::to_string(lightIndex) + "}}";
  std::string path = test::writeGltf(dir, name, spec);
  nlohmann::json gltf;
  std::ifstream(path) >> gltf;
  gltf["extensionsUsed"] = {"KHR_lights_punctual"};
  gltf["extensions"]["KHR_lights_punctual"]["lights"] = nlohmann::json::parse("[" + lights + "]");
  std::ofstream(path) << gltf.dump();
  return path;
}
}  // namespace

TEST(GltfLights, ASpotIsPlacedByItsNodeAndShinesAlongItsMinusZ) {
  Scene s = loadGltf(writeLitQuad("spot", R"({"type":"spot","color":[1,0.5,0.25],"intensity":8,)"
                                          R"("spot":{"innerConeAngle":0.2,"outerConeAngle":0.6}})"));
  ASSERT_EQ(s.punctualLights.size(), 1u);
  const PunctualLight& l = s.punctualLights[0];
  EXPECT_EQ(l.kind, PunctualKind::Spot);
  EXPECT_NEAR(glm::distance(l.position, glm::vec3(1, 2, 3)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(l.direction, glm::vec3(0, 1, 0)), 0.0f, 1e-6f);  // -Z turned 90 degrees about +X
  EXPECT_EQ(l.intensity, glm::vec3(8.0f, 4.0f, 2.0f));
  EXPECT_FLOAT_EQ(l.innerConeAngle, 0.2f);
  EXPECT_FLOAT_EQ(l.outerConeAngle, 0.6f);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(GltfLights, RangeIsIgnoredWithOneWarning) {
  Scene s = loadGltf(writeLitQuad("range", R"({"type":"point","range":5})"));
  ASSERT_EQ(s.punctualLights.size(), 1u);
  EXPECT_EQ(s.punctualLights[0].intensity, glm::vec3(1.0f));  // the spec's defaults: white, intensity 1
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("range"), std::string::npos);
}

struct BadLight {
  const char* name;
  const char* lights;
  int index;
  const char* message;
};

class GltfLightsBadInput : public ::testing::TestWithParam<BadLight> {};

TEST_P(GltfLightsBadInput, IsRefusedWithOneLine) {
  const BadLight& b = GetParam();
  std::string error = test::loadError(writeLitQuad(b.name, b.lights, b.index));
  EXPECT_NE(error.find(b.message), std::string::npos) << error;
}

INSTANTIATE_TEST_SUITE_P(
    GltfLights, GltfLightsBadInput,
    ::testing::Values(BadLight{"negative_intensity", R"({"type":"point","intensity":-1})", 0, "intensity"},
                      BadLight{"negative_color", R"({"type":"point","color":[1,-1,1]})", 0, "color"},
                      BadLight{"huge_intensity", R"({"type":"point","intensity":1e300})", 0, "overflows"},
                      BadLight{"inner_not_below_outer", R"({"type":"spot","spot":{"innerConeAngle":0.5,"outerConeAngle":0.5}})",
                               0, "cone angles"},
                      BadLight{"outer_past_half_pi", R"({"type":"spot","spot":{"outerConeAngle":2}})", 0, "cone angles"},
                      BadLight{"negative_inner", R"({"type":"spot","spot":{"innerConeAngle":-0.1}})", 0, "cone angles"},
                      BadLight{"unknown_type", R"({"type":"area"})", 0, "unknown type"},
                      BadLight{"missing_light", R"({"type":"point"})", 3, "does not exist"}),
    [](const auto& info) { return std::string(info.param.name); });
