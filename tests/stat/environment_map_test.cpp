// The environment light's sampling (shaders/shared/environment_map.h), run as C++ from the shared header against
// its pdf: chi-square per pixel (bins aligned with the piecewise-constant density, so the expected counts are
// exact) and over the sphere, the pdf integrating to one, the inverse, the direction convention and the power.
#include <gtest/gtest.h>

#include "../shaders/shared/environment_map.h"
#include "../shaders/shared/rng.h"
#include "render/gpu_scene.h"
#include "support/chi2.h"

using namespace vkmc;
using namespace vkmc::gpu;

namespace {
constexpr uint32_t kSamples = 1000000;
constexpr int kTests = 3;  // Sidak correction over the chi-square tests in this file
constexpr double kPiD = 3.14159265358979323846;

// 24 x 12 pixels: a gradient, a hot spot 50x brighter, a black corner (unless gentle); rotated 30 degrees.
EnvironmentMap testMap(bool gentle = false) {
  EnvironmentMap m;
  m.width = 24, m.height = 12;
  m.rotationDegrees = 30.0f;
  for (uint32_t y = 0; y < m.height; ++y)
    for (uint32_t x = 0; x < m.width; ++x) {
      glm::vec3 L(0.2f + 0.05f * x, 0.3f + 0.1f * y, 0.5f);
      if (!gentle && x == 17 && y == 4) L *= 50.0f;
      if (!gentle && x < 3 && y < 2) L = glm::vec3(0.0f);
      m.radiance.push_back(L);
    }
  return m;
}

EnvironmentHeader headerOf(const EnvironmentMap& m) {
  EnvironmentHeader h{};
  h.width = m.width, h.height = m.height;
  h.cosRotation = std::cos(glm::radians(m.rotationDegrees));
  h.sinRotation = std::sin(glm::radians(m.rotationDegrees));
  return h;
}

vec2 u2(uint32_t i, uint32_t stream) {
  uint key = pathKey(stream, i, 0u);
  return vec2(randomUnit(key, 0u), randomUnit(key, 1u));
}

double lum(glm::vec3 c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }
}  // namespace

TEST(EnvironmentMap, SamplesFollowTheirPdfPixelByPixel) {
  const EnvironmentMap m = testMap();
  const EnvironmentHeader h = headerOf(m);
  const std::vector<float> table = environmentDistribution(m);
  // The density the distribution is meant to follow, computed here independently: luminance x sin(theta).
  std::vector<double> expected(m.width * m.height), observed(m.width * m.height, 0.0);
  double total = 0.0;
  for (uint32_t y = 0; y < m.height; ++y)
    for (uint32_t x = 0; x < m.width; ++x)
      total += expected[y * m.width + x] = lum(m.radiance[y * m.width + x]) * std::sin(kPiD * (y + 0.5) / m.height);
  for (double& e : expected) e *= kSamples / total;
  uint32_t pdfMismatches = 0;
  for (uint32_t i = 0; i < kSamples; ++i) {
    float pdf = 0.0f;
    vec3 w = sampleEnvironment(table.data(), h, u2(i, 31), pdf);
    ASSERT_NEAR(glm::length(w), 1.0f, 1e-5f);
    observed[environmentPixel(h, environmentUv(h, w))] += 1.0;
    float again = environmentPdf(table.data(), h, w);
    pdfMismatches += std::abs(again - pdf) > 1e-3f * pdf ? 1 : 0;  // only where a sample sits on a pixel border
  }
  auto r = test::chi2FromCounts(observed, expected);
  EXPECT_GT(r.pValue, test::sidakLevel(kTests)) << r.table;
  EXPECT_LT(pdfMismatches, kSamples / 10000) << "the pdf a sample reports and environmentPdf disagree";
  for (uint32_t y = 0; y < 2; ++y)
    for (uint32_t x = 0; x < 3; ++x) EXPECT_EQ(observed[y * m.width + x], 0.0) << "a black pixel was sampled";
}

