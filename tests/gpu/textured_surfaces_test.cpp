// Textured surfaces in whole renders with known answers: alpha MASK (a cutoff, from a texture) and BLEND
// (stochastic transparency, unbiased for the blend) in closest-hit and shadow walks, back-face culling of
// single-sided materials in both walks, normal mapping on a plane under a uniform environment, and glTF lines
// drawn one pixel wide.
#include <gtest/gtest.h>

#include <cmath>

#include "app/render_job.h"
#include "support/gltf_builder.h"
#include "support/render_helpers.h"
#include "support/lab_world.h"
#include "support/test_scenes.h"
#include "support/z_test.h"

using namespace vkmc;

namespace {

const char* kSpecularExtension = R"("extensionsUsed":["KHR_materials_specular"])";
// Black surfaces reflect nothing only without their dielectric specular lobe (KHR_materials_specular factor 0).
const char* kNoSpecular = R"("extensions":{"KHR_materials_specular":{"specularFactor":0}})";
const std::string kEmitter =
    std::string(R"({"pbrMetallicRoughness":{"baseColorFactor":[0,0,0,1],"metallicFactor":0},"emissiveFactor":[1,1,1],)") +
    kNoSpecular + "}";
const char* kWhite = R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1],"metallicFactor":0},
  "extensions":{"KHR_materials_specular":{"specularFactor":0}}})";

RenderOutcome render(const std::string& path, glm::vec3 from, glm::vec3 at, float fov, uint32_t spp, int maxDepth = 0,
                     std::optional<glm::vec3> background = std::nullopt) {
  RenderOptions o;
  o.scenePath = path;
  o.width = 32;
  o.height = 32;
  o.spp = spp;
  o.seed = 9;
  o.lookFrom = from;
  o.lookAt = at;
  o.fovDegrees = fov;
  o.background = background;
  o.estimator.maxDepth = maxDepth;
  o.progress = false;
  return runRender(test::sharedContext(), o);
}

// A 4 x 4 emitter of radiance 1 at z = 0 facing the camera at z = 3, and a sheet at z = 1 between them.
std::string sheetScene(const std::filesystem::path& dir, const std::string& name, const std::string& sheet,
                       const std::string& rootExtra = "") {
  std::vector<test::QuadSpec> quads = {{{-2, -2, 0}, {4, 0, 0}, {0, 4, 0}, 0}, {{-1, -1, 1}, {2, 0, 0}, {0, 2, 0}, 1}};
  return test::writeQuadsGltf(dir, name, quads, kEmitter + "," + sheet,
                              std::string(kSpecularExtension) + (rootExtra.empty() ? "" : "," + rootExtra));
}

}  // namespace

TEST(AlphaBlend, AHalfTransparentBlackSheetPassesHalfTheLight) {
  auto dir = test::makeTempDir("alpha");
  std::string sheet = R"({"pbrMetallicRoughness":{"baseColorFactor":[0,0,0,0.5],"metallicFactor":0},"alphaMode":"BLEND",
    "doubleSided":true,)" +
                      std::string(kNoSpecular) + "}";
  RenderOutcome r = render(sheetScene(dir, "blend", sheet), {0, 0, 3}, {0, 0, 0}, 30.0f, 16);
  EXPECT_TRUE(r.features.alpha);
  // The sheet reflects nothing towards the camera: every sample sees the emitter (1) or the sheet (0).
  EXPECT_TRUE(test::regionMatches(test::whole(r.film), glm::dvec3(0.5), 5.0));
}

TEST(AlphaMask, ACutoffKeepsOrRemovesTheSurface) {
  auto dir = test::makeTempDir("alpha");
  for (float alpha : {0.4f, 0.6f}) {
    std::string sheet = R"({"pbrMetallicRoughness":{"baseColorFactor":[0,0,0,)" + std::to_string(alpha) +
                        R"(],"metallicFactor":0},"alphaMode":"MASK","alphaCutoff":0.5,)" + kNoSpecular + "}";
    RenderOutcome r = render(sheetScene(dir, "mask" + std::to_string(alpha), sheet), {0, 0, 3}, {0, 0, 0}, 30.0f, 4);
    test::RegionStats all = test::whole(r.film);
    EXPECT_EQ(all.mean.g, alpha < 0.5f ? 1.0 : 0.0) << "alpha " << alpha;
  }
}

