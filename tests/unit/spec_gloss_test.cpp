// KHR_materials_pbrSpecularGlossiness into metallic-roughness (host/scene/spec_gloss.h): the conversion exact
// for a plain dielectric and a plain metal, factors-only materials converted in place, textured ones baked per
// texel with the same conversion, and a file that requires the extension loads.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/gltf_loader.h"
#include "scene/spec_gloss.h"
#include "scene/texture_sampler.h"
#include "support/test_scenes.h"

using namespace vkmc;

namespace {
const char* kRequired = R"("extensionsUsed":["KHR_materials_pbrSpecularGlossiness"],
  "extensionsRequired":["KHR_materials_pbrSpecularGlossiness"])";
}

TEST(SpecGloss, ADielectricKeepsItsDiffuseColourAndAMetalItsSpecularColour) {
  MetalRoughSample plastic = metalRoughFromSpecGloss(glm::vec3(0.8f, 0.2f, 0.1f), glm::vec3(0.04f), 0.7f);
  EXPECT_EQ(plastic.metallic, 0.0f);
  EXPECT_NEAR(plastic.baseColor.r, 0.8f, 1e-5f);
  EXPECT_NEAR(plastic.baseColor.g, 0.2f, 1e-5f);
  EXPECT_NEAR(plastic.roughness, 0.3f, 1e-6f);
  MetalRoughSample gold = metalRoughFromSpecGloss(glm::vec3(0.0f), glm::vec3(0.9f, 0.6f, 0.3f), 1.0f);
  EXPECT_NEAR(gold.metallic, 1.0f, 1e-4f);
  EXPECT_NEAR(gold.baseColor.r, 0.9f, 1e-3f);
  EXPECT_NEAR(gold.baseColor.b, 0.3f, 1e-3f);
  EXPECT_EQ(gold.roughness, 0.0f);
  MetalRoughSample black = metalRoughFromSpecGloss(glm::vec3(0.5f), glm::vec3(0.0f), 0.0f);
  EXPECT_EQ(black.metallic, 0.0f) << "below a dielectric's 0.04 nothing is metal";
  EXPECT_EQ(black.roughness, 1.0f);
}

TEST(SpecGloss, FactorsAloneAreConvertedInPlaceAndARequiredExtensionLoads) {
  auto dir = test::makeTempDir("specgloss");
  std::string material = R"({"extensions":{"KHR_materials_pbrSpecularGlossiness":{"diffuseFactor":[0.8,0.2,0.1,0.5],
    "specularFactor":[0.04,0.04,0.04],"glossinessFactor":0.25}}})";
  Scene s = loadGltf(test::writeQuadsGltf(dir, "factors", {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0}}, material, kRequired));
  const Material& m = s.materials[0];
  EXPECT_EQ(m.metallic, 0.0f);
  EXPECT_NEAR(m.baseColor.r, 0.8f, 1e-5f);
  EXPECT_NEAR(m.roughness, 0.75f, 1e-6f);
  EXPECT_EQ(m.alpha, 0.5f);
  EXPECT_FALSE(m.textured());
}

// The extension's ranges (every factor in [0, 1]) are enforced: a specularFactor of 1e30 made 62% of samples NaN.
TEST(SpecGloss, FactorsOutsideTheirRangeAreRefusedNamingTheFactor) {
  auto dir = test::makeTempDir("specgloss_range");
  const std::pair<const char*, const char*> cases[] = {
      {R"("specularFactor":[1e30,0.04,0.04])", "specularFactor must lie in [0, 1]"},
      {R"("diffuseFactor":[0.5,0.5,-0.1,1])", "diffuseFactor must lie in [0, 1]"},
      {R"("glossinessFactor":1.5)", "glossinessFactor must lie in [0, 1]"}};
  for (const auto& [factor, expected] : cases) {
    std::string material = std::string(R"({"extensions":{"KHR_materials_pbrSpecularGlossiness":{)") + factor + "}}}";
    std::string msg =
        test::loadError(test::writeQuadsGltf(dir, "range", {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0}}, material, kRequired));
    EXPECT_NE(msg.find(expected), std::string::npos) << factor << ": " << msg;
  }
}

