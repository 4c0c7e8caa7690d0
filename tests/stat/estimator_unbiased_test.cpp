// Every roulette mode, splitting setting, sampling technique and MIS heuristic is unbiased: on the white
// furnace its image mean and four quadrants match L = 2 exactly, and on the Cornell box it matches the baseline
// estimator (power-heuristic MIS, BSDF sampling, throughput roulette), by z-tests at 5 sigma sized from the
// measured variances. Fixed seeds make them stable; the two renders use independent seeds.
// Sized by samples, not seconds. The biases they catch are the estimators' classic slips, each many sigmas at these
// counts: a roulette or splitting weight without its 1/(1 - q), 1/q or 1/K (tens of percent of L), a MIS pair whose
// weights do not sum to one (a light or a plate counted twice or not at all), a light pdf in the wrong measure
// (area against solid angle: off by cos/r^2 across the image), a shadow-ray or camera-ray roulette that drops what
// it terminates, and a stiff furnace whose paths end early (the last two tests resolve 2.5% of L = 100).
#include <gtest/gtest.h>

#include "support/param_name.h"
#include "support/render_helpers.h"

using namespace vkmc;
using namespace vkmc::test;

namespace {

struct Variant {
  const char* name;
  EstimatorConfig config;
};
void PrintTo(const Variant& v, std::ostream* os) { *os << v.name; }

std::vector<Variant> variants() {
  std::vector<Variant> v;
  auto add = [&](const char* name, auto edit) {
    EstimatorConfig c;
    edit(c);
    v.push_back({name, c});
  };
  add("baseline", [](EstimatorConfig&) {});
  add("rr fixed q=0.5", [](EstimatorConfig& c) {
    c.rr = RouletteMode::Fixed;
    c.rrQ = 0.5f;
    c.rrDepth = 1;
  });
  add("rr fixed q=0.7 c=0.3", [](EstimatorConfig& c) {
    c.rr = RouletteMode::Fixed;
    c.rrQ = 0.7f;
    c.rrC = 0.3f;
    c.rrDepth = 1;
  });
  add("rr throughput from 1", [](EstimatorConfig& c) { c.rrDepth = 1; });
  add("rr efficiency", [](EstimatorConfig& c) { c.rr = RouletteMode::Efficiency; });
  add("rr ears", [](EstimatorConfig& c) {
    c.rr = RouletteMode::Ears;
    c.earsFallback = EarsFallback::Never;
  });
  add("rr ears, learned roulette alone", [](EstimatorConfig& c) {
    c.rr = RouletteMode::Ears;
    c.earsMax = 1.0f;
    c.earsFallback = EarsFallback::Never;
  });
  add("rr ears, learned light samples", [](EstimatorConfig& c) {
    c.rr = RouletteMode::Ears;
    c.earsLightMax = gpu::kEarsLightFactorMax;
    c.earsFallback = EarsFallback::Never;
  });
  add("rr ears, fallen back to throughput roulette", [](EstimatorConfig& c) {
    c.rr = RouletteMode::Ears;
    c.earsFallback = EarsFallback::Always;
  });
  // The fallback's shadow stage adds a path's several light samples with float atomics (render_kernels.cpp).
  add("rr ears, fallen back, 3 light samples", [](EstimatorConfig& c) {
    c.rr = RouletteMode::Ears;
    c.earsFallback = EarsFallback::Always;
    c.lightSamples = 3;
  });
  add("light samples 4", [](EstimatorConfig& c) { c.lightSamples = 4; });
  add("light samples 3, split depth 3", [](EstimatorConfig& c) {
    c.lightSamples = 3;
    c.splitDepth = 3;
  });
  add("bsdf samples 4", [](EstimatorConfig& c) { c.bsdfSamples = 4.0f; });
  add("bsdf samples 2.5 to depth 2, 2 light samples", [](EstimatorConfig& c) {
    c.bsdfSamples = 2.5f;
    c.splitDepth = 2;
    c.lightSamples = 2;
  });
  add("bsdf uniform", [](EstimatorConfig& c) { c.bsdfSampling = BsdfSampling::Uniform; });
  add("bsdf cosine", [](EstimatorConfig& c) { c.bsdfSampling = BsdfSampling::Cosine; });
  add("solid-angle lights", [](EstimatorConfig& c) { c.lightSampling = LightSampling::SolidAngle; });
  add("uniform light selection", [](EstimatorConfig& c) { c.lightSelect = LightSelect::Uniform; });
  add("mis none", [](EstimatorConfig& c) { c.mis = MisHeuristic::None; });
  add("mis balance", [](EstimatorConfig& c) { c.mis = MisHeuristic::Balance; });
  add("nee off", [](EstimatorConfig& c) { c.nee = false; });
  add("camera rr 0.5", [](EstimatorConfig& c) { c.cameraRrQ = 0.5f; });
  add("shadow rr 0.5", [](EstimatorConfig& c) {
    c.shadowRrThreshold = 0.5f;
    c.shadowRrQ = 0.5f;
  });
  return v;
}

void expectSame(const Film& f, const Film& ref, const std::string& what) {
  EXPECT_TRUE(regionsAgree(whole(f), whole(ref), 5.0)) << what << ": image mean";
  uint32_t w = f.width / 2, h = f.height / 2;
  for (uint32_t qy = 0; qy < 2; ++qy)
    for (uint32_t qx = 0; qx < 2; ++qx)
      EXPECT_TRUE(regionsAgree(region(f, qx * w, qy * h, qx * w + w, qy * h + h),
                               region(ref, qx * w, qy * h, qx * w + w, qy * h + h), 5.0))
          << what << ": quadrant " << qx << "," << qy;
}

// The variants whose techniques differ on glossy plates: MIS, NEE, BSDF sampling and solid-angle lights.
std::vector<Variant> glossyTechniques() {
  std::vector<Variant> v;
  for (const Variant& x : variants()) {
    std::string n = x.name;
    if (n.find("mis") != std::string::npos || n.find("nee") != std::string::npos || n.find("bsdf") != std::string::npos ||
        n.find("solid") != std::string::npos)
      v.push_back(x);
  }
  return v;
}

std::string variantName(const ::testing::TestParamInfo<Variant>& info) { return paramName(info.param.name); }

// The rows below: every variant on the furnace and the Cornell box; those that differ on glossy plates on the
// Veach scene. The baselines are rendered once per process and shared by the rows.
class EstimatorVariant : public ::testing::TestWithParam<Variant> {};
class GlossyTechnique : public ::testing::TestWithParam<Variant> {};

}  // namespace

