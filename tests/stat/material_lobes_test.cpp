// The layered glTF BSDF's new lobes (bsdf_gltf.h), run as C++ from the shared headers: rough dielectric
// reflection plus transmission (refracting, from either side, and thin-walled), clearcoat and sheen. Each
// sampler against its pdf by chi-square over the whole sphere, its weights f |cos| / pdf against quadrature of
// f |cos|, white furnaces (energy <= 1; = 1 for lossless smooth glass and a perfect mirror), and reciprocity.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../shaders/shared/bsdf_gltf.h"
#include "../shaders/shared/rng.h"
#include "support/chi2.h"
#include "support/param_name.h"
#include "support/z_test.h"

using namespace vkmc;
using namespace vkmc::gpu;

namespace {
constexpr uint32_t kSamples = 1000000;
constexpr int kChi2Tests = 12 * 2;  // Sidak correction over the chi-square tests of this file

vec3 u3(uint32_t i, uint32_t stream) {
  uint key = pathKey(stream, i, 0u);
  return vec3(randomUnit(key, 0u), randomUnit(key, 1u), randomUnit(key, 2u));
}
vec3 fromTheta(float cosTheta) { return vec3(std::sqrt(1 - cosTheta * cosTheta), 0.0f, cosTheta); }

// Radiance crossing into a medium of relative index eta is scaled by 1 / eta^2; the flux a furnace counts is not.
float fluxScale(const GltfMaterial& m, vec3 wi) { return wi.z < 0.0f && !m.thinWalled ? m.eta * m.eta : 1.0f; }

struct Case {
  std::string name;
  GltfMaterial m;
  float azimuth = 0.0f;  // wo's, off the anisotropy direction (local x) for a stretched lobe
};

GltfMaterial glass(float roughness, float eta, vec3 tint = vec3(1.0f)) {
  GltfMaterial m = makeGltfMaterial(tint, 0.0f, roughness, 1.0f);
  setTransmission(m, 1.0f, eta, false);
  return m;
}

std::vector<Case> roughCases() {
  std::vector<Case> c;
  c.push_back({"rough glass entering", glass(0.3f, 1.5f)});
  c.push_back({"rough glass leaving", glass(0.5f, 1.0f / 1.5f)});
  GltfMaterial thin = makeGltfMaterial(vec3(0.9f, 0.6f, 0.3f), 0.0f, 0.4f, 1.0f);
  setTransmission(thin, 0.7f, 1.0f, true);
  c.push_back({"thin-walled partial transmission", thin});
  GltfMaterial coat = makeGltfMaterial(vec3(0.8f, 0.2f, 0.1f), 0.3f, 0.6f, 1.0f);
  setClearcoat(coat, 1.0f, 0.3f, vec3(0.0f, 0.0f, 1.0f));
  c.push_back({"clearcoat over metal-dielectric", coat});
  GltfMaterial tilted = makeGltfMaterial(vec3(0.5f), 0.0f, 0.8f, 1.0f);
  setClearcoat(tilted, 0.7f, 0.2f, normalize(vec3(0.3f, 0.1f, 1.0f)));
  c.push_back({"clearcoat with its own normal", tilted});
  GltfMaterial sheen = makeGltfMaterial(vec3(0.2f, 0.3f, 0.8f), 0.0f, 0.7f, 1.0f);
  setSheen(sheen, vec3(1.0f, 0.3f, 0.1f), 0.5f);
  c.push_back({"sheen over a dielectric", sheen});
  GltfMaterial all = glass(0.4f, 1.3f, vec3(0.9f, 0.8f, 0.7f));
  setIor(all, 1.3f, vec3(1.0f, 0.5f, 0.5f));
  setClearcoat(all, 0.5f, 0.25f, vec3(0.0f, 0.0f, 1.0f));
  setSheen(all, vec3(0.3f), 0.3f);
  c.push_back({"glass with coat, sheen and specular colour", all});
  // A thin film over half metal, half dielectric: it changes the Fresnel terms, so the lobes' probabilities, the
  // reflect-or-transmit choice and the diffuse weight with them.
  GltfMaterial film = makeGltfMaterial(vec3(0.9f, 0.7f, 0.3f), 0.5f, 0.35f, 1.0f);
  setTransmission(film, 0.4f, 1.0f, true);
  setIridescence(film, 1.0f, 1.8f, 450.0f);
  c.push_back({"iridescent film over metal, dielectric and thin transmission", film});
  // KHR_materials_anisotropy: the lobe stretched along local x, seen from an azimuth off both axes.
  GltfMaterial brushed = makeGltfMaterial(vec3(0.9f, 0.7f, 0.5f), 1.0f, 0.3f, 1.0f);
  setAnisotropy(brushed, 0.8f);
  c.push_back({"anisotropic metal", brushed, 0.7f});
  GltfMaterial stretched = glass(0.3f, 1.5f);
  setAnisotropy(stretched, 0.6f);
  setClearcoat(stretched, 0.5f, 0.2f, vec3(0.0f, 0.0f, 1.0f));
  c.push_back({"anisotropic rough glass under a coat", stretched, 1.1f});
  return c;
}

class RoughLobes : public ::testing::TestWithParam<std::tuple<int, float>> {};
}  // namespace