TEST(EnvironmentMap, SolidAnglePdfFitsAndIntegratesToOne) {
  // Over a theta x phi grid the pixels' edges cut cells, whose expected counts come from quadrature: a gentle map
  // keeps its error at the edges below the noise (the per-pixel test above is the exact one).
  const EnvironmentMap m = testMap(true);
  const EnvironmentHeader h = headerOf(m);
  const std::vector<float> table = environmentDistribution(m);
  // The grid's pole (z) on the map's (y): the solid-angle pdf has a 1 / sin(theta) factor there, which the grid's
  // quadrature integrates exactly only when its own sin(theta) cancels it.
  auto r = test::chi2Sphere(
      [&](uint32_t i) {
        float pdf = 0.0f;
        vec3 w = sampleEnvironment(table.data(), h, u2(i, 32), pdf);
        return vec3(w.z, w.x, w.y);
      },
      [&](vec3 g) { return double(environmentPdf(table.data(), h, vec3(g.y, g.z, g.x))); }, kSamples, 21, 41, 64);
  EXPECT_NEAR(r.pdfIntegral, 1.0, 5e-3);
  EXPECT_GT(r.pValue, test::sidakLevel(kTests)) << "chi2 " << r.statistic << " dof " << r.dof << "\n" << r.table;
}

TEST(EnvironmentMap, AConstantMapIsSampledUniformlyOnTheSphere) {
  EnvironmentMap m = EnvironmentMap::constant(glm::vec3(2.0f));
  const EnvironmentHeader h = headerOf(m);
  const std::vector<float> table = environmentDistribution(m);
  auto r = test::chi2Sphere(
      [&](uint32_t i) {
        float pdf = 0.0f;
        return sampleEnvironment(table.data(), h, u2(i, 33), pdf);
      },
      [&](vec3 w) { return double(environmentPdf(table.data(), h, w)); }, kSamples);
  EXPECT_NEAR(r.pdfIntegral, 1.0, 2e-3);
  EXPECT_GT(r.pValue, test::sidakLevel(kTests)) << r.table;
  // pi r^2 times the integral of the luminance over the sphere: pi 4 pi L for r = 1.
  EXPECT_NEAR(environmentPower(m, 1.0), 4.0 * kPiD * kPiD * 2.0, 1e-9);
}

TEST(EnvironmentMap, InvertingASampleGivesBackItsRandomNumbers) {
  const EnvironmentMap m = testMap();
  const EnvironmentHeader h = headerOf(m);
  const std::vector<float> table = environmentDistribution(m);
  for (uint32_t i = 0; i < 10000; ++i) {
    vec2 u = u2(i, 34);
    float pdf = 0.0f;
    vec2 uv = sampleEnvDistribution(table.data(), h.width, h.height, u, pdf);
    vec2 back = invertEnvDistributionSample(table.data(), h.width, h.height, uv);
    ASSERT_NEAR(back.x, u.x, 2e-5f) << i;
    ASSERT_NEAR(back.y, u.y, 2e-5f) << i;
  }
}

TEST(EnvironmentMap, DirectionConventionYUpCentreAlongMinusZ) {
  EnvironmentHeader h{};
  h.width = 8, h.height = 4;
  h.cosRotation = 1.0f;
  auto near = [](vec3 a, vec3 b) { return glm::length(a - b) < 1e-5f; };
  EXPECT_TRUE(near(environmentDirection(h, vec2(0.5f, 0.5f)), vec3(0, 0, -1)));  // the image's centre
  EXPECT_TRUE(near(environmentDirection(h, vec2(0.75f, 0.5f)), vec3(1, 0, 0)));  // right of it: +X
  EXPECT_TRUE(near(environmentDirection(h, vec2(0.3f, 0.0f)), vec3(0, 1, 0)));   // the top row: +Y
  EXPECT_TRUE(near(environmentDirection(h, vec2(0.0f, 0.5f)), vec3(0, 0, 1)));   // the edges: +Z
  h.cosRotation = 0.0f, h.sinRotation = 1.0f;                                    // 90 degrees counter-clockwise seen from above
  EXPECT_TRUE(near(environmentDirection(h, vec2(0.5f, 0.5f)), vec3(-1, 0, 0)));
  for (uint32_t i = 0; i < 1000; ++i) {
    vec2 uv = u2(i, 35) * vec2(1.0f, 0.98f) + vec2(0.0f, 0.01f);
    vec2 back = environmentUv(h, environmentDirection(h, uv));
    ASSERT_NEAR(std::min(std::abs(back.x - uv.x), 1.0f - std::abs(back.x - uv.x)), 0.0f, 1e-4f) << i;
    ASSERT_NEAR(back.y, uv.y, 1e-4f) << i;
  }
}
