// Delta lobes and transmission through every estimator (scenes/materials, made by tools/make_scenes.py):
// lossless smooth glass and a perfect mirror inside a closed emitter of radiance 1 give L = 1 at every pixel
// (Fresnel splits, total internal reflection and the eta^2 scaling in and out cancel); and light reachable only
// through glass is counted once, whatever the mix of light sampling, MIS and BSDF sampling.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "app/render_job.h"
#include "support/param_name.h"
#include "support/render_helpers.h"
#include "support/test_scenes.h"
#include "support/z_test.h"

using namespace vkmc;
using namespace vkmc::test;

namespace {
struct Variant {
  std::string name;
  EstimatorConfig e;
  Integrator integrator = Integrator::Wavefront;
};

std::vector<Variant> variants() {
  std::vector<Variant> v;
  v.push_back({"default", EstimatorConfig{}});
  EstimatorConfig e;
  e.nee = false;
  v.push_back({"no light sampling", e});
  e = EstimatorConfig{};
  e.mis = MisHeuristic::None;
  v.push_back({"light sampling without MIS", e});
  e = EstimatorConfig{};
  e.bsdfSampling = BsdfSampling::Cosine;
  v.push_back({"cosine continuation", e});
  e = EstimatorConfig{};
  e.rr = RouletteMode::Fixed;
  e.rrQ = 0.2f;
  e.rrDepth = 2;
  v.push_back({"fixed roulette", e});
  e = EstimatorConfig{};
  e.bsdfSamples = 3.0f;
  e.lightSamples = 2;
  e.splitDepth = 2;
  v.push_back({"splitting", e});
  v.push_back({"megakernel", EstimatorConfig{}, Integrator::Megakernel});
  e = EstimatorConfig{};
  e.mis = MisHeuristic::Balance;
  e.lightSampling = LightSampling::SolidAngle;
  v.push_back({"balance heuristic, solid-angle lights", e});
  e = EstimatorConfig{};
  e.bsdfSampling = BsdfSampling::Uniform;
  e.rr = RouletteMode::Efficiency;
  v.push_back({"uniform continuation, efficiency roulette", e});
  e = EstimatorConfig{};
  e.shadowRrThreshold = 0.5f;
  e.cameraRrQ = 0.3f;
  v.push_back({"shadow and camera roulette", e});
  return v;
}

RenderOutcome render(const std::string& scene, const Variant& v, uint32_t w, uint32_t h, uint32_t spp) {
  RenderOptions o;
  o.scenePath = scenePath(scene);
  o.width = w;
  o.height = h;
  o.spp = spp;
  o.seed = 99;
  o.estimator = v.e;
  // 4 replicates: the per-pixel check below needs more than the 1 degree of freedom of the default 2 (whose two
  // replicate means can agree exactly in a pixel of discrete values, a variance estimate of 0).
  o.estimator.replicates = 4;
  o.integrator = v.integrator;
  o.progress = false;
  return runRender(sharedContext(), o);
}

class MaterialFurnace : public ::testing::TestWithParam<std::tuple<std::string, int>> {};
}  // namespace

TEST_P(MaterialFurnace, RadianceIsOneEverywhere) {
  const auto& [scene, index] = GetParam();
  const Variant v = variants()[size_t(index)];
  RenderOutcome r = render("materials/" + scene + ".gltf", v, 24, 24, 16);
  const Film& f = r.film;
  EXPECT_EQ(f.totalNonfinite(), 0u) << v.name;
  EXPECT_TRUE(r.features.delta) << v.name;
  // Whole-image mean against 1 at 5 sigma of its measured variance; 1e-4 of slack for the mirror, whose every
  // sample is exactly 1 (zero variance), and the float rounding of a long chain of Fresnel splits.
  glm::dvec3 mean = f.imageMean(), var = f.imageMeanVarianceOfMean();
  for (int c = 0; c < 3; ++c)
    EXPECT_TRUE(withinSigmas(zTest(mean[c], 1.0, std::sqrt(var[c] / f.pixels()), 1e-4), 5.0)) << v.name << " channel " << c;
  // And no pixel far off: each within 5 sigma of its own variance (plus the same slack). Not under fixed or camera
  // roulette, whose 16 skewed, discrete samples per pixel give no usable per-pixel interval (the image mean has one).
  if (v.e.rr == RouletteMode::Fixed || v.e.cameraRrQ > 0.0f) return;
  int outside = 0;
  for (size_t p = 0; p < f.pixels(); ++p)
    outside += !withinSigmas(zTest(f.mean(p, 1), 1.0, std::sqrt(f.varianceOfMean(p, 1)), 1e-4), 5.0);
  EXPECT_LE(outside, 1) << v.name << ": pixels off 1";
}