TEST(AlphaMask, TheTexturesAlphaDecidesPerTexel) {
  // A 2 x 1 texture, nearest: alpha 0 on the left half of the sheet (u < 0.5), 255 on the right.
  auto dir = test::makeTempDir("alpha");
  std::string png = test::writePng(dir, "half", 2, 1, {255, 255, 255, 0, 255, 255, 255, 255});
  std::string sheet = R"({"pbrMetallicRoughness":{"baseColorFactor":[0,0,0,1],"metallicFactor":0,
    "baseColorTexture":{"index":0}},"alphaMode":"MASK",)" +
                      std::string(kNoSpecular) + "}";
  std::string extra = R"("images":[{"uri":")" + png + R"("}],"samplers":[{"magFilter":9728,"minFilter":9728}],
    "textures":[{"source":0,"sampler":0}])";
  RenderOutcome r = render(sheetScene(dir, "masktex", sheet, extra), {0, 0, 3}, {0, 0, 0}, 30.0f, 4);
  EXPECT_TRUE(r.features.textures);
  // Columns well left of the middle see the emitter, columns well right see the black sheet.
  EXPECT_EQ(test::region(r.film, 2, 4, 12, 28).mean.g, 1.0);
  EXPECT_EQ(test::region(r.film, 20, 4, 30, 28).mean.g, 0.0);
}

TEST(AlphaBlend, ShadowRaysPassAHalfTransparentSheetHalfTheTime) {
  // A white floor at y = 0 lit by a downward emitter at y = 1; a black BLEND sheet (alpha 0.5) at y = 0.5 between
  // them, above the camera (y = 0.4), halves the floor's direct light in light-sampled and BSDF-sampled walks.
  auto dir = test::makeTempDir("alpha");
  std::vector<test::QuadSpec> quads = {{{-5, 0, 5}, {10, 0, 0}, {0, 0, -10}, 1},  // floor, facing +y
                                       {{-1, 1, -1}, {2, 0, 0}, {0, 0, 2}, 0}};   // emitter, facing -y
  std::string materials = kEmitter + "," + kWhite;
  std::string open = test::writeQuadsGltf(dir, "open", quads, materials, kSpecularExtension);
  quads.push_back({{-3, 0.5f, -3}, {6, 0, 0}, {0, 0, 6}, 2});
  std::string sheet = R"({"pbrMetallicRoughness":{"baseColorFactor":[0,0,0,0.5],"metallicFactor":0},"alphaMode":"BLEND",
    "doubleSided":true,)" +
                      std::string(kNoSpecular) + "}";
  std::string shaded = test::writeQuadsGltf(dir, "shaded", quads, materials + "," + sheet, kSpecularExtension);
  RenderOutcome a = render(open, {0, 0.4f, 0}, {0, 0, 0.001f}, 40.0f, 64, 1);
  RenderOutcome b = render(shaded, {0, 0.4f, 0}, {0, 0, 0.001f}, 40.0f, 64, 1);
  test::RegionStats full = test::whole(a.film), half = test::whole(b.film);
  ASSERT_GT(full.mean.g, 0.05);
  full.mean *= 0.5;
  full.variance *= 0.25;
  EXPECT_TRUE(test::regionsAgree(half, full, 5.0));
}

