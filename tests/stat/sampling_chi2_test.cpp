// Every sampling routine the kernels use, run as C++ from the same shared headers, against its pdf:
// chi-square goodness of fit, pdfs integrating to one, and sample weights (f cos / pdf) whose mean matches the
// quadrature of f cos (the chi-square test alone never looks at eval).
#include <gtest/gtest.h>

#include "../shaders/shared/bsdf_gltf.h"
#include "../shaders/shared/geometry.h"
#include "../shaders/shared/light_sampling.h"
#include "../shaders/shared/rng.h"
#include "../shaders/shared/sampling.h"
#include "scene_layout.h"
#include "support/chi2.h"
#include "support/param_name.h"
#include "support/z_test.h"
#include "render/alias_table.h"

using namespace vkmc;
using namespace vkmc::gpu;
using vkmc::test::chi2Sphere;

namespace {
constexpr uint32_t kSamples = 1000000;
constexpr int kTests = 2 + 15 + 27 + 4 + 1;  // Sidak correction over every chi-square test in this file

vec3 u3(uint32_t i, uint32_t stream) {
  uint key = pathKey(stream, i, 0u);
  return vec3(randomUnit(key, 0u), randomUnit(key, 1u), randomUnit(key, 2u));
}

void expectFits(const test::Chi2Result& r, const std::string& what) {
  EXPECT_GT(r.pValue, test::sidakLevel(kTests)) << what << ": chi2 " << r.statistic << " dof " << r.dof << "\n" << r.table;
}

vec3 fromTheta(float cosTheta) { return vec3(std::sqrt(1 - cosTheta * cosTheta), 0.0f, cosTheta); }
}  // namespace

TEST(Chi2, UniformAndCosineHemisphere) {
  auto uni = chi2Sphere(
      [](uint32_t i) {
        vec3 u = u3(i, 1);
        return sampleUniformHemisphere(vec2(u.x, u.y));
      },
      [](vec3 w) { return double(uniformHemispherePdf(w.z)); }, kSamples);
  expectFits(uni, "uniform hemisphere");
  EXPECT_NEAR(uni.pdfIntegral, 1.0, 2e-3);
  auto cos = chi2Sphere(
      [](uint32_t i) {
        vec3 u = u3(i, 2);
        return sampleCosineHemisphere(vec2(u.x, u.y));
      },
      [](vec3 w) { return double(cosineHemispherePdf(w.z)); }, kSamples);
  expectFits(cos, "cosine hemisphere");
  EXPECT_NEAR(cos.pdfIntegral, 1.0, 2e-3);
}

// One row per roughness (alpha along x and along y: isotropic where equal, KHR_materials_anisotropy's stretched
// lobe where not) and cosine of the outgoing angle, seen at an azimuth off both axes.
class GgxVisibleNormals : public ::testing::TestWithParam<std::tuple<vec2, float>> {};

TEST_P(GgxVisibleNormals, ReflectionMatchesItsPdf) {
  const auto [alpha, cosO] = GetParam();
  const float sinO = std::sqrt(1.0f - cosO * cosO), phi = 0.6f;
  vec3 wo(sinO * std::cos(phi), sinO * std::sin(phi), cosO);
  auto r = chi2Sphere(
      [&](uint32_t i) {
        vec3 u = u3(i, 3);
        vec3 h = sampleGgxVisibleNormal(wo, alpha, vec2(u.x, u.y));
        vec3 wi = 2.0f * dot(wo, h) * h - wo;
        return wi.z > 0.0f ? normalize(wi) : vec3(0.0f);
      },
      [&](vec3 wi) { return double(ggxReflectionPdf(wo, wi, alpha)); }, kSamples);
  expectFits(r, "VNDF alpha " + std::to_string(alpha.x) + "," + std::to_string(alpha.y) + " cos " + std::to_string(cosO));
  EXPECT_LE(r.pdfIntegral, 1.0 + 2e-3);
}

