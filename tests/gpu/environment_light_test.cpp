// The environment light rendered: a Lambertian plane of albedo rho in a constant environment L has radiance
// rho L everywhere (it cannot see itself), a white world's light; the studio lights what the file declares no world
// for, and a lights-only world adds nothing; under a non-constant
// map, NEE + MIS, light sampling alone and BSDF sampling alone agree within their measured confidence intervals
// (the MIS combination with escaped rays is unbiased).
#include <gtest/gtest.h>

#include <filesystem>
#include <tuple>

#include "io/exr.h"
#include "scene/studio_environment.h"
#include "support/render_helpers.h"
#include "support/test_scenes.h"

using namespace vkmc;
using namespace vkmc::test;

namespace {
constexpr float kRho = 0.5f;

Scene planeScene(World world = World::White) {
  Scene s;
  s.world = world;
  Material m;
  m.baseColor = glm::vec3(kRho);
  m.metallic = 0.0f;
  m.specular = 0.0f;
  s.materials.push_back(m);
  addQuad(s, glm::vec3(-1.0f, -1.0f, 0.0f), glm::vec3(2.0f, 0.0f, 0.0f), glm::vec3(0.0f, 2.0f, 0.0f), 0);
  return s;
}

// Looking down -Z at the plane, which fills the image.
RenderOptions planeView(uint32_t spp, uint32_t seed) {
  RenderOptions o;
  o.scenePath = "in-memory plane";
  o.width = 16;
  o.height = 16;
  o.spp = spp;
  o.seed = seed;
  o.progress = false;
  o.lookFrom = glm::vec3(0.0f, 0.0f, 3.0f);
  o.lookAt = glm::vec3(0.0f);
  o.fovDegrees = 20.0f;
  return o;
}

// 32 x 16: a dim sky gradient and a sun of 2 x 2 pixels 200 times brighter.
std::string writeSunMap() {
  static const std::filesystem::path dir = makeTempDir("environment_light");
  ExrImage image;
  image.width = 32, image.height = 16;
  for (const char* c : {"R", "G", "B"}) image.channels[c].resize(32 * 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 32; ++x) {
      float sky = 0.2f + 0.05f * float(16 - y), sun = (x >= 26 && x < 28 && y >= 3 && y < 5) ? 200.0f : 0.0f;
      image.channels["R"][y * 32 + x] = sky + sun;
      image.channels["G"][y * 32 + x] = sky + 0.8f * sun;
      image.channels["B"][y * 32 + x] = 1.5f * sky + 0.5f * sun;
    }
  std::string path = (dir / "sun.exr").string();
  writeExr(path, image);
  return path;
}
}  // namespace

TEST(EnvironmentLight, AWhiteWorldIsAConstantEnvironmentAndConverges) {
  // rho L = 0.5 on every pixel, by NEE + MIS (the default) and by BSDF sampling alone.
  for (bool nee : {true, false}) {
    RenderOptions o = planeView(16, nee ? 3 : 4);
    o.estimator.nee = nee;
    RenderOutcome r = runRender(sharedContext(), o, planeScene());
    EXPECT_EQ(r.environment, "constant");
    EXPECT_EQ(r.film.totalNonfinite(), 0u);
    EXPECT_TRUE(regionMatches(whole(r.film), glm::dvec3(kRho), 5.0)) << (nee ? "NEE + MIS" : "BSDF sampling");
  }
}

// In a white world, camera rays that miss the scene see a grey backdrop (kDefaultBackdrop), exactly, while the
// plane stays lit by the white environment (rho L); with a --background, escaped camera rays see it instead.
TEST(EnvironmentLight, TheWhiteWorldsBackdropIsGreyForCameraRaysOnly) {
  RenderOptions o = planeView(16, 5);
  o.fovDegrees = 90.0f;  // the plane fills the middle; the corners see the sky
  RenderOutcome r = runRender(sharedContext(), o, planeScene());
  EXPECT_EQ(r.backdrop, kDefaultBackdrop);
  const Film& f = r.film;
  EXPECT_NEAR(f.mean(0, 1), kDefaultBackdrop, 1e-6) << "a corner: every sample the backdrop";
  const size_t centre = size_t(8) * f.width + 8;
  EXPECT_TRUE(withinSigmas(zTest(f.mean(centre, 1), kRho, std::sqrt(f.varianceOfMean(centre, 1)), 1e-6), 5.0))
      << "the plane, lit by the white environment: " << f.mean(centre, 1);
  o.background = glm::vec3(0.25f);
  RenderOutcome given = runRender(sharedContext(), o, planeScene());
  EXPECT_EQ(given.backdrop, 0.0f);
  EXPECT_NEAR(given.film.mean(0, 1), 0.25, 1e-6) << "--background: seen by escaped camera rays too";
}