INSTANTIATE_TEST_SUITE_P(Materials, MaterialFurnace,
                         ::testing::Combine(::testing::Values("glass_furnace", "mirror_furnace"), ::testing::Range(0, 10)),
                         [](const auto& info) {
                           return paramName(std::get<0>(info.param) + " " + variants()[size_t(std::get<1>(info.param))].name);
                         });

// A filament inside a thin-walled glass bulb and a caustic under a glass sphere: light sampling cannot see the
// emitter through the delta transmission, so what arrives through glass comes from BSDF sampling with full
// weight. With and without light sampling, with and without MIS, the images agree.
TEST(ThroughGlass, EmittersBehindGlassAreCountedOnce) {
  for (const char* scene : {"materials/glass_bulb.gltf", "materials/caustic.gltf"}) {
    std::vector<Variant> vs = variants();
    RenderOutcome base = render(scene, vs[0], 24, 18, 256);
    ASSERT_EQ(base.film.totalNonfinite(), 0u) << scene;
    RegionStats a = whole(base.film);
    for (int i : {1, 2}) {
      RenderOutcome other = render(scene, vs[size_t(i)], 24, 18, 256);
      EXPECT_EQ(other.film.totalNonfinite(), 0u) << scene;
      EXPECT_TRUE(regionsAgree(a, whole(other.film), 5.0)) << scene << ": default vs " << vs[size_t(i)].name;
    }
    EXPECT_GT(a.mean.x, 0.0) << scene << ": light reaches the floor";
  }
}

// A rough glass volume of ior exactly 1 (index-matched) is invisible: light passes straight through whatever its
// roughness, so the glass furnace reads 1. Walter's btdf has no half vector at eta 1 (every refraction gives
// wi = -wo): it gave non-finite samples (195 at 480 px), then, at ior 1 + 1e-4, lost 2% of the light at roughness
// 0.3 and 29% at roughness 1.
TEST(IndexMatchedVolume, RoughIorOneIsInvisibleInTheGlassFurnace) {
  const std::string text = [] {
    std::ifstream in(scenePath("materials/glass_furnace.gltf"));
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }();
  for (const std::string roughness : {"0.3", "1.0"}) {
    std::string s = text;
    for (auto [from, to] : {std::pair{std::string("\"ior\": 1.5"), std::string("\"ior\": 1.0")},
                            std::pair{std::string("\"roughnessFactor\": 0.0"), "\"roughnessFactor\": " + roughness}}) {
      const size_t at = s.find(from);
      ASSERT_NE(at, std::string::npos) << from;
      s.replace(at, from.size(), to);
    }
    const auto path = test::makeTempDir("index_matched") / ("rough" + roughness + ".gltf");
    std::ofstream(path) << s;
    RenderOptions o = optionsFor("", EstimatorConfig{}, 16, 16, 256);
    o.scenePath = path.string();
    const RenderOutcome r = runRender(sharedContext(), o);
    EXPECT_EQ(r.film.totalNonfinite(), 0u) << roughness;
    const glm::dvec3 mean = r.film.imageMean(), var = r.film.imageMeanVarianceOfMean();
    EXPECT_TRUE(withinSigmas(zTest(mean.y, 1.0, std::sqrt(var.y / r.film.pixels()), 1e-4), 5.0))
        << "roughness " << roughness << ": " << mean.y;
  }
}

// KHR_materials_anisotropy through the kernels: a brushed metal plate (its texture coordinates' u along x, so its
// generated tangent is +x) reflects a small light above the camera. The highlight stretches along the anisotropy
// direction: along x with anisotropyRotation 0, along y with pi/2 (the brightness's second moments about the
// highlight's centre, x against y); and light sampling alone and BSDF sampling alone agree on the image mean.
namespace {
RenderOutcome brushedPlate(float rotation, const EstimatorConfig& e, const std::string& roughness = "0.3") {
  const auto dir = test::makeTempDir("brushed_plate");
  const std::string name = "brushed" + std::to_string(int(rotation * 100));
  const std::string materials =
      R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1],"metallicFactor":1,"roughnessFactor":)" + roughness +
      "},"
      R"("extensions":{"KHR_materials_anisotropy":{"anisotropyStrength":0.9,"anisotropyRotation":)" +
      std::to_string(rotation) + "}}}," + R"({"pbrMetallicRoughness":{"baseColorFactor":[0,0,0,1]},"emissiveFactor":[1,1,1],)" +
      R"("extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":20}}})";
  const std::string scene = test::writeQuadsGltf(
      dir, name, {{{-2, -2, 0}, {4, 0, 0}, {0, 4, 0}, 0}, {{-0.1f, -0.1f, 2.5f}, {0, 0.2f, 0}, {0.2f, 0, 0}, 1}}, materials,
      R"("extensionsUsed":["KHR_materials_anisotropy","KHR_materials_emissive_strength"])");
  RenderOptions o = optionsFor("", e, 48, 48, 64, 71);
  o.scenePath = scene;
  o.lookFrom = glm::vec3(0.0f, 0.0f, 3.0f);
  o.lookAt = glm::vec3(0.0f);
  o.fovDegrees = 50.0f;
  return runRender(sharedContext(), o);
}