INSTANTIATE_TEST_SUITE_P(Chi2, GgxVisibleNormals,
                         ::testing::Combine(::testing::Values(vec2(0.2f), vec2(0.5f), vec2(1.0f), vec2(0.6f, 0.1f),
                                                              vec2(0.08f, 0.5f)),
                                            ::testing::Values(0.95f, 0.5f, 0.15f)),
                         [](const auto& info) {
                           const vec2 a = std::get<0>(info.param);
                           std::string alpha =
                               a.x == a.y ? test::shortNumber(a.x) : test::shortNumber(a.x) + " " + test::shortNumber(a.y);
                           return test::paramName("alpha " + alpha + " cos " + test::shortNumber(std::get<1>(info.param)));
                         });

// One row per roughness, metallic and cosine of the outgoing angle.
class GltfBrdf : public ::testing::TestWithParam<std::tuple<float, float, float>> {};

TEST_P(GltfBrdf, SamplingMatchesPdfAndEval) {
  const auto [roughness, metallic, cosO] = GetParam();
  GltfMaterial m = makeGltfMaterial(vec3(0.8f, 0.5f, 0.2f), metallic, roughness, 1.0f);
  vec3 wo = fromTheta(cosO);
  std::string what =
      "roughness " + std::to_string(roughness) + " metallic " + std::to_string(metallic) + " cos " + std::to_string(cosO);
  auto r = chi2Sphere(
      [&](uint32_t i) {
        vec3 wi = sampleGltfBsdf(m, wo, u3(i, 4)).wi;
        return wi.z > 0.0f ? normalize(wi) : vec3(0.0f);
      },
      [&](vec3 wi) { return double(gltfBsdfPdf(m, wo, wi)); }, kSamples);
  expectFits(r, what);
  // Weights f cos / pdf: their mean is the directional albedo, which quadrature of f cos must match.
  double sum = 0, sumSq = 0;
  const uint32_t n = 200000;
  for (uint32_t i = 0; i < n; ++i) {
    BsdfSample s = sampleGltfBsdf(m, wo, u3(i, 5));
    double w = s.wi.z > 0.0f ? luminance(s.weight) : 0.0;
    sum += w;
    sumSq += w * w;
  }
  test::SampleMean weight = test::sampleMean(sum, sumSq, n);
  double quad = 0.0;
  const int nt = 256, np = 256;
  for (int t = 0; t < nt; ++t)
    for (int p = 0; p < np; ++p) {
      double theta = (t + 0.5) * (kPi / 2) / nt, phi = (p + 0.5) * 2 * kPi / np;
      vec3 wi(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      quad += luminance(gltfBsdfEval(m, wo, wi)) * wi.z * std::sin(theta) * (kPi / 2 / nt) * (2 * kPi / np);
    }
  EXPECT_TRUE(test::withinSigmas(test::zTest(weight.mean, quad, weight.sigma, 2e-3 * quad), 5)) << what;
  EXPECT_TRUE(test::atMostSigmas(test::zTest(weight.mean, 1.0, weight.sigma), 5))
      << what << ": the BRDF reflects more than it receives";
}

INSTANTIATE_TEST_SUITE_P(Chi2, GltfBrdf,
                         ::testing::Combine(::testing::Values(0.45f, 0.7f, 1.0f), ::testing::Values(0.0f, 0.5f, 1.0f),
                                            ::testing::Values(0.95f, 0.5f, 0.15f)),
                         [](const auto& info) {
                           return test::paramName("roughness " + test::shortNumber(std::get<0>(info.param)) + " metallic " +
                                                  test::shortNumber(std::get<1>(info.param)) + " cos " +
                                                  test::shortNumber(std::get<2>(info.param)));
                         });

TEST(Chi2, SpecularFactorZeroIsLambertian) {
  GltfMaterial m = makeGltfMaterial(vec3(0.3f, 0.6f, 0.9f), 0.0f, 0.4f, 0.0f);
  for (float a : {0.1f, 0.5f, 0.99f})
    for (float b : {0.2f, 0.7f}) {
      vec3 f = gltfBsdfEval(m, fromTheta(a), normalize(vec3(0.3f, 0.1f, b)));
      EXPECT_NEAR(f.x, 0.3f / kPi, 1e-6f);
      EXPECT_NEAR(f.z, 0.9f / kPi, 1e-6f);
    }
  EXPECT_EQ(lobeProbabilities(m, fromTheta(0.5f)).specular, 0.0f);
}

namespace {
// The triangle split into n^2 congruent sub-triangles (equal areas); cell of barycentrics (b1, b2).
int subTriangleCell(double b1, double b2, int n) {
  double fi = std::clamp(b1, 0.0, 1.0) * n, fj = std::clamp(b2, 0.0, 1.0) * n;
  int i = std::min(n - 1, int(fi)), j = std::min(n - 1 - i, int(fj));
  bool up = (fi - i) + (fj - j) < 1.0 || i + j == n - 1;
  return (i * n + j) * 2 + (up ? 0 : 1);
}

// How far barycentrics lie outside their triangle (0 inside).
double outsideBy(vec3 b) { return std::max(0.0, -double(std::min({b.x, b.y, b.z}))); }

double solidAngleD(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
  glm::dvec3 ua = glm::normalize(a - p), ub = glm::normalize(b - p), uc = glm::normalize(c - p);
  return 2.0 *
         std::atan2(std::abs(glm::dot(ua, glm::cross(ub, uc))), 1.0 + glm::dot(ua, ub) + glm::dot(ub, uc) + glm::dot(uc, ua));
}

struct Tri {
  vec3 a, b, c;
  const char* name;
};
void PrintTo(const Tri& t, std::ostream* os) { *os << t.name; }
class TriangleLight : public ::testing::TestWithParam<Tri> {};
}  // namespace

TEST_P(TriangleLight, SamplingByAreaAndSolidAngle) {
  const Tri t = GetParam();
  const int n = 12;
  vec3 p(0.0f);
  float omega = triangleSolidAngle(p, t.a, t.b, t.c);
  ASSERT_TRUE(useSphericalSampling(omega));
  glm::dvec3 A(t.a), B(t.b), C(t.c);
  auto corner = [&](int i, int j) { return A + (double(i) / n) * (B - A) + (double(j) / n) * (C - A); };
  std::vector<double> cellOmega(2 * n * n, 0.0);
  double omegaTotal = solidAngleD(glm::dvec3(0.0), A, B, C);
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j) {
      cellOmega[(i * n + j) * 2] = solidAngleD(glm::dvec3(0.0), corner(i, j), corner(i + 1, j), corner(i, j + 1));
      if (i + j < n - 1)
        cellOmega[(i * n + j) * 2 + 1] = solidAngleD(glm::dvec3(0.0), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1));
    }
  std::vector<double> observedArea(2 * n * n, 0.0), observedSolid(2 * n * n, 0.0), expectedArea(2 * n * n, 0.0),
      expectedSolid(2 * n * n, 0.0);
  int cells = 0;
  for (int k = 0; k < 2 * n * n; ++k) {
    if (cellOmega[k] <= 0.0) continue;
    ++cells;
    expectedSolid[k] = cellOmega[k] / omegaTotal * kSamples;
  }
  for (int k = 0; k < 2 * n * n; ++k) expectedArea[k] = cellOmega[k] > 0.0 ? double(kSamples) / cells : 0.0;
  int misses = 0;
  double worstOutside = 0.0;
  for (uint32_t i = 0; i < kSamples; ++i) {
    vec3 u = u3(i, 6);
    vec3 b = sampleUniformTriangle(vec2(u.x, u.y));
    observedArea[subTriangleCell(b.y, b.z, n)] += 1.0;
    vec3 w = sampleSphericalTriangle(p, t.a, t.b, t.c, vec2(u.x, u.y), omega);
    vec3 h = intersectTriangle(makeRayShear(p, w), t.a, t.b, t.c, 1e30f);
    if (h.x <= 0.0f) {
      // A direction just outside an edge by float rounding is harmless; anything farther is a sampler bug.
      ++misses;
      worstOutside = std::max(worstOutside, outsideBy(rayTriangleBarycentrics(p, w, t.a, t.b, t.c)));
      continue;
    }
    observedSolid[subTriangleCell(h.y, h.z, n)] += 1.0;
  }
  EXPECT_LT(worstOutside, 1e-5) << t.name << ": " << misses << " directions missed the triangle";
  auto ra = test::chi2FromCounts(observedArea, expectedArea);
  EXPECT_GT(ra.pValue, test::sidakLevel(kTests)) << "area sampling, " << t.name << ": chi2 " << ra.statistic << "\n" << ra.table;
  // Misses are dropped from the observations, so scale the expectation to the hits.
  for (double& e : expectedSolid) e *= double(kSamples - misses) / kSamples;
  auto rs = test::chi2FromCounts(observedSolid, expectedSolid);
  EXPECT_GT(rs.pValue, test::sidakLevel(kTests)) << "solid-angle sampling, " << t.name << ": chi2 " << rs.statistic << "\n"
                                                 << rs.table;
  EXPECT_NEAR(omega, omegaTotal, 1e-5 * omegaTotal) << "float solid angle against double";
}