// The studio (--environment studio, or a file that declares no world): the Lambertian plane (facing +Z) has
// radiance rho / pi times the studio's cosine-weighted radiance over its hemisphere, summed here over the map's
// texels (the texels' exact solid angles; the cosine at each texel's centre, a quadrature error under 0.2% at
// 128 x 64), and the camera sees the grey backdrop.
TEST(EnvironmentLight, TheStudioEnvironmentLightsAsItsMapIntegrates) {
  const EnvironmentMap studio = studioEnvironment();
  double irradiance = 0.0;
  for (uint32_t y = 0; y < studio.height; ++y)
    for (uint32_t x = 0; x < studio.width; ++x) {
      const glm::vec3 w = equirectangularDirection(x, y, studio.width, studio.height);
      const double band = std::cos(M_PI * y / studio.height) - std::cos(M_PI * (y + 1) / studio.height);
      irradiance += studio.radiance[size_t(y) * studio.width + x].x * std::max(0.0f, w.z) * band * 2.0 * M_PI / studio.width;
    }
  for (bool named : {true, false}) {
    RenderOptions o = planeView(64, named ? 6 : 7);
    if (named) o.environmentPath = kStudioEnvironment;
    RenderOutcome r = runRender(sharedContext(), o, planeScene(named ? World::LightsOnly : World::Studio));
    EXPECT_EQ(r.environment, "studio");
    EXPECT_EQ(r.backdrop, kDefaultBackdrop);
    EXPECT_EQ(r.film.totalNonfinite(), 0u);
    const double expected = kRho / M_PI * irradiance;
    const glm::dvec3 mean = r.film.imageMean(), var = r.film.imageMeanVarianceOfMean();
    EXPECT_TRUE(withinSigmas(zTest(mean.y, expected, std::sqrt(var.y / r.film.pixels()), 2e-3 * expected), 5.0))
        << (named ? "--environment studio: " : "the undeclared world: ") << mean.y << " against " << expected;
  }
}

// A lights-only world adds no light: the plane, with none of its own, is black, and so is the sky behind it.
TEST(EnvironmentLight, ALightsOnlyWorldAddsNothing) {
  RenderOptions o = planeView(4, 8);
  o.fovDegrees = 90.0f;
  RenderOutcome r = runRender(sharedContext(), o, planeScene(World::LightsOnly));
  EXPECT_EQ(r.environment, "");
  EXPECT_EQ(r.backdrop, 0.0f);
  EXPECT_EQ(r.film.imageMean(), glm::dvec3(0.0));
}

TEST(EnvironmentLight, NeeWithMisLightSamplingAloneAndBsdfSamplingAgreeUnderAMap) {
  const std::string map = writeSunMap();
  auto render = [&](bool nee, MisHeuristic mis, uint32_t spp, uint32_t seed) {
    RenderOptions o = planeView(spp, seed);
    o.environmentPath = map;
    o.environmentRotation = -40.0f;  // turns the sun to about (0.24, 0.71, 0.67): above the plane
    o.estimator.nee = nee;
    o.estimator.mis = mis;
    RenderOutcome r = runRender(sharedContext(), o, planeScene());
    EXPECT_EQ(r.film.totalNonfinite(), 0u);
    EXPECT_TRUE(r.warnings.empty());
    return whole(r.film);
  };
  RegionStats bsdf = render(false, MisHeuristic::Power, 256, 11);
  RegionStats mis = render(true, MisHeuristic::Power, 64, 12);
  RegionStats light = render(true, MisHeuristic::None, 64, 13);
  EXPECT_GT(mis.mean.x, 0.1);
  EXPECT_TRUE(regionsAgree(mis, bsdf, 5.0)) << "NEE + MIS against BSDF sampling";
  EXPECT_TRUE(regionsAgree(light, bsdf, 5.0)) << "light sampling alone against BSDF sampling";
  EXPECT_LT(mis.variance.x, bsdf.variance.x) << "importance sampling the sun should beat BSDF sampling";
}

