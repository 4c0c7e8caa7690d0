// The material extensions read into a Material (scene/gltf_material_extensions.cpp): every value, its default,
// and one error line naming the material, the extension and the key for a value out of range.
#include <gtest/gtest.h>

#include "scene/dispersion.h"
#include "scene/gltf_loader.h"
#include "scene/scene_features.h"
#include "support/test_scenes.h"

using namespace vkmc;
using vkmc::test::GltfSpec;

namespace {
std::filesystem::path dir() {
  static auto d = test::makeTempDir("material_extensions");
  return d;
}

std::string quadWith(const std::string& name, const std::string& extensions) {
  GltfSpec spec = test::quadSpec();
  spec.materialJson =
      R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1],"roughnessFactor":0.5},"extensions":{)" + extensions + "}}";
  return test::writeGltf(dir(), name, spec);
}
}  // namespace

TEST(MaterialExtensions, EveryValueIsRead) {
  Scene s = loadGltf(quadWith("all", R"(
    "KHR_materials_specular":{"specularFactor":0.5,"specularColorFactor":[2,1,0.5]},
    "KHR_materials_ior":{"ior":1.33},
    "KHR_materials_transmission":{"transmissionFactor":0.75},
    "KHR_materials_volume":{"thicknessFactor":0.1,"attenuationDistance":2,"attenuationColor":[0.5,1,0.25]},
    "KHR_materials_clearcoat":{"clearcoatFactor":0.6,"clearcoatRoughnessFactor":0.2},
    "KHR_materials_sheen":{"sheenColorFactor":[0.3,0.2,0.1],"sheenRoughnessFactor":0.4})"));
  const Material& m = s.materials[0];
  EXPECT_FLOAT_EQ(m.specular, 0.5f);
  EXPECT_EQ(m.specularColor, glm::vec3(2.0f, 1.0f, 0.5f));
  EXPECT_FLOAT_EQ(m.ior, 1.33f);
  EXPECT_FLOAT_EQ(m.transmission, 0.75f);
  EXPECT_TRUE(m.volumetric);
  EXPECT_NEAR(m.attenuation.x, std::log(2.0) / 2, 1e-6);  // -ln(color) / distance
  EXPECT_EQ(m.attenuation.y, 0.0f);
  EXPECT_NEAR(m.attenuation.z, std::log(4.0) / 2, 1e-6);
  EXPECT_FLOAT_EQ(m.clearcoat, 0.6f);
  EXPECT_FLOAT_EQ(m.clearcoatRoughness, 0.2f);
  EXPECT_EQ(m.sheenColor, glm::vec3(0.3f, 0.2f, 0.1f));
  EXPECT_FLOAT_EQ(m.sheenRoughness, 0.4f);
  EXPECT_FALSE(m.culledFromBehind()) << "a transmitting surface is left through its back faces";
  SceneFeatures f = scanFeatures(s);
  EXPECT_TRUE(f.transmission && f.volumes && f.clearcoat && f.sheen && f.glossy);
  EXPECT_FALSE(f.delta) << "roughness 0.5 and clearcoat roughness 0.2 are rough, and nothing is textured";
  EXPECT_FALSE(f.singleSided);
}

TEST(MaterialExtensions, DefaultsAndSmoothLobes) {
  Scene s = loadGltf(quadWith("defaults", R"("KHR_materials_transmission":{},"KHR_materials_clearcoat":{"clearcoatFactor":1})"));
  const Material& m = s.materials[0];
  EXPECT_EQ(m.transmission, 0.0f);
  EXPECT_FLOAT_EQ(m.ior, 1.5f);
  EXPECT_FALSE(m.volumetric);
  EXPECT_EQ(m.clearcoatRoughness, 0.0f);
  SceneFeatures f = scanFeatures(s);
  EXPECT_FALSE(f.transmission);
  EXPECT_TRUE(f.clearcoat);
  EXPECT_TRUE(f.delta) << "a clearcoat of roughness 0 is a delta lobe";
  EXPECT_TRUE(f.singleSided);
}

// KHR_materials_iridescence: every value (the ratified spelling of the film's ior and the draft's), its defaults,
// and a thickness that is the maximum without a thickness texture.
TEST(MaterialExtensions, IridescenceIsRead) {
  Scene s = loadGltf(quadWith("film", R"("KHR_materials_iridescence":{"iridescenceFactor":0.8,"iridescenceIor":1.6,
      "iridescenceThicknessMinimum":150,"iridescenceThicknessMaximum":500})"));
  const Material& m = s.materials[0];
  EXPECT_FLOAT_EQ(m.iridescence, 0.8f);
  EXPECT_FLOAT_EQ(m.iridescenceIor, 1.6f);
  EXPECT_FLOAT_EQ(m.iridescenceThicknessMin, 500.0f) << "no thickness texture: the maximum throughout";
  EXPECT_FLOAT_EQ(m.iridescenceThicknessMax, 500.0f);
  SceneFeatures f = scanFeatures(s);
  EXPECT_TRUE(f.iridescence && f.glossy);
  const Material draft =
      loadGltf(quadWith("draft", R"("KHR_materials_iridescence":{"iridescenceFactor":1,"iridescenceIOR":2.0})")).materials[0];
  EXPECT_FLOAT_EQ(draft.iridescenceIor, 2.0f);
  EXPECT_FLOAT_EQ(draft.iridescenceThicknessMax, 400.0f);
  const Material off = loadGltf(quadWith("off", R"("KHR_materials_iridescence":{})")).materials[0];
  EXPECT_FLOAT_EQ(off.iridescenceIor, 1.3f);
  EXPECT_FALSE(scanFeatures(loadGltf(quadWith("off2", R"("KHR_materials_iridescence":{})"))).iridescence)
      << "a factor of 0 (the default) is no film: compiled out";
  EXPECT_NE(test::loadError(quadWith("bad", R"("KHR_materials_iridescence":{"iridescenceIor":0.5})"))
                .find("KHR_materials_iridescence.iridescenceIor"),
            std::string::npos);
}

// KHR_materials_anisotropy: strength and rotation read, the scene's tangents generated for it (its direction is given
// in tangent space) and the feature compiled in; a strength of 0 (the default) is no anisotropy.
TEST(MaterialExtensions, AnisotropyIsReadWithItsTangents) {
  Scene s = loadGltf(quadWith("brushed", R"("KHR_materials_anisotropy":{"anisotropyStrength":0.6,"anisotropyRotation":1.2})"));
  const Material& m = s.materials[0];
  EXPECT_FLOAT_EQ(m.anisotropyStrength, 0.6f);
  EXPECT_FLOAT_EQ(m.anisotropyRotation, 1.2f);
  EXPECT_FALSE(s.tangents.empty()) << "an anisotropic material needs a tangent frame";
  const SceneFeatures f = scanFeatures(s);
  EXPECT_TRUE(f.anisotropy && f.textures);
  Scene off = loadGltf(quadWith("unbrushed", R"("KHR_materials_anisotropy":{"anisotropyRotation":1.2})"));
  EXPECT_FALSE(scanFeatures(off).anisotropy);
  EXPECT_TRUE(off.tangents.empty());
  EXPECT_NE(test::loadError(quadWith("overstretched", R"("KHR_materials_anisotropy":{"anisotropyStrength":1.5})"))
                .find("KHR_materials_anisotropy.anisotropyStrength"),
            std::string::npos);
}

// KHR_materials_dispersion: read, and a feature only where the material refracts into a volume (the extension's
// rule); the channels' iors from Cauchy's fit: the file's ior at the d line, n_F - n_C = (n_d - 1) / V with
// V = 20 / dispersion, blue above green above red, and all equal without dispersion.
TEST(MaterialExtensions, DispersionIsReadAndSpreadsTheIor) {
  Scene s = loadGltf(quadWith("prism", R"("KHR_materials_dispersion":{"dispersion":2},
    "KHR_materials_transmission":{"transmissionFactor":1},"KHR_materials_volume":{"thicknessFactor":1})"));
  EXPECT_FLOAT_EQ(s.materials[0].dispersion, 2.0f);
  EXPECT_TRUE(scanFeatures(s).dispersion);
  Scene thin = loadGltf(quadWith("thin", R"("KHR_materials_dispersion":{"dispersion":2},
    "KHR_materials_transmission":{"transmissionFactor":1})"));
  EXPECT_FALSE(scanFeatures(thin).dispersion) << "thin-walled: nothing refracts";
  ASSERT_EQ(thin.warnings.size(), 1u);
  EXPECT_NE(thin.warnings[0].find("KHR_materials_dispersion without transmission into a KHR_materials_volume"), std::string::npos)
      << thin.warnings[0];
  EXPECT_NE(test::loadError(quadWith("negative", R"("KHR_materials_dispersion":{"dispersion":-1})"))
                .find("KHR_materials_dispersion.dispersion"),
            std::string::npos);
  const float ior = 1.5f, dispersion = 2.0f;  // Abbe number 10
  EXPECT_NEAR(iorAtWavelength(ior, dispersion, 587.6f), ior, 1e-6f);
  EXPECT_NEAR(iorAtWavelength(ior, dispersion, 486.1f) - iorAtWavelength(ior, dispersion, 656.3f), (ior - 1.0f) / 10.0f, 1e-5f);
  const glm::vec3 rgb = channelIors(ior, dispersion);
  EXPECT_LT(rgb.r, rgb.g);
  EXPECT_LT(rgb.g, rgb.b);
  EXPECT_EQ(channelIors(ior, 0.0f), glm::vec3(ior));
  EXPECT_EQ(iorAtWavelength(ior, 500.0f, 630.0f), 1.0f) << "the extension clamps the ior at 1";
}

// KHR_materials_ior has no upper bound: 1000 is valid (a near-perfect mirror); beyond 1e4 it renders as 1e4.
TEST(MaterialExtensions, LargeIorsAreAccepted) {
  EXPECT_FLOAT_EQ(loadGltf(quadWith("ior1000", R"("KHR_materials_ior":{"ior":1000})")).materials[0].ior, 1000.0f);
  EXPECT_FLOAT_EQ(loadGltf(quadWith("ior1e30", R"("KHR_materials_ior":{"ior":1e30})")).materials[0].ior, 1e4f);
  EXPECT_FLOAT_EQ(loadGltf(quadWith("ior0", R"("KHR_materials_ior":{"ior":0})")).materials[0].ior, 1.0f);
}

TEST(MaterialExtensions, BadValuesAreNamedOnOneLine) {
  struct Row {
    const char* extensions;
    const char* message;
  } rows[] = {
      {R"("KHR_materials_transmission":{"transmissionFactor":1.5})", "material 0 KHR_materials_transmission.transmissionFactor"},
      {R"("KHR_materials_ior":{"ior":0.5})", "material 0 KHR_materials_ior.ior"},
      {R"("KHR_materials_ior":{"ior":"glass"})", "material 0 KHR_materials_ior.ior is not a finite number"},
      {R"("KHR_materials_volume":{"thicknessFactor":1,"attenuationDistance":0})", "attenuationDistance must be positive"},
      {R"("KHR_materials_volume":{"attenuationColor":[1,2,1]})", "KHR_materials_volume.attenuationColor"},
      {R"("KHR_materials_sheen":{"sheenColorFactor":[1,1]})", "KHR_materials_sheen.sheenColorFactor is not an array of 3"},
      {R"("KHR_materials_clearcoat":{"clearcoatRoughnessFactor":-1})", "KHR_materials_clearcoat.clearcoatRoughnessFactor"},
      {R"("KHR_materials_clearcoat":{"clearcoatTexture":{"index":9}})", "clearcoatTexture"},
      {R"("KHR_materials_specular":{"specularColorFactor":[1,-1,1]})", "KHR_materials_specular.specularColorFactor"},
  };
  int i = 0;
  for (const Row& row : rows) {
    std::string error = test::loadError(quadWith("bad" + std::to_string(i++), row.extensions));
    EXPECT_NE(error.find(row.message), std::string::npos) << row.extensions << " -> " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
}