// The brightness's second moments about its centroid, in image coordinates (x right, y down): var x, var y, cov.
glm::dvec3 brightnessMoments(const Film& f) {
  double w = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
  for (uint32_t y = 0; y < f.height; ++y)
    for (uint32_t x = 0; x < f.width; ++x) {
      double v = f.mean(y * f.width + x, 1);
      w += v, sx += v * x, sy += v * y, sxx += v * x * x, syy += v * y * y, sxy += v * x * y;
    }
  double mx = sx / w, my = sy / w;
  return {sxx / w - mx * mx, syy / w - my * my, sxy / w - mx * my};
}
double stretchXOverY(const Film& f) {
  const glm::dvec3 m = brightnessMoments(f);
  return m.x / m.y;
}
// The correlation of x and y under the brightness: positive along the image's main diagonal (right and down).
double diagonalStretch(const Film& f) {
  const glm::dvec3 m = brightnessMoments(f);
  return m.z / std::sqrt(m.x * m.y);
}
}  // namespace

TEST(Anisotropy, TheHighlightStretchesAlongTheRotatedDirection) {
  const RenderOutcome along = brushedPlate(0.0f, EstimatorConfig{});
  const RenderOutcome across = brushedPlate(1.5707963f, EstimatorConfig{});
  ASSERT_TRUE(along.features.anisotropy);
  EXPECT_EQ(along.film.totalNonfinite() + across.film.totalNonfinite(), 0u);
  const double a = stretchXOverY(along.film), c = stretchXOverY(across.film);
  EXPECT_GT(a, 2.0) << "rotation 0: stretched along x (the tangent)";
  EXPECT_LT(c, 0.5) << "rotation pi/2: stretched along y (the bitangent)";
  // The sense of the rotation: counter-clockwise from the tangent (+x) toward the bitangent. The plate's v runs up
  // the world's +y, so its image's +v, and with it glTF's bitangent (a normal map's green, up the image), is world
  // -y: pi/4 is along (x, -y) in the world, right and down the picture.
  EXPECT_GT(diagonalStretch(brushedPlate(0.7853982f, EstimatorConfig{}).film), 0.5);
  EXPECT_LT(diagonalStretch(brushedPlate(-0.7853982f, EstimatorConfig{}).film), -0.5);
}

// A smooth base stretched along one axis (Khronos' AnisotropyDiscTest: roughness 0, strength 1): rough along the
// direction, alpha 1e-4 across it, and no non-finite sample (alpha 0 across divided by zero).
TEST(Anisotropy, ASmoothBaseStretchedAlongOneAxisStaysFinite) {
  const RenderOutcome r = brushedPlate(0.3f, EstimatorConfig{}, "0.0");
  EXPECT_EQ(r.film.totalNonfinite(), 0u);
  EXPECT_GT(stretchXOverY(r.film), 2.0);
}

TEST(Anisotropy, LightSamplingAndBsdfSamplingAgree) {
  EstimatorConfig lightOnly;
  lightOnly.mis = MisHeuristic::None;
  EstimatorConfig bsdfOnly;
  bsdfOnly.nee = false;
  const RenderOutcome a = brushedPlate(0.7f, lightOnly), b = brushedPlate(0.7f, bsdfOnly);
  EXPECT_EQ(a.film.totalNonfinite() + b.film.totalNonfinite(), 0u);
  EXPECT_TRUE(regionsAgree(whole(a.film), whole(b.film), 5.0));
  EXPECT_GT(whole(a.film).mean.y, 0.0);
}