TEST(BackFaces, ASingleSidedSheetSeenFromBehindIsNotThere) {
  // The black sheet between the camera and the emitter: its front towards the camera hides the emitter; turned
  // round (front towards the emitter) it is culled unless the material is double-sided.
  auto dir = test::makeTempDir("sides");
  const std::string black = R"({"pbrMetallicRoughness":{"baseColorFactor":[0,0,0,1],"metallicFactor":0},)";
  const std::string single = black + kNoSpecular + "}", twoSided = black + R"("doubleSided":true,)" + kNoSpecular + "}";
  const test::QuadSpec emitter = {{-2, -2, 0}, {4, 0, 0}, {0, 4, 0}, 0};
  const test::QuadSpec facingCamera = {{-1, -1, 1}, {2, 0, 0}, {0, 2, 0}, 1}, facingAway = {{-1, -1, 1}, {0, 2, 0}, {2, 0, 0}, 1};
  struct Case {
    const char* name;
    test::QuadSpec sheet;
    std::string material;
    double expected;
  };
  for (const Case& c : {Case{"front", facingCamera, single, 0.0}, Case{"back", facingAway, single, 1.0},
                        Case{"back_double_sided", facingAway, twoSided, 0.0}}) {
    std::string path = test::writeQuadsGltf(dir, c.name, {emitter, c.sheet}, kEmitter + "," + c.material, kSpecularExtension);
    RenderOutcome r = render(path, {0, 0, 3}, {0, 0, 0}, 30.0f, 4);
    EXPECT_TRUE(r.features.singleSided) << c.name;  // the emitter is single-sided in every case
    EXPECT_EQ(test::whole(r.film).mean.g, c.expected) << c.name;
  }
}

TEST(BackFaces, ShadowRaysPassTheBackOfASingleSidedSheet) {
  // The floor and emitter of ShadowRaysPassAHalfTransparentSheetHalfTheTime with an opaque black single-sided
  // sheet between them: facing the emitter, walks from the floor meet its back and the floor is lit as if it
  // were not there; facing the floor, it blocks every path.
  auto dir = test::makeTempDir("sides");
  std::vector<test::QuadSpec> quads = {{{-5, 0, 5}, {10, 0, 0}, {0, 0, -10}, 1},  // floor, facing +y
                                       {{-1, 1, -1}, {2, 0, 0}, {0, 0, 2}, 0}};   // emitter, facing -y
  std::string materials = kEmitter + "," + kWhite + "," +
                          R"({"pbrMetallicRoughness":{"baseColorFactor":[0,0,0,1],"metallicFactor":0},)" + kNoSpecular + "}";
  std::string open = test::writeQuadsGltf(dir, "open", quads, materials, kSpecularExtension);
  std::vector<test::QuadSpec> up = quads, down = quads;
  up.push_back({{-3, 0.5f, 3}, {6, 0, 0}, {0, 0, -6}, 2});    // front +y, towards the emitter
  down.push_back({{-3, 0.5f, -3}, {6, 0, 0}, {0, 0, 6}, 2});  // front -y, towards the floor
  RenderOutcome a = render(open, {0, 0.4f, 0}, {0, 0, 0.001f}, 40.0f, 64, 1);
  RenderOutcome b =
      render(test::writeQuadsGltf(dir, "up", up, materials, kSpecularExtension), {0, 0.4f, 0}, {0, 0, 0.001f}, 40.0f, 64, 1);
  RenderOutcome c =
      render(test::writeQuadsGltf(dir, "down", down, materials, kSpecularExtension), {0, 0.4f, 0}, {0, 0, 0.001f}, 40.0f, 64, 1);
  ASSERT_GT(test::whole(a.film).mean.g, 0.05);
  EXPECT_TRUE(test::regionsAgree(test::whole(b.film), test::whole(a.film), 5.0));
  EXPECT_EQ(test::whole(c.film).mean.g, 0.0);
}