// Seen from the origin: a far small triangle and a near one covering a wide solid angle.
INSTANTIATE_TEST_SUITE_P(
    Chi2, TriangleLight,
    ::testing::Values(Tri{vec3(-0.3f, -0.2f, 2.0f), vec3(0.4f, -0.1f, 2.2f), vec3(0.0f, 0.5f, 1.8f), "small"},
                      Tri{vec3(-2.0f, -1.5f, 0.4f), vec3(2.5f, -1.0f, 0.5f), vec3(0.0f, 2.5f, 0.3f), "wide"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(Chi2, AliasTableReproducesItsWeights) {
  std::vector<double> weights;
  for (int i = 0; i < 50; ++i) weights.push_back(std::pow(10.0, (i % 7) - 3.0) * (1 + i % 3));
  std::vector<AliasEntry> table = buildAliasTable(weights);
  double total = 0;
  for (double w : weights) total += w;
  std::vector<double> observed(weights.size(), 0.0), expected(weights.size());
  for (size_t i = 0; i < weights.size(); ++i) {
    expected[i] = weights[i] / total * kSamples;
    EXPECT_NEAR(table[i].pmf, weights[i] / total, 1e-6 * (1 + weights[i] / total));
  }
  // The light entries as the device holds them (the triangle is the entry's own index here).
  std::vector<uvec4> entries;
  for (uint32_t i = 0; i < table.size(); ++i)
    entries.push_back(encodeLightEntry(table[i].probability, table[i].alias, kLightKindTriangle, i, table[i].pmf));
  const uint32_t n = uint32_t(entries.size());
  for (uint32_t s = 0; s < kSamples; ++s) {
    // The kernel's selection (scene_layout.h): u * n picks a slot, the fraction decides between it and its alias.
    float scaled = randomUnit(pathKey(8u, s, 0u), 0u) * float(n);
    uint32_t slot = aliasSlot(scaled, n);
    uvec4 chosen = entries[aliasChoice(scaled, slot, entries[slot])];
    ASSERT_EQ(lightEntryPmf(chosen), table[lightEntryIndex(chosen)].pmf);
    observed[lightEntryIndex(chosen)] += 1.0;
  }
  auto r = test::chi2FromCounts(observed, expected);
  EXPECT_GT(r.pValue, test::sidakLevel(kTests)) << r.table;
}