// KHR_materials_dispersion through the kernels. Each path past the dispersive glass carries one colour channel,
// chosen with probability 1/3 and weighted 3: the glass furnace (lossless glass at any ior) still reads 1 in every
// channel, smooth or rough. Under the glass sphere of the caustic scene the channels' caustics separate: a white
// light through white glass onto a grey floor gives R = B exactly in every sample without dispersion, and many
// pixels whose R and B differ by more than 5 sigma with it.
// (Light sampling through the dispersive glass's own lobes is checked on rough glass below.)
namespace {
std::string withDispersion(const std::string& scene, const std::string& roughness, const std::string& tag) {
  std::ifstream in(scenePath(scene));
  nlohmann::json j = nlohmann::json::parse(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()));
  for (auto& m : j["materials"])
    if (m["name"] == "glass") {
      m["extensions"]["KHR_materials_dispersion"] = {{"dispersion", 5.0}};
      m["pbrMetallicRoughness"]["roughnessFactor"] = std::stod(roughness);
    }
  j["extensionsUsed"].push_back("KHR_materials_dispersion");
  const auto path = test::makeTempDir("dispersion") / (tag + ".gltf");
  for (const auto& b : j["buffers"])
    if (b.contains("uri") && b["uri"].get<std::string>().rfind("data:", 0) != 0)
      std::filesystem::copy_file(std::filesystem::path(scenePath(scene)).parent_path() / b["uri"].get<std::string>(),
                                 path.parent_path() / b["uri"].get<std::string>());
  std::ofstream(path) << j.dump();
  return path.string();
}
}  // namespace

TEST(Dispersion, TheGlassFurnaceStaysOneInEveryChannel) {
  // The wavefront, the megakernel (its own call of takeSpectralChannel), and rr ears, whose copies inherit the
  // channel from the vertex they split at (ears_copies.comp).
  EstimatorConfig ears;
  ears.rr = RouletteMode::Ears;
  ears.earsFallback = EarsFallback::Never;
  const std::vector<Variant> runs = {
      {"wavefront", EstimatorConfig{}}, {"megakernel", EstimatorConfig{}, Integrator::Megakernel}, {"rr ears", ears}};
  const std::string scene = withDispersion("materials/glass_furnace.gltf", "0.0", "furnace");
  for (const Variant& v : runs) {
    RenderOptions o = optionsFor("", v.e, 16, 16, 256, 73);
    o.scenePath = scene;
    o.integrator = v.integrator;
    const RenderOutcome r = runRender(sharedContext(), o);
    ASSERT_TRUE(r.features.dispersion);
    EXPECT_EQ(r.film.totalNonfinite(), 0u) << v.name;
    const glm::dvec3 mean = r.film.imageMean(), var = r.film.imageMeanVarianceOfMean();
    for (int c = 0; c < 3; ++c)
      EXPECT_TRUE(withinSigmas(zTest(mean[c], 1.0, std::sqrt(var[c] / r.film.pixels()), 1e-4), 5.0))
          << v.name << " channel " << c << ": " << mean[c];
  }
}

// Rough dispersive glass (not lossless: single-scattering GGX loses a few percent, so no furnace): light sampling
// evaluates its lobes at the channel's ior, BSDF sampling samples them there; with and without light sampling the
// caustic scene's image agrees.
TEST(Dispersion, RoughDispersiveGlassAgreesWithAndWithoutLightSampling) {
  const std::string scene = withDispersion("materials/caustic.gltf", "0.3", "rough_caustic");
  EstimatorConfig bsdfOnly;
  bsdfOnly.nee = false;
  RegionStats stats[2];
  for (int i = 0; i < 2; ++i) {
    RenderOptions o = optionsFor("", i == 0 ? EstimatorConfig{} : bsdfOnly, 24, 18, 256, 83 + i);
    o.scenePath = scene;
    const RenderOutcome r = runRender(sharedContext(), o);
    EXPECT_EQ(r.film.totalNonfinite(), 0u);
    stats[i] = whole(r.film);
  }
  EXPECT_TRUE(regionsAgree(stats[0], stats[1], 5.0));
}

TEST(Dispersion, TheCausticSeparatesIntoItsColours) {
  auto separated = [](const std::string& path) {
    RenderOptions o = optionsFor("", EstimatorConfig{}, 48, 36, 512, 79);
    o.scenePath = path;
    const RenderOutcome r = runRender(sharedContext(), o);
    EXPECT_EQ(r.film.totalNonfinite(), 0u);
    int pixels = 0;
    for (size_t p = 0; p < r.film.pixels(); ++p) {
      double d = r.film.mean(p, 0) - r.film.mean(p, 2), v = r.film.varianceOfMean(p, 0) + r.film.varianceOfMean(p, 2);
      pixels += v > 0.0 ? std::abs(d) > 5.0 * std::sqrt(v) : d != 0.0;
    }
    return pixels;
  };
  EXPECT_EQ(separated(scenePath("materials/caustic.gltf")), 0) << "no dispersion: R = B in every sample";
  EXPECT_GT(separated(withDispersion("materials/caustic.gltf", "0.0", "caustic")), 20);
}