TEST(EnvironmentLight, MisWeightsStayUnbiasedWhenTheLightTableMixesEveryKind) {
  // An emissive quad, a point light and the map share one power-proportional table, so the selection pmfs that
  // weigh BSDF-sampled hits on the quad and escaped rays (emissionAt, escapedRadiance) include the point light's
  // and the environment's power. NEE + MIS must agree with light sampling alone (which never uses those
  // weights), in both integrators.
  const std::string map = writeSunMap();
  auto scene = [] {
    Scene s = planeScene();
    Material lamp;
    lamp.emission = glm::vec3(4.0f, 3.0f, 2.0f);
    s.materials.push_back(lamp);
    addQuad(s, glm::vec3(-0.3f, -0.3f, 1.5f), glm::vec3(0.0f, 0.6f, 0.0f), glm::vec3(0.6f, 0.0f, 0.0f), 1);  // facing -z
    PunctualLight point;
    point.position = glm::vec3(0.5f, 0.2f, 0.7f);
    point.intensity = glm::vec3(0.5f, 1.0f, 0.7f);
    s.punctualLights.push_back(point);
    return s;
  };
  auto render = [&](MisHeuristic mis, Integrator integrator, uint32_t seed) {
    RenderOptions o = planeView(64, seed);
    o.environmentPath = map;
    o.environmentRotation = -40.0f;
    o.estimator.mis = mis;
    o.integrator = integrator;
    RenderOutcome r = runRender(sharedContext(), o, scene());
    EXPECT_EQ(r.film.totalNonfinite(), 0u);
    EXPECT_EQ(r.sceneInfo.punctualLights, 1u);
    return whole(r.film);
  };
  RegionStats light = render(MisHeuristic::None, Integrator::Wavefront, 21);
  RegionStats mis = render(MisHeuristic::Power, Integrator::Wavefront, 22);
  RegionStats mega = render(MisHeuristic::Balance, Integrator::Megakernel, 23);
  EXPECT_TRUE(regionsAgree(mis, light, 5.0)) << "power heuristic against light sampling alone";
  EXPECT_TRUE(regionsAgree(mega, light, 5.0)) << "megakernel, balance heuristic, against light sampling alone";
}

TEST(EnvironmentLight, EntersASingleSidedRoomThroughTheWallsTheCameraLooksThrough) {
  // A closed room of single-sided walls facing in, seen from outside above its +Z side: the eye passes the near
  // wall, the ceiling and the +X wall from behind, so they are removed for every ray (bvh/seen_through_faces.h)
  // and the white world lights the floor. Kept, they would leave the room black: every ray from inside meets a
  // wall's front.
  Scene s = planeScene();
  s.positions.clear(), s.normals.clear(), s.materialIds.clear();
  const glm::vec3 o(-1.0f), x(2, 0, 0), y(0, 2, 0), z(0, 0, 2);
  for (auto [corner, u, v] : {std::tuple{o, z, y}, {o + x, y, z}, {o, x, z}, {o + y, z, x}, {o, y, x}, {o + z, x, y}})
    addQuad(s, corner, v, u, 0);  // u x v faces out; v x u, in
  RenderOptions view = planeView(64, 5);
  view.lookFrom = glm::vec3(3.0f, 4.0f, 6.0f);
  view.lookAt = glm::vec3(0.0f, -1.0f, 0.0f);  // the floor's centre, at the image's centre
  view.fovDegrees = 60.0f;
  RenderOutcome r = runRender(sharedContext(), view, s);
  EXPECT_EQ(r.seenThroughTriangles, 6u);
  const size_t centre = 8 * 16 + 8;
  EXPECT_GT(r.film.mean(centre, 0), 0.1) << "the floor sees the sky through the open ceiling";
  EXPECT_EQ(r.film.totalNonfinite(), 0u);
}
