// Stiff case 5: near-specular and very rough GGX at grazing angles. Every eval, pdf and sample stays finite,
// and the white-furnace energy of a perfect metal (F0 = 1) never exceeds 1. Rows go to the stability table.
#include <gtest/gtest.h>

#include "../shaders/shared/bsdf_gltf.h"
#include "../shaders/shared/rng.h"
#include "support/param_name.h"
#include "support/stability_row.h"
#include "support/z_test.h"

using namespace vkmc::gpu;

namespace {
bool finite3(vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// One row per (roughness, cosine of the outgoing angle).
class StiffBsdf : public ::testing::TestWithParam<std::tuple<float, float>> {};
}  // namespace

TEST_P(StiffBsdf, ExtremeRoughnessAndGrazingAnglesStayFiniteAndEnergyConserving) {
  const auto [roughness, cosO] = GetParam();
  GltfMaterial m = makeGltfMaterial(vec3(1.0f), 1.0f, roughness, 1.0f);  // white metal: F0 = 1
  vec3 wo(std::sqrt(1.0f - cosO * cosO), 0.0f, cosO);
  const uint32_t n = 200000;
  double sum = 0, sumSq = 0;
  int nonfinite = 0;
  for (uint32_t i = 0; i < n; ++i) {
    uint key = pathKey(17u, i, 0u);
    // Roughness below sqrt(kDeltaAlpha) is a delta lobe: its samples carry their weight, with no pdf or eval.
    BsdfSample s = sampleGltfBsdf(m, wo, vec3(randomUnit(key, 0), randomUnit(key, 1), randomUnit(key, 2)));
    if (!finite3(s.wi) || !std::isfinite(s.pdf) || !finite3(s.weight)) {
      ++nonfinite;
      continue;
    }
    double w = s.wi.z > 0.0f ? s.weight.x : 0.0;
    if (!std::isfinite(w))
      ++nonfinite;
    else
      sum += w, sumSq += w * w;
  }
  vkmc::test::SampleMean albedo = vkmc::test::sampleMean(sum, sumSq, n);
  vkmc::test::ZTest energy = vkmc::test::zTest(albedo.mean, 1.0, albedo.sigma);
  std::string what = "roughness " + std::to_string(roughness) + ", cos " + std::to_string(cosO);
  EXPECT_EQ(nonfinite, 0) << what;
  EXPECT_TRUE(vkmc::test::atMostSigmas(energy, 5.0)) << what;
  vkmc::test::stabilityRow("5", "GGX metal F0=1, " + what, "albedo <= 1, finite", albedo.mean, albedo.sigma,
                           nonfinite == 0 && energy.atMost(5.0));
}

INSTANTIATE_TEST_SUITE_P(Stiff, StiffBsdf,
                         ::testing::Combine(::testing::Values(1e-3f, 0.01f, 0.3f, 1.0f),
                                            ::testing::Values(1.0f, 0.5f, 1e-2f, 1e-4f, 1e-6f)),
                         [](const auto& info) {
                           return vkmc::test::paramName("roughness " + vkmc::test::shortNumber(std::get<0>(info.param)) +
                                                        " cos " + vkmc::test::shortNumber(std::get<1>(info.param)));
                         });