TEST(NormalMap, ATiltedNormalSeesTheFractionOfTheEnvironmentAboveThePlane) {
  // A white Lambertian plane under a uniform environment of radiance 1, direct light only: with its shading
  // normal tilted by theta from the geometric one, cosine-weighted directions below the plane are lost, and
  // L = (1 + cos theta) / 2 (the part of the tilted cosine lobe above the plane); without the map L = 1.
  auto dir = test::makeTempDir("normalmap");
  const double theta = 60.0 * 3.14159265358979 / 180.0;
  auto byte = [](double x) { return uint8_t(std::lround((x + 1.0) * 0.5 * 255.0)); };
  uint8_t r = byte(std::sin(theta)), g = byte(0.0), b = byte(std::cos(theta));
  std::string png = test::writePng(dir, "tilt", 1, 1, {r, g, b, 255});
  glm::dvec3 n(r / 255.0 * 2 - 1, g / 255.0 * 2 - 1, b / 255.0 * 2 - 1);
  double expected = 0.5 * (1.0 + n.z / glm::length(n));  // the 8-bit texel's own tilt
  std::string plane = R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1],"metallicFactor":0},
    "normalTexture":{"index":0},"extensions":{"KHR_materials_specular":{"specularFactor":0}}})";
  std::string extra = std::string(kSpecularExtension) + R"(,"images":[{"uri":")" + png + R"("}],"textures":[{"source":0}])";
  std::vector<test::QuadSpec> quads = {{{-5, -5, 0}, {10, 0, 0}, {0, 10, 0}, 0}};
  std::string mapped = test::writeQuadsGltf(dir, "mapped", quads, plane, extra);
  std::string flat = test::writeQuadsGltf(dir, "flat", quads, kWhite, kSpecularExtension);
  RenderOutcome m = render(mapped, {0, 0, 1}, {0, 0, 0}, 30.0f, 64, 1, glm::vec3(1.0f));
  RenderOutcome f = render(flat, {0, 0, 1}, {0, 0, 0}, 30.0f, 64, 1, glm::vec3(1.0f));
  EXPECT_TRUE(m.features.normalMaps);
  EXPECT_NEAR(test::whole(f.film).mean.g, 1.0, 1e-4);  // every sample is 1 up to rounding
  EXPECT_TRUE(test::regionMatches(test::whole(m.film), glm::dvec3(expected), 5.0)) << "expected " << expected;
}

TEST(NormalMap, ATiltedMirrorStillReflectsTheEnvironment) {
  // A white mirror (metal, roughness 0) seen from straight above with its normal map tilted by 60 degrees: the
  // mirror direction about the mapped normal points 120 degrees from the geometric one, under the plane, and
  // such paths died black. The lifted normal (normalForValidReflection) mirrors the view just above the plane,
  // where the uniform background of radiance 1 is: L = F G2 / G1, 1 for a white metal at alpha 1e-4.
  auto dir = test::makeTempDir("normalmap");
  const double theta = 60.0 * 3.14159265358979 / 180.0;
  auto byte = [](double x) { return uint8_t(std::lround((x + 1.0) * 0.5 * 255.0)); };
  std::string png = test::writePng(dir, "tilt", 1, 1, {byte(std::sin(theta)), byte(0.0), byte(std::cos(theta)), 255});
  std::string mirror = R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1],"metallicFactor":1,"roughnessFactor":0},
    "normalTexture":{"index":0}})";
  std::string extra = R"("images":[{"uri":")" + png + R"("}],"textures":[{"source":0}])";
  std::vector<test::QuadSpec> quads = {{{-5, -5, 0}, {10, 0, 0}, {0, 10, 0}, 0}};
  RenderOutcome m =
      render(test::writeQuadsGltf(dir, "mirror", quads, mirror, extra), {0, 0, 1}, {0, 0, 0}, 30.0f, 16, 1, glm::vec3(1.0f));
  test::RegionStats all = test::whole(m.film);
  EXPECT_GT(all.mean.g, 0.99);
  EXPECT_LT(all.mean.g, 1.0 + 5.0 * std::sqrt(all.variance.g) + 1e-4);
}

TEST(ThinRibbons, ALineCoversOnePixelOfEachColumn) {
  // A black LINES segment across the middle of the view, in front of an emitter of radiance 1: each sample sees
  // 1 or 0, so a column's darkness summed over its rows is the line's width in pixels, 1 (the ribbon is a pixel
  // at its distance; in the central columns the view's obliqueness changes that by under 0.2%).
  auto dir = test::makeTempDir("ribbons");
  test::GltfBuilder b;
  int quad =
      b.accessor(std::vector<float>{-2, -2, 0, 2, -2, 0, 2, 2, 0, -2, 2, 0}, 5126, "VEC3", 4, R"("min":[-2,-2,0],"max":[2,2,0])");
  int quadIndices = b.accessor(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, 5123, "SCALAR", 6);
  int line = b.accessor(std::vector<float>{-3, 0, 1, 3, 0, 1}, 5126, "VEC3", 2, R"("min":[-3,0,1],"max":[3,0,1])");
  std::string black =
      R"({"pbrMetallicRoughness":{"baseColorFactor":[0,0,0,1],"metallicFactor":0},)" + std::string(kNoSpecular) + "}";
  std::string body = R"("nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":)" + std::to_string(quad) +
                     R"(},"indices":)" + std::to_string(quadIndices) + R"(,"material":0},{"attributes":{"POSITION":)" +
                     std::to_string(line) + R"(},"mode":1,"material":1}]}],"materials":[)" + kEmitter + "," + black + "]," +
                     kSpecularExtension;
  RenderOutcome r = render(b.write(dir, "line", body), {0, 0, 3}, {0, 0, 0}, 30.0f, 64);
  test::RegionStats centre = test::region(r.film, 12, 0, 20, 32);  // 8 central columns, every row
  double darkness = 32.0 * (1.0 - centre.mean.g), sigma = 32.0 * std::sqrt(centre.variance.g);
  EXPECT_NEAR(darkness, 1.0, 5.0 * sigma + 0.003) << "sigma " << sigma;
  EXPECT_GT(darkness, 0.5) << "the line is drawn";
}

