// KHR_lights_punctual lights rendered against closed forms: a Lambertian plane of albedo rho seen at max-depth 1
// has radiance rho / pi times the irradiance the light delivers (point and spot I falloff cos / d^2, directional
// E cos), including the stiff cases of a light 1e-3 and 1e3 units away. One light alone makes each sample exact
// (no selection noise), so those rows allow float rounding as slack; two lights together are chosen at random
// in proportion to power and tested against the sum by a z-test on the measured variance.
#include <gtest/gtest.h>

#include <cmath>

#include "../shaders/shared/punctual_light.h"
#include "support/param_name.h"
#include "support/render_helpers.h"

using namespace vkmc;
using namespace vkmc::test;

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr float kRho = 0.5f;
constexpr double kRelativeSlack = 2e-5;  // float rounding of one deterministic sample chain

double radians(double degrees) { return degrees * kPi / 180.0; }

// A Lambertian square of albedo kRho in z = 0 facing +z, 2 halfSize wide.
Scene planeScene(float halfSize) {
  Scene s;
  Material m;
  m.baseColor = glm::vec3(kRho);
  m.metallic = 0.0f;
  m.specular = 0.0f;  // pure Lambert
  s.materials.push_back(m);
  addQuad(s, glm::vec3(-halfSize, -halfSize, 0.0f), glm::vec3(2.0f * halfSize, 0.0f, 0.0f),
          glm::vec3(0.0f, 2.0f * halfSize, 0.0f), 0);
  return s;
}

PunctualLight pointLight(glm::vec3 position, float intensity) {
  PunctualLight l;
  l.kind = PunctualKind::Point;
  l.position = position;
  l.intensity = glm::vec3(intensity);
  return l;
}

// Renders `scene` at max-depth 1 through a camera at height cameraHeight looking down -Z at the origin with a
// field of view so narrow (0.01 degrees) that the irradiance varies across the image by under 1e-6.
RegionStats renderOrigin(Scene scene, float cameraHeight, uint32_t spp = 4) {
  RenderOptions o;
  o.scenePath = "in-memory plane";
  o.width = 8;
  o.height = 8;
  o.spp = spp;
  o.seed = 17;
  o.progress = false;
  o.lookFrom = glm::vec3(0.0f, 0.0f, cameraHeight);
  o.lookAt = glm::vec3(0.0f);
  o.fovDegrees = 0.01f;
  o.estimator.maxDepth = 1;
  RenderOutcome r = runRender(sharedContext(), o, std::move(scene));
  EXPECT_EQ(r.film.totalNonfinite(), 0u);
  return whole(r.film);
}

::testing::AssertionResult exactly(const RegionStats& r, double expected) {
  for (int c = 0; c < 3; ++c) {
    auto t = withinSigmas(zTest(r.mean[c], expected, std::sqrt(r.variance[c]), kRelativeSlack * expected + 1e-30), 5.0);
    if (!t) return t;
  }
  return ::testing::AssertionSuccess();
}
}  // namespace

// Point light of intensity I at height h over the plane: L = rho / pi * I / h^2 under it.
class PointLightOverPlane : public ::testing::TestWithParam<float> {};

TEST_P(PointLightOverPlane, RadianceUnderItIsRhoOverPiTimesIOverHSquared) {
  const float h = GetParam(), intensity = 2.0f;
  Scene s = planeScene(std::max(1.0f, 2.0f * h));
  s.punctualLights.push_back(pointLight(glm::vec3(0.0f, 0.0f, h), intensity));
  RegionStats r = renderOrigin(std::move(s), 5.0f * h);
  double expected = kRho / kPi * intensity / (double(h) * h);
  EXPECT_TRUE(exactly(r, expected)) << "h = " << h;
}

INSTANTIATE_TEST_SUITE_P(PunctualLight, PointLightOverPlane, ::testing::Values(1e-3f, 1.0f, 1e3f),
                         [](const auto& info) { return paramName("h " + shortNumber(info.param)); });

// A spot (inner 20 degrees, outer 40) at height 1 shining down -Z, moved sideways so that the origin is seen
// alpha off its axis: L = rho / pi * I falloff(cos alpha) cos^3 alpha (d = 1 / cos alpha, the plane's cos is cos alpha).
class SpotFalloff : public ::testing::TestWithParam<double> {};