TEST_P(RoughLobes, SamplingMatchesPdfAndEvalAndConservesEnergy) {
  const auto [index, cosO] = GetParam();
  const Case c = roughCases()[size_t(index)];
  const GltfMaterial m = c.m;
  const float sinO = std::sqrt(1.0f - cosO * cosO);
  vec3 wo(sinO * std::cos(c.azimuth), sinO * std::sin(c.azimuth), cosO);
  std::string what = c.name + ", cos " + std::to_string(cosO);
  auto r = test::chi2Sphere(
      [&](uint32_t i) {
        BsdfSample s = sampleGltfBsdf(m, wo, u3(i, 31));
        return maxComponent(s.weight) > 0.0f ? normalize(s.wi) : vec3(0.0f);
      },
      [&](vec3 wi) { return double(gltfBsdfPdf(m, wo, wi)); }, kSamples);
  EXPECT_GT(r.pValue, test::sidakLevel(kChi2Tests)) << what << ": chi2 " << r.statistic << " dof " << r.dof << "\n" << r.table;
  EXPECT_LE(r.pdfIntegral, 1.0 + 3e-3) << what;
  // Weights: their mean is the directional albedo, which quadrature of f |cos| over the sphere must match; and
  // the flux (radiance scaling undone) must not exceed what arrives.
  double sum = 0, sumSq = 0, flux = 0, fluxSq = 0;
  const uint32_t n = 400000;
  for (uint32_t i = 0; i < n; ++i) {
    BsdfSample s = sampleGltfBsdf(m, wo, u3(i, 32));
    ASSERT_FALSE(s.delta) << what;
    ASSERT_TRUE(std::isfinite(s.weight.x) && std::isfinite(s.weight.y) && std::isfinite(s.weight.z)) << what;
    double w = luminance(s.weight), wf = w * fluxScale(m, s.wi);
    sum += w, sumSq += w * w, flux += wf, fluxSq += wf * wf;
  }
  test::SampleMean albedo = test::sampleMean(sum, sumSq, n), energy = test::sampleMean(flux, fluxSq, n);
  double quad = 0.0;
  const int nt = 512, np = 256;
  for (int t = 0; t < nt; ++t)
    for (int p = 0; p < np; ++p) {
      double theta = (t + 0.5) * kPi / nt, phi = (p + 0.5) * 2 * kPi / np;
      vec3 wi(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      quad += luminance(gltfBsdfEval(m, wo, wi)) * std::abs(wi.z) * std::sin(theta) * (kPi / nt) * (2 * kPi / np);
    }
  EXPECT_TRUE(test::withinSigmas(test::zTest(albedo.mean, quad, albedo.sigma, 5e-3 * quad), 5)) << what;
  EXPECT_TRUE(test::atMostSigmas(test::zTest(energy.mean, 1.0, energy.sigma), 5)) << what << ": more flux out than in";
}

INSTANTIATE_TEST_SUITE_P(Chi2, RoughLobes, ::testing::Combine(::testing::Range(0, 10), ::testing::Values(0.9f, 0.35f)),
                         [](const auto& info) {
                           return test::paramName(roughCases()[size_t(std::get<0>(info.param))].name + " cos " +
                                                  test::shortNumber(std::get<1>(info.param)));
                         });

// Lossless smooth glass (white, specularFactor 1) and a white perfect mirror: every sample carries its whole
// flux, exactly, from either side and at every angle, total internal reflection included.
TEST(DeltaLobes, LosslessGlassAndMirrorKeepEveryPhoton) {
  GltfMaterial mirror = makeGltfMaterial(vec3(1.0f), 1.0f, 0.0f, 1.0f);
  for (float eta : {1.5f, 1.0f / 1.5f, 2.4f})
    for (float cosO : {1.0f, 0.8f, 0.5f, 0.2f, 0.02f}) {
      GltfMaterial g = glass(0.0f, eta);
      vec3 wo = fromTheta(cosO);
      int refracted = 0;
      for (uint32_t i = 0; i < 2000; ++i) {
        BsdfSample s = sampleGltfBsdf(g, wo, u3(i, 33));
        ASSERT_TRUE(s.delta);
        refracted += s.wi.z < 0.0f;
        EXPECT_NEAR(s.weight.x * fluxScale(g, s.wi), 1.0f, 1e-5f) << "eta " << eta << " cos " << cosO;
        EXPECT_NEAR(length(s.wi), 1.0f, 1e-5f);
        if (s.wi.z < 0.0f) {
          EXPECT_NEAR(std::sqrt(1 - s.wi.z * s.wi.z), std::sqrt(1 - cosO * cosO) / eta, 1e-5f);
        }  // Snell
        BsdfSample r = sampleGltfBsdf(mirror, wo, u3(i, 34));
        EXPECT_NEAR(r.weight.x, 1.0f, 1e-6f);
        EXPECT_NEAR(r.wi.z, cosO, 1e-6f);
      }
      float sin2T = (1 - cosO * cosO) / (eta * eta);
      if (sin2T >= 1.0f)
        EXPECT_EQ(refracted, 0) << "total internal reflection, eta " << eta << " cos " << cosO;
      else
        EXPECT_GT(refracted, 0) << "eta " << eta << " cos " << cosO;
      EXPECT_EQ(luminance(gltfBsdfEval(g, wo, vec3(0.1f, 0.2f, -0.97f))), 0.0f) << "a delta lobe is never evaluated";
      EXPECT_EQ(gltfBsdfPdf(g, wo, vec3(-wo.x, -wo.y, wo.z)), 0.0f);
    }
}

// Delta reflection over a diffuse base: the diffuse is weighted by Fresnel in and out, so white stays <= 1 at
// every angle (the spec's (1 - F(v.h)) weighting would reach ~1.4 at grazing angles under a smooth interface).
TEST(DeltaLobes, SmoothDielectricOverWhiteDiffuseConservesEnergy) {
  GltfMaterial m = makeGltfMaterial(vec3(1.0f), 0.0f, 0.0f, 1.0f);
  GltfMaterial coated = makeGltfMaterial(vec3(1.0f), 0.0f, 1.0f, 0.0f);
  setClearcoat(coated, 1.0f, 0.0f, vec3(0.0f, 0.0f, 1.0f));
  GltfMaterial sheen = makeGltfMaterial(vec3(1.0f), 0.0f, 1.0f, 0.0f);
  setSheen(sheen, vec3(1.0f), 0.3f);
  for (const GltfMaterial& mat : {m, coated, sheen})
    for (float cosO : {1.0f, 0.5f, 0.15f, 0.02f}) {
      vec3 wo = fromTheta(cosO);
      double sum = 0, sumSq = 0;
      const uint32_t n = 200000;
      for (uint32_t i = 0; i < n; ++i) {
        double w = luminance(sampleGltfBsdf(mat, wo, u3(i, 35)).weight);
        sum += w, sumSq += w * w;
      }
      test::SampleMean e = test::sampleMean(sum, sumSq, n);
      EXPECT_TRUE(test::atMostSigmas(test::zTest(e.mean, 1.0, e.sigma), 5)) << "cos " << cosO << " mean " << e.mean;
      EXPECT_GT(e.mean, 0.5) << "cos " << cosO;  // and it is not losing most of it either
    }
}

// A smooth base stretched along one axis (roughness 0, strength 0.8): rough along x, alpha clamped to 1e-4 across it
// (alpha 0 divided by zero: every sample NaN). Its samples and their weights and pdfs stay finite.
TEST(Anisotropy, ASmoothBaseStretchedAlongOneAxisIsFinite) {
  GltfMaterial m = makeGltfMaterial(vec3(0.9f), 1.0f, 0.0f, 1.0f);
  setAnisotropy(m, 0.8f);
  ASSERT_FALSE(isDeltaAlpha(m.alpha));
  for (float cosO : {0.9f, 0.4f})
    for (uint32_t i = 0; i < 20000; ++i) {
      const float sinO = std::sqrt(1.0f - cosO * cosO);
      vec3 wo(sinO * std::cos(0.5f), sinO * std::sin(0.5f), cosO);
      BsdfSample s = sampleGltfBsdf(m, wo, u3(i, 38));
      ASSERT_TRUE(std::isfinite(s.weight.x) && std::isfinite(s.pdf)) << "cos " << cosO << " sample " << i;
    }
}

// f(wo, wi) = f(wi, wo) for reflection; for refraction the generalized reciprocity of radiance,
// f(wo, wi) / n_o^2 = f(wi, wo) / n_i^2: with wo outside and wi inside glass of index eta, f(wo, wi) eta^2 = f(wi, wo).
TEST(Reciprocity, ReflectionAndRefraction) {
  GltfMaterial layered = makeGltfMaterial(vec3(0.7f, 0.5f, 0.3f), 0.2f, 0.5f, 1.0f);
  setClearcoat(layered, 0.8f, 0.3f, vec3(0.0f, 0.0f, 1.0f));
  setSheen(layered, vec3(0.5f, 0.2f, 0.9f), 0.4f);
  GltfMaterial brushed = makeGltfMaterial(vec3(0.8f, 0.6f, 0.4f), 0.6f, 0.4f, 1.0f);
  setAnisotropy(brushed, 0.7f);
  for (uint32_t i = 0; i < 2000; ++i) {
    vec3 a = u3(i, 36), b = u3(i, 37);
    vec3 wo = sampleCosineHemisphere(vec2(a.x, a.y)), wi = sampleCosineHemisphere(vec2(b.x, b.y));
    vec3 f1 = gltfBsdfEval(layered, wo, wi), f2 = gltfBsdfEval(layered, wi, wo);
    EXPECT_NEAR(f1.x, f2.x, 1e-4f * (1 + f1.x));
    EXPECT_NEAR(f1.z, f2.z, 1e-4f * (1 + f1.z));
    vec3 g1 = gltfBsdfEval(brushed, wo, wi), g2 = gltfBsdfEval(brushed, wi, wo);
    EXPECT_NEAR(g1.y, g2.y, 1e-4f * (1 + g1.y)) << "anisotropic";
    GltfMaterial in = glass(0.4f, 1.5f), out = glass(0.4f, 1.0f / 1.5f);
    vec3 wt = vec3(wi.x, wi.y, -wi.z);  // below
    float t1 = gltfBsdfEval(in, wo, wt).x * 1.5f * 1.5f;
    float t2 = gltfBsdfEval(out, -wt, -wo).x;
    EXPECT_NEAR(t1, t2, 2e-3f * (1 + t1)) << "wo " << wo.z << " wi " << wt.z;
  }
}