TEST(DefaultLight, TheStudioLightsAFileThatDeclaresNoWorldWithItsOwnLightsOnTop) {
  // A file that declares no world is lit by the studio, whether it has an emissive map (a decoration), a plain
  // emitter (a light, as in the Cornell box) or neither: its own lights are added on top, as viewers show it.
  auto dir = test::makeTempDir("defaultlight");
  std::string png = test::writePng(dir, "glow", 1, 1, {255, 128, 0, 255});
  std::string extra = R"("images":[{"uri":")" + png + R"("}],"textures":[{"source":0}])";
  std::vector<test::QuadSpec> quads = {{{-1, -1, 0}, {2, 0, 0}, {0, 2, 0}, 0}};
  for (const std::string& material :
       {std::string(R"({"emissiveFactor":[1,1,1],"emissiveTexture":{"index":0}})"), std::string(R"({"emissiveFactor":[1,1,1]})"),
        std::string(R"({"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.5,0.5,1]}})")}) {
    std::string file = test::withoutWorld(test::writeQuadsGltf(dir, "undeclared", quads, material, extra));
    RenderOutcome r = render(file, {0, 0, 3}, {0, 0, 0}, 30.0f, 1);
    EXPECT_EQ(r.environment, "studio") << material;
    EXPECT_EQ(r.backdrop, kDefaultBackdrop) << material;
    // The quad fills the middle: every sample there is its emission (red 1 under both emissive materials) plus
    // what it reflects of the studio, so the file's own light is still there, on top.
    const test::RegionStats centre = test::region(r.film, 12, 12, 20, 20);
    if (material.find("emissive") != std::string::npos) {
      EXPECT_GE(centre.mean.x, 1.0 - 1e-6) << material;
    }
    EXPECT_GT(centre.mean.y, 0.0) << material;
  }
  // The tests' own files declare theirs: lights-only where a plain emitter lights them.
  RenderOutcome lab =
      render(test::writeQuadsGltf(dir, "plain", quads, R"({"emissiveFactor":[1,1,1]})"), {0, 0, 3}, {0, 0, 0}, 30.0f, 1);
  EXPECT_TRUE(lab.environment.empty()) << lab.environment;
}