TEST_P(SpotFalloff, FollowsTheSpecsSmoothCone) {
  const double alpha = radians(GetParam()), inner = radians(20.0), outer = radians(40.0);
  const float intensity = 3.0f;
  Scene s = planeScene(2.0f);
  PunctualLight l = pointLight(glm::vec3(-std::tan(alpha), 0.0, 1.0), intensity);
  l.kind = PunctualKind::Spot;
  l.innerConeAngle = float(inner);
  l.outerConeAngle = float(outer);
  s.punctualLights.push_back(l);
  RegionStats r = renderOrigin(std::move(s), 5.0f);
  double t = std::clamp((std::cos(alpha) - std::cos(outer)) / (std::cos(inner) - std::cos(outer)), 0.0, 1.0);
  double expected = kRho / kPi * intensity * t * t * std::pow(std::cos(alpha), 3.0);
  EXPECT_TRUE(exactly(r, expected)) << "alpha " << GetParam() << " degrees, falloff " << t * t;
  // The shared falloff is the one the kernels ran.
  EXPECT_NEAR(gpu::spotFalloff(float(std::cos(alpha)), float(std::cos(outer)), float(std::cos(inner))), t * t, 1e-5);
}

INSTANTIATE_TEST_SUITE_P(PunctualLight, SpotFalloff, ::testing::Values(10.0, 30.0, 50.0),
                         [](const auto& info) { return paramName("alpha " + shortNumber(float(info.param))); });

// A directional light of irradiance E at normal incidence, tilted beta from the plane's normal: L = rho / pi E cos(beta).
class DirectionalCosineLaw : public ::testing::TestWithParam<double> {};

TEST_P(DirectionalCosineLaw, RadianceIsRhoOverPiTimesECosBeta) {
  const double beta = radians(GetParam());
  const float irradiance = 2.0f;
  Scene s = planeScene(1.0f);
  PunctualLight l;
  l.kind = PunctualKind::Directional;
  l.direction = glm::vec3(std::sin(beta), 0.0, -std::cos(beta));
  l.intensity = glm::vec3(irradiance);
  s.punctualLights.push_back(l);
  RegionStats r = renderOrigin(std::move(s), 5.0f);
  EXPECT_TRUE(exactly(r, kRho / kPi * irradiance * std::cos(beta))) << "beta " << GetParam() << " degrees";
}

INSTANTIATE_TEST_SUITE_P(PunctualLight, DirectionalCosineLaw, ::testing::Values(0.0, 60.0),
                         [](const auto& info) { return paramName("beta " + shortNumber(float(info.param))); });

TEST(PunctualLight, TwoLightsChosenByPowerSumTheirIrradiance) {
  // A point light (4 pi I = 25 W) and a directional light (E pi r^2 = 2 pi W for r = sqrt 2): each sample picks
  // one in proportion to power and divides by its pmf, so the mean is the sum and the noise is real.
  Scene s = planeScene(1.0f);
  s.punctualLights.push_back(pointLight(glm::vec3(0.0f, 0.0f, 1.0f), 2.0f));
  PunctualLight d;
  d.kind = PunctualKind::Directional;
  d.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  d.intensity = glm::vec3(1.0f);
  s.punctualLights.push_back(d);
  RegionStats r = renderOrigin(std::move(s), 5.0f, 256);
  double expected = kRho / kPi * (2.0 + 1.0);
  EXPECT_GT(r.variance.x, 0.0);
  EXPECT_TRUE(regionMatches(r, glm::dvec3(expected), 5.0));
}

TEST(PunctualLight, ASceneLitOnlyByPunctualLightsGetsNoDefaultEnvironment) {
  Scene s = planeScene(1.0f);
  s.punctualLights.push_back(pointLight(glm::vec3(0.0f, 0.0f, 1.0f), 2.0f));
  RenderOptions o;
  o.scenePath = "in-memory plane";
  o.width = 4;
  o.height = 4;
  o.spp = 1;
  o.progress = false;
  RenderOutcome r = runRender(sharedContext(), o, std::move(s));
  EXPECT_EQ(r.environment, "");
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
  EXPECT_EQ(r.sceneInfo.punctualLights, 1u);
}