TEST(SpecGloss, TexturesAreBakedPerTexel) {
  // A 2 x 1 diffuse texture (red, then black) and a specular-glossiness texture (dielectric 0.04 with glossiness
  // 1, then gold with glossiness 0.5): the baked texels are the conversion of each pair.
  auto dir = test::makeTempDir("specgloss");
  auto srgb = [](float x) {
    return uint8_t(std::lround(255.0f * (x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f)));
  };
  std::string diffuse = test::writePng(dir, "diffuse", 2, 1, {255, 0, 0, 255, 0, 0, 0, 200});
  std::string sg =
      test::writePng(dir, "sg", 2, 1, {srgb(0.04f), srgb(0.04f), srgb(0.04f), 255, srgb(0.9f), srgb(0.6f), srgb(0.3f), 128});
  std::string material = R"({"extensions":{"KHR_materials_pbrSpecularGlossiness":{"diffuseTexture":{"index":0},
    "specularGlossinessTexture":{"index":1}}}})";
  std::string extra =
      std::string(kRequired) + R"(,"images":[{"uri":")" + diffuse + R"("},{"uri":")" + sg +
      R"("}],"samplers":[{"magFilter":9728,"minFilter":9728}],"textures":[{"source":0,"sampler":0},{"source":1,"sampler":0}])";
  Scene s = loadGltf(test::writeQuadsGltf(dir, "baked", {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0}}, material, extra));
  ASSERT_EQ(s.textures.size(), 4u);
  const Material& m = s.materials[0];
  ASSERT_TRUE(m.baseColorTexture.present() && m.metallicRoughnessTexture.present());
  EXPECT_EQ(m.baseColor, glm::vec3(1.0f));
  const Texture& base = s.textures[m.baseColorTexture.texture];
  const Texture& mr = s.textures[m.metallicRoughnessTexture.texture];
  ASSERT_EQ(base.width, 2u);
  glm::vec4 left = sampleTexture(base, glm::vec2(0.25f, 0.5f), true), right = sampleTexture(base, glm::vec2(0.75f, 0.5f), true);
  glm::vec4 leftMr = sampleTexture(mr, glm::vec2(0.25f, 0.5f), false), rightMr = sampleTexture(mr, glm::vec2(0.75f, 0.5f), false);
  EXPECT_NEAR(left.r, 1.0f, 0.01f);  // red plastic
  EXPECT_NEAR(left.g, 0.0f, 0.01f);
  EXPECT_NEAR(leftMr.b, 0.0f, 0.01f);  // metallic
  EXPECT_NEAR(leftMr.g, 0.0f, 0.01f);  // roughness 1 - glossiness 1
  EXPECT_NEAR(right.r, 0.9f, 0.01f);   // gold
  EXPECT_NEAR(right.b, 0.3f, 0.01f);
  EXPECT_NEAR(right.a, 200.0f / 255.0f, 0.01f) << "the diffuse texture's alpha";
  EXPECT_NEAR(rightMr.b, 1.0f, 0.01f);
  EXPECT_NEAR(rightMr.g, 1.0f - 128.0f / 255.0f, 0.01f);
}

TEST(SpecGloss, BakedAtTheFinerGridAndNeverReachableByIndex) {
  // A 1 x 1 diffuse texture and a 4 x 1 specular-glossiness one: the bake keeps the 4 texels of gloss detail.
  // A second material that points one past the file's textures is refused, though baked textures sit there.
  auto dir = test::makeTempDir("specgloss_grid");
  std::string diffuse = test::writePng(dir, "diffuse", 1, 1, {255, 255, 255, 255});
  std::string sg = test::writePng(dir, "sg", 4, 1, {10, 10, 10, 255, 10, 10, 10, 0, 10, 10, 10, 255, 10, 10, 10, 0});
  std::string material = R"({"extensions":{"KHR_materials_pbrSpecularGlossiness":{"diffuseTexture":{"index":0},
    "specularGlossinessTexture":{"index":1}}}})";
  std::string extra =
      std::string(kRequired) + R"(,"images":[{"uri":")" + diffuse + R"("},{"uri":")" + sg +
      R"("}],"samplers":[{"magFilter":9728,"minFilter":9728}],"textures":[{"source":0,"sampler":0},{"source":1,"sampler":0}])";
  Scene s = loadGltf(test::writeQuadsGltf(dir, "grid", {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0}}, material, extra));
  const Texture& mr = s.textures[s.materials[0].metallicRoughnessTexture.texture];
  ASSERT_EQ(mr.width, 4u);
  EXPECT_NEAR(sampleTexture(mr, glm::vec2(0.125f, 0.5f), false).g, 0.0f, 0.01f);  // glossiness 1
  EXPECT_NEAR(sampleTexture(mr, glm::vec2(0.375f, 0.5f), false).g, 1.0f, 0.01f);  // glossiness 0
  std::string twoMaterials = material + R"(,{"pbrMetallicRoughness":{"baseColorTexture":{"index":2}}})";
  std::string error = test::loadError(test::writeQuadsGltf(
      dir, "past", {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0}, {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, 1}}, twoMaterials, extra));
  EXPECT_NE(error.find("refers to missing texture 2"), std::string::npos) << error;
}