TEST(NormalMap, GreenTiltsTheNormalUpTheImage) {
  // A white plane facing +z whose uvs run (0,0) at -x-y to (1,1) at +x+y, so the image's "up" (-v) is -y, lit
  // by an emitter on its +y side. A normal map tilting its normals 60 degrees up the image (green > 0.5) turns
  // them away from the light; tilting them down it (green < 0.5) turns them toward it. Generated tangents with
  // the wrong bitangent sign swap the two.
  auto dir = test::makeTempDir("normalmap");
  const double s = std::sin(60.0 * 3.14159265358979 / 180.0), c = 0.5;
  auto byte = [](double x) { return uint8_t(std::lround((x + 1.0) * 0.5 * 255.0)); };
  std::string up = test::writePng(dir, "up", 1, 1, {byte(0), byte(s), byte(c), 255});
  std::string down = test::writePng(dir, "down", 1, 1, {byte(0), byte(-s), byte(c), 255});
  std::vector<test::QuadSpec> quads = {{{-1, -1, 0}, {2, 0, 0}, {0, 2, 0}, 1},      // the plane
                                       {{-5, 2, 0.2f}, {10, 0, 0}, {0, 0, 3}, 0}};  // emitter, facing -y
  auto scene = [&](const std::string& png, const std::string& name) {
    std::string plane = R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1],"metallicFactor":0},
      "normalTexture":{"index":0},)" +
                        std::string(kNoSpecular) + "}";
    std::string extra = std::string(kSpecularExtension) + R"(,"images":[{"uri":")" + png + R"("}],"textures":[{"source":0}])";
    return test::writeQuadsGltf(dir, name, quads, kEmitter + "," + plane, extra);
  };
  RenderOutcome away = render(scene(up, "up"), {0, 0, 1}, {0, 0, 0}, 20.0f, 32, 1);
  RenderOutcome toward = render(scene(down, "down"), {0, 0, 1}, {0, 0, 0}, 20.0f, 32, 1);
  double a = test::whole(away.film).mean.g, t = test::whole(toward.film).mean.g;
  EXPECT_GT(t, 0.02);
  EXPECT_GT(t, 2.0 * a) << "toward the light " << t << ", away from it " << a;
}

TEST(Unlit, AnUnlitSurfaceShowsItsBaseColour) {
  // KHR_materials_unlit as an emission shader: seen directly, the quad's radiance is its base colour.
  auto dir = test::makeTempDir("unlit");
  std::vector<test::QuadSpec> quads = {{{-2, -2, 0}, {4, 0, 0}, {0, 4, 0}, 0}};
  std::string unlit = R"({"pbrMetallicRoughness":{"baseColorFactor":[0.2,0.4,0.6,1]},"extensions":{"KHR_materials_unlit":{}}})";
  RenderOutcome r = render(test::writeQuadsGltf(dir, "unlit", quads, unlit, R"("extensionsUsed":["KHR_materials_unlit"])"),
                           {0, 0, 3}, {0, 0, 0}, 30.0f, 4);
  test::RegionStats all = test::whole(r.film);
  EXPECT_NEAR(all.mean.r, 0.2, 1e-6);
  EXPECT_NEAR(all.mean.g, 0.4, 1e-6);
  EXPECT_NEAR(all.mean.b, 0.6, 1e-6);
}

// The leaf canopy (scenes/textures/leaves.gltf): 288 alpha-masked cards whose holes every camera, bounce and
// shadow ray must find through the texture pages. Without light sampling (emission found by BSDF sampling
// alone) and in the megakernel (another walk) the image agrees with the default's.
TEST(AlphaCanopy, EstimatorsAndIntegratorsAgreeThroughTheHoles) {
  auto canopy = [](bool nee, Integrator integrator, uint32_t seed, bool withoutTextures = false) {
    RenderOptions o;
    o.scenePath = test::scenePath("textures/leaves.gltf");
    o.width = o.height = 32;
    o.spp = 256;
    o.seed = seed;
    o.estimator.nee = nee;
    o.integrator = integrator;
    o.withoutTextures = withoutTextures;
    o.progress = false;
    return runRender(test::sharedContext(), o);
  };
  RenderOutcome base = canopy(true, Integrator::Wavefront, 11);
  EXPECT_TRUE(base.features.alpha && base.features.textures);
  ASSERT_EQ(base.film.totalNonfinite(), 0u);
  test::RegionStats a = test::whole(base.film);
  EXPECT_GT(a.mean.g, 0.0);
  for (auto [nee, integrator, seed] :
       {std::tuple{false, Integrator::Wavefront, 12u}, std::tuple{true, Integrator::Megakernel, 13u}}) {
    RenderOutcome other = canopy(nee, integrator, seed);
    EXPECT_EQ(other.film.totalNonfinite(), 0u);
    EXPECT_TRUE(test::regionsAgree(a, test::whole(other.film), 5.0)) << "nee " << nee << ", " << toString(integrator);
  }
  // The holes matter: with textures (and so alpha) compiled out the cards are whole and the image is another.
  EXPECT_FALSE(test::regionsAgree(a, test::whole(canopy(true, Integrator::Wavefront, 14, true).film), 5.0));
}