TEST_P(EstimatorVariant, FurnaceMatchesTheAnalyticValue) {
  const Variant& v = GetParam();
  RenderOutcome r = renderWith("furnace.gltf", v.config, 16, 16, 256);
  ASSERT_EQ(r.film.totalNonfinite(), 0u) << v.name;
  EXPECT_TRUE(regionMatches(whole(r.film), glm::dvec3(2.0), 5.0)) << v.name << ": image mean";
  for (uint32_t q = 0; q < 4; ++q)
    EXPECT_TRUE(regionMatches(region(r.film, (q % 2) * 8, (q / 2) * 8, (q % 2) * 8 + 8, (q / 2) * 8 + 8), glm::dvec3(2.0), 5.0))
        << v.name << ": quadrant " << q;
}

TEST_P(EstimatorVariant, CornellBoxMatchesTheBaseline) {
  static const RenderOutcome ref = renderWith("cornell_box.gltf", EstimatorConfig{}, 32, 32, 512, 999);
  const Variant& v = GetParam();
  RenderOutcome r = renderWith("cornell_box.gltf", v.config, 32, 32, 128);
  ASSERT_EQ(r.film.totalNonfinite(), 0u) << v.name;
  expectSame(r.film, ref.film, v.name);
}

TEST_P(GlossyTechnique, VeachSceneMatchesTheBaselineOnEachPlate) {
  // Glossy plates, where BSDF sampling, light sampling and their combinations differ most. 96 x 64 pixels
  // (rows measured on a render): lights 7-21, plates 28-31 (roughness 0.02), 37-40 (0.1), 45-50 (0.25),
  // 55-60 (0.5).
  struct Band {
    uint32_t y0, y1;
    const char* name;
  };
  const Band bands[] = {
      {7, 22, "lights"}, {55, 61, "plate 0.5"}, {45, 51, "plate 0.25"}, {37, 41, "plate 0.1"}, {28, 32, "plate 0.02"}};
  static const RenderOutcome ref = renderWith("veach_mis.gltf", EstimatorConfig{}, 96, 64, 512, 999);
  const Variant& v = GetParam();
  std::string n = v.name;
  // Where light sampling alone carries a near-specular reflection (no MIS, or MIS against a BSDF technique
  // that ignores the lobe), f cos / p has so heavy a tail that at test sample counts the sample mean is not
  // normal and its variance estimate is far too small: a z-test there is invalid, not failed. (Measured:
  // "mis none" at 4096 spp lands within 1 sigma of the baseline, with sigma 50x the baseline's.) The lecture
  // test on MIS measures exactly that variance.
  bool lightSamplingCarriesSharpLobe = n == "mis none" || n == "bsdf uniform" || n == "bsdf cosine";
  RenderOutcome r = renderWith("veach_mis.gltf", v.config, 96, 64, 256);
  ASSERT_EQ(r.film.totalNonfinite(), 0u) << v.name;
  for (const Band& b : bands) {
    if (lightSamplingCarriesSharpLobe && std::string(b.name) == "plate 0.02") continue;
    EXPECT_TRUE(regionsAgree(region(r.film, 8, b.y0, 88, b.y1), region(ref.film, 8, b.y0, 88, b.y1), 5.0))
        << v.name << ", " << b.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Unbiased, EstimatorVariant, ::testing::ValuesIn(variants()), variantName);
INSTANTIATE_TEST_SUITE_P(Unbiased, GlossyTechnique, ::testing::ValuesIn(glossyTechniques()), variantName);

// EARS on the stiff furnace: a vertex whose copies each reflect 99% of L is split wherever the cache says so; the
// pool bounds the splits (a full pool leaves a vertex as it is) and the mean stays L.
TEST(EstimatorUnbiased, StiffFurnaceWithEars) {
  EstimatorConfig e;
  e.rr = RouletteMode::Ears;
  e.earsFallback = EarsFallback::Never;
  // 64x64 at 12 spp: of its first image pass (8 spp) half are training samples, the other half run on the kernels
  // without the training code (ears.h earsTrainingSamples), deciding with what the first half just taught.
  RenderOutcome r = renderWith("furnace_stiff.gltf", e, 64, 64, 12);
  ASSERT_EQ(r.film.totalNonfinite(), 0u);
  RegionStats s = whole(r.film);
  EXPECT_TRUE(regionMatches(s, glm::dvec3(100.0), 5.0));
  EXPECT_LT(std::sqrt(s.variance.x), 0.5) << "the test must resolve a 2.5% bias";
  ASSERT_TRUE(r.ears);
  EXPECT_GT(r.ears->learningPasses, 0u);
}

// Efficiency roulette on this furnace (8x8, 64 spp, no cap) is stiff_furnace_test's full render, at 5 sigma there.
TEST(EstimatorUnbiased, StiffFurnaceWithThroughputRoulette) {
  // Albedo 0.99, Le = 1: L = 100. Paths run hundreds of bounces; no depth cap.
  RenderOutcome r = renderWith("furnace_stiff.gltf", EstimatorConfig{}, 16, 16, 192);
  ASSERT_EQ(r.film.totalNonfinite(), 0u);
  RegionStats s = whole(r.film);
  EXPECT_TRUE(regionMatches(s, glm::dvec3(100.0), 5.0));
  EXPECT_LT(std::sqrt(s.variance.x), 0.5) << "the test must resolve a 2.5% bias";
}
