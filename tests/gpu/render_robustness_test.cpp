// Whole renders under stress: the Cornell box scaled and translated renders the same image (no acne, no
// leaks), and non-finite samples are counted and kept out of the image.
#include <gtest/gtest.h>

#include <filesystem>

#include "analysis/error_metrics.h"
#include "app/render_job.h"
#include "support/render_helpers.h"
#include "support/stability_row.h"
#include "support/z_test.h"
#include "scene/gltf_loader.h"

using namespace vkmc;
using vkmc::test::withinSigmas;
using vkmc::test::zTest;
using vkmc::test::zTest2;

namespace {
vk::Context& context() {
  static vk::Context ctx;
  return ctx;
}

RenderOptions smallOptions(const std::string& name) {
  RenderOptions o;
  o.scenePath = name;
  o.width = 32;
  o.height = 32;
  o.spp = 64;
  o.seed = 77;
  o.estimator.sampler = Sampler::Independent;  // sharp per-pixel comparisons: 63 dof a pixel, not sobol's 1 (3 with 4 replicates)
  o.progress = false;
  return o;
}

struct Transform {
  const char* name;
  float scale;
  glm::vec3 shift;
};
void PrintTo(const Transform& t, std::ostream* os) {
  *os << "scale " << t.scale << " shift " << t.shift.x << "," << t.shift.y << "," << t.shift.z;
}
class ScaledCornellBox : public ::testing::TestWithParam<Transform> {};

struct NamedScene {
  std::string name, path;
};
void PrintTo(const NamedScene& s, std::ostream* os) { *os << s.path; }
class SpecializedAndGeneralPipelines : public ::testing::TestWithParam<NamedScene> {};

struct IntegratorCase {
  const char* name;
  const char* scene;
  const char* estimator;
};
void PrintTo(const IntegratorCase& c, std::ostream* os) { *os << c.scene << " " << c.estimator; }
class MegakernelAndWavefront : public ::testing::TestWithParam<IntegratorCase> {};

Scene transformed(const Scene& base, float scale, glm::vec3 shift) {
  Scene s = base;
  s.bounds = Aabb{};
  for (glm::vec3& p : s.positions) {
    p = p * scale + shift;
    s.bounds.grow(p);
  }
  for (Camera& c : s.cameras) c.position = c.position * scale + shift;
  return s;
}
}  // namespace

TEST_P(ScaledCornellBox, RendersTheSameAsTheUnscaledBox) {
  // The unscaled render, once for every row.
  static const Scene base = loadGltf(std::string(VKMC_SOURCE_DIR) + "/scenes/cornell_box.gltf");
  static const RenderOutcome ref = runRender(context(), smallOptions("reference"), base);
  const Transform v = GetParam();
  SCOPED_TRACE("scale " + std::to_string(v.scale) + " shift " + std::to_string(v.shift.x));
  RenderOutcome r = runRender(context(), smallOptions("variant"), transformed(base, v.scale, v.shift));
  ASSERT_EQ(r.film.totalNonfinite(), 0u);
  int outside = 0;
  for (size_t p = 0; p < r.film.pixels(); ++p)
    for (int c = 0; c < 3; ++c) outside += !test::pixelsAgree(ref.film, r.film, p, c, 5.0, 1e-7);
  EXPECT_EQ(outside, 0);
  glm::dvec3 a = ref.film.imageMean(), b = r.film.imageMean();
  glm::dvec3 va = ref.film.imageMeanVarianceOfMean(), vb = r.film.imageMeanVarianceOfMean();
  for (int c = 0; c < 3; ++c)
    EXPECT_TRUE(withinSigmas(zTest(a[c], b[c], std::sqrt((va[c] + vb[c]) / r.film.pixels())), 5.0))
        << "image mean, channel " << c;
  test::stabilityRow("6",
                     "Cornell box scaled " + std::to_string(v.scale) + ", shifted " + std::to_string(v.shift.x) +
                         ": pixels outside 5 sigma of the unscaled render",
                     "0", outside, 0.0, outside == 0);
}

INSTANTIATE_TEST_SUITE_P(RenderRobustness, ScaledCornellBox,
                         ::testing::Values(Transform{"scaled_1e_3", 1e-3f, glm::vec3(0.0f)},
                                           Transform{"scaled_1e4", 1e4f, glm::vec3(0.0f)},
                                           Transform{"shifted_1e4", 1.0f, glm::vec3(1e4f)},
                                           Transform{"scaled_1e3_shifted_far", 1e3f, glm::vec3(-3e4f, 1e4f, 2e4f)}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(RenderRobustness, FiniteSamplesWhoseSquareOverflowsFloatStillCount) {
  // An emitter so bright (1e30) that the square of a sample overflows float: the film's high sums (scaled by
  // 2^-96) take it, so no finite sample is dropped and means and variances stay finite.
  Scene s;
  Material wall;
  wall.baseColor = glm::vec3(0.5f);
  Material hot;
  hot.emission = glm::vec3(1e30f);
  s.materials = {wall, hot};
  test::addQuad(s, glm::vec3(-2, -2, 0), glm::vec3(4, 0, 0), glm::vec3(0, 4, 0), 0);        // wall facing +z
  test::addQuad(s, glm::vec3(-0.5f, -0.5f, 1), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), 1);  // hot patch in front
  RenderOptions o = smallOptions("nonfinite");
  o.lookFrom = glm::vec3(0, 0, 5);
  o.lookAt = glm::vec3(0, 0, 0);
  RenderOutcome r = runRender(context(), o, s);
  EXPECT_EQ(r.film.totalNonfinite(), 0u);
  EXPECT_EQ(r.stats.nonfiniteEmission + r.stats.nonfiniteLightSamples + r.stats.nonfiniteThroughput, 0u);
  EXPECT_EQ(r.film.totalSamples(), 32u * 32u * 64u);
  size_t hotPixels = 0;
  for (size_t p = 0; p < r.film.pixels(); ++p)
    for (int c = 0; c < 3; ++c) {
      ASSERT_TRUE(std::isfinite(r.film.mean(p, c)));
      ASSERT_TRUE(std::isfinite(r.film.varianceOfMean(p, c)));
      hotPixels += c == 0 && r.film.mean(p, c) > 0.99e30;  // the patch seen directly: L = 1e30 in every sample
    }
  EXPECT_GT(hotPixels, 32u * 32u / 100);
}

TEST(RenderRobustness, PerPixelZTestHasItsNominalFalsePositiveRate) {
  // Two independent renders of the grey furnace (channels equal, so each pixel is one test): at level 5%
  // about 5% of pixels fail, within a 4-sigma binomial bound over 1024 pixels.
  RenderOptions o;
  o.scenePath = std::string(VKMC_SOURCE_DIR) + "/scenes/furnace.gltf";
  o.width = 32;
  o.height = 32;
  o.spp = 256;
  o.progress = false;
  o.seed = 11;
  ExrImage a = filmToImage(runRender(context(), o).film);
  o.seed = 12;
  ExrImage b = filmToImage(runRender(context(), o).film);
  ErrorMetrics m = compareImages(a, b, 0.05, true);
  ASSERT_TRUE(m.hasZTest);
  double failRate = 1.0 - m.zTestPassFraction, sigma = std::sqrt(0.05 * 0.95 / 1024.0);
  EXPECT_TRUE(withinSigmas(zTest(failRate, 0.05, sigma), 4.0));
  // Sidak-corrected at 1% over the image: two unbiased renders pass everywhere (with probability 99%).
  EXPECT_EQ(compareImages(a, b).zTestPassFraction, 1.0);
}

TEST_P(SpecializedAndGeneralPipelines, RenderTheSameImage) {
  // The Cornell box (Lambertian: GGX compiled out when specialized) and a scene without emitters lit by the
  // background (no light-sampling code and no shadow stage when specialized).
  const std::string scene = GetParam().path;
  if (!std::filesystem::exists(scene)) GTEST_SKIP() << "no " << scene;
  RenderOptions o;
  o.scenePath = scene;
  o.width = 32;
  o.height = 32;
  o.spp = 64;
  o.progress = false;
  o.background = glm::vec3(0.5f);
  o.seed = 5;
  o.estimator.replicates = 4;  // the per-pixel test below needs more than the default's 1 dof a pixel
  ExrImage a = filmToImage(runRender(context(), o).film);
  o.specialize = false;
  o.seed = 6;
  RenderOutcome general = runRender(context(), o);
  ErrorMetrics m = compareImages(filmToImage(general.film), a);
  EXPECT_EQ(m.zTestPassFraction, 1.0) << scene;
  EXPECT_TRUE(withinSigmas(zTest(m.meanDifference, 0.0, std::sqrt(m.mse / (3.0 * 32 * 32))), 5.0)) << scene;
}

INSTANTIATE_TEST_SUITE_P(RenderRobustness, SpecializedAndGeneralPipelines,
                         ::testing::Values(NamedScene{"cornell_box", std::string(VKMC_SOURCE_DIR) + "/scenes/cornell_box.gltf"},
                                           NamedScene{"shared_Box", std::string(VKMC_SHARED_SCENES) + "/Box/Box.gltf"}),
                         [](const auto& info) { return info.param.name; });

TEST(RenderRobustness, NonFiniteValuesAreCountedByTheStageThatProducedThem) {
  // A finite but enormous emitter (3e38): light-sample contributions overflow to infinity inside shade. They
  // are counted there, and every sample they reach is excluded by accumulate, never written.
  Scene s;
  Material wall;
  wall.baseColor = glm::vec3(0.5f);
  Material hot;
  hot.emission = glm::vec3(3e38f);
  // Double-sided: the camera, below the emitter's plane, must see it (a single-sided one is culled from there);
  // the overflowing light samples are the ones taken on the emitter itself.
  hot.doubleSided = true;
  s.materials = {wall, hot};
  test::addQuad(s, glm::vec3(-2, -2, 0), glm::vec3(4, 0, 0), glm::vec3(0, 4, 0), 0);
  test::addQuad(s, glm::vec3(-0.5f, 0.5f, 1), glm::vec3(0, 0, 1), glm::vec3(1, 0, 0),
                1);  // faces +y, at right angles to the wall
  RenderOptions o = smallOptions("stage-nonfinite");
  o.lookFrom = glm::vec3(0, 0, 5);
  o.lookAt = glm::vec3(0, 0, 0);
  RenderOutcome r = runRender(context(), o, s);
  EXPECT_GT(r.stats.nonfiniteLightSamples, 0u);
  EXPECT_GT(r.film.totalNonfinite(), 0u);
  bool finiteImage = true;
  for (size_t p = 0; p < r.film.pixels(); ++p)
    finiteImage &= std::isfinite(r.film.mean(p, 0)) && std::isfinite(r.film.varianceOfMean(p, 0));
  EXPECT_TRUE(finiteImage);
  test::stabilityRow("10", "emission 3e38: light samples overflowing in shade (count), samples excluded (count)",
                     "> 0 counted, image finite", double(r.stats.nonfiniteLightSamples), double(r.film.totalNonfinite()),
                     r.stats.nonfiniteLightSamples > 0 && finiteImage);
}

// A stack of 16k thin parallel layers in the Cornell box: a ray across it meets every layer's box, so the walk
// down to the nearest layer pushes 3 entries per level of the 4-wide tree, past the 12-entry register stack,
// then culls the rest (a short walk, unlike a pile of coincident triangles, which would meet llvmpipe's loop
// limit in the megakernel). The wavefront defers those walks to its deep passes (intersect and shadow), the
// megakernel starts them over inline; both must give the same image, with no walk lost.
TEST(RenderRobustness, WalksThatOutgrowTheRegisterStackRenderTheSameInBothIntegrators) {
  Scene scene = loadGltf(std::string(VKMC_SOURCE_DIR) + "/scenes/cornell_box.gltf");
  const glm::vec3 c = scene.bounds.center(), a = 0.15f * scene.bounds.extent();
  // Layers across z, so that each has a flat box and the walk culls the layers behind the nearest hit.
  const glm::vec3 tri[3] = {c - a, c + glm::vec3(a.x, -a.y, -a.z), c + glm::vec3(-a.x, a.y, -a.z)};
  const glm::vec3 n(0.0f, 0.0f, 1.0f);
  const int layers = 16384;
  const glm::vec3 spacing = n * (a.z / float(layers));
  for (int i = 0; i < layers; ++i) {
    for (const glm::vec3& v : tri) {
      scene.positions.push_back(v + float(i) * spacing);
      scene.normals.push_back(n);
    }
    scene.materialIds.push_back(scene.materialIds.front());
    scene.bounds.grow(tri[0] + float(i) * spacing);
  }
  RenderOptions o = smallOptions("pile");
  o.spp = 32;
  RenderOutcome wave = runRender(context(), o, scene);
  o.integrator = Integrator::Megakernel;
  o.seed += 1;
  RenderOutcome mega = runRender(context(), o, scene);
  EXPECT_GT(wave.stats.deepWalks, 100u) << "the stack should send walks to the deep passes";
  EXPECT_EQ(wave.stats.deepWalksTraced, wave.stats.deepWalks) << "every deferred walk is traced by a deep pass";
  EXPECT_EQ(wave.stats.traversalsCut, 0u);
  EXPECT_EQ(mega.stats.traversalsCut, 0u);
  // Independent seeds: with layers 1e-5 apart an ulp can flip a roulette decision, so the same seed does not
  // promise the same image here (it does in the test below); every pixel must agree within noise.
  ErrorMetrics m = compareImages(filmToImage(mega.film), filmToImage(wave.film));
  EXPECT_EQ(m.zTestPassFraction, 1.0);
}

// The megakernel runs the wavefront's stage functions with the same random-number streams, so with the same seed
// it must trace the very same paths: the same ray counts, and the same image up to float summation order. Then a
// second seed: the same image within noise (per-pixel z-test). Cornell box (NEE + MIS), Veach's MIS scene
// (glossy), four light samples per hit with fixed roulette, and camera-ray roulette.
TEST_P(MegakernelAndWavefront, RenderTheSameImage) {
  const IntegratorCase& v = GetParam();
  RenderOptions o;
  o.scenePath = std::string(VKMC_SOURCE_DIR) + "/scenes/" + v.scene;
  o.width = 32;
  o.height = 32;
  o.spp = 32;
  o.progress = false;
  o.seed = 5;
  // 4 replicates: the per-pixel test below needs more than the 1 degree of freedom of the default 2 (whose two
  // replicate means can agree exactly where a pixel's values are discrete, e.g. a lamp's edge crossing it).
  o.estimator.replicates = 4;
  o.estimator.applyJson(nlohmann::json::parse(v.estimator));
  RenderOutcome wave = runRender(context(), o);
  o.integrator = Integrator::Megakernel;
  RenderOutcome mega = runRender(context(), o);
  std::string what = std::string(v.scene) + " " + v.estimator;
  EXPECT_EQ(mega.stats.cameraRays, wave.stats.cameraRays) << what;
  EXPECT_EQ(mega.stats.extensionRays, wave.stats.extensionRays) << what;
  EXPECT_EQ(mega.stats.shadowRays, wave.stats.shadowRays) << what;
  size_t differ = 0;
  for (size_t p = 0; p < wave.film.pixels(); ++p)
    for (int c = 0; c < 3; ++c) {
      double a = wave.film.mean(p, c), b = mega.film.mean(p, c);
      differ += std::abs(a - b) > 1e-4 * (std::abs(a) + std::abs(b)) + 1e-7;
    }
  EXPECT_EQ(differ, 0u) << what << ": pixels that differ beyond summation order";
  o.seed = 6;
  ErrorMetrics m = compareImages(filmToImage(runRender(context(), o).film), filmToImage(wave.film));
  EXPECT_EQ(m.zTestPassFraction, 1.0) << what;
}

INSTANTIATE_TEST_SUITE_P(
    RenderRobustness, MegakernelAndWavefront,
    ::testing::Values(IntegratorCase{"cornell_box", "cornell_box.gltf", "{}"},
                      IntegratorCase{"veach_mis", "veach_mis.gltf", "{}"},
                      IntegratorCase{"cornell_box_light_splitting_fixed_rr_shadow_rr", "cornell_box.gltf",
                                     R"({"light_samples": 4, "split_depth": 2, "rr": "fixed", "rr_q": 0.3, "shadow_rr": 0.1})"},
                      IntegratorCase{"furnace_camera_rr_efficiency_rr", "furnace.gltf",
                                     R"({"camera_rr": 0.5, "rr": "efficiency"})"}),
    [](const auto& info) { return std::string(info.param.name); });

// Scenes whose 4-wide BVH has at most 4 inner nodes on a path cannot outgrow the walk's 12-entry register stack, so
// their kernels leave the deep passes out (walksCanOutgrowRegisterStack); a walk that still overflowed would be
// reported as cut. many_lights sits on the bound (4 levels: 12 entries). veach_mis (7 levels) keeps them.
struct DeepPassCase {
  std::string name;
  bool deepPasses;
  Integrator integrator;
};
void PrintTo(const DeepPassCase& c, std::ostream* os) { *os << c.name; }
class DeepWalkPasses : public ::testing::TestWithParam<DeepPassCase> {};

TEST_P(DeepWalkPasses, AreLeftOutOnlyWhereNoWalkCanNeedThem) {
  const DeepPassCase& c = GetParam();
  RenderOptions o = smallOptions(std::string(VKMC_SOURCE_DIR) + "/scenes/" + c.name + ".gltf");
  o.width = 64;
  o.height = 64;
  o.spp = 16;
  o.integrator = c.integrator;
  RenderOutcome r = runRender(context(), o);
  EXPECT_EQ(r.features.deepWalks, c.deepPasses);
  EXPECT_EQ(walksCanOutgrowRegisterStack(r.bvh), c.deepPasses);
  EXPECT_EQ(r.stats.traversalsCut, 0u);
  if (!c.deepPasses) {
    EXPECT_EQ(r.stats.deepWalks, 0u);
  }
  EXPECT_GT(r.stats.rays(), 64u * 64u * 16u);
}

INSTANTIATE_TEST_SUITE_P(RenderRobustness, DeepWalkPasses,
                         ::testing::Values(DeepPassCase{"cornell_box", false, Integrator::Wavefront},
                                           DeepPassCase{"cornell_box", false, Integrator::Megakernel},
                                           DeepPassCase{"many_lights", false, Integrator::Wavefront},
                                           DeepPassCase{"two_rooms", false, Integrator::Wavefront},
                                           DeepPassCase{"veach_mis", true, Integrator::Wavefront}),
                         [](const auto& info) {
                           return info.param.name + (info.param.integrator == Integrator::Megakernel ? "_megakernel" : "");
                         });

// Splitting draws its slots from the path pool, which fills within a pass (slots are handed out over all of its
// bounces). A vertex that finds it full goes on unsplit (q = 1: unbiased, fewer splits than asked), and is counted:
// none without splitting, none where the pool holds every split (two ways at the first vertex), many where it
// cannot (16 ways at three vertices), and the image keeps its mean.
TEST(RenderRobustness, SplitsAFullPathPoolRefusesAreCountedAndKeepTheMean) {
  EstimatorConfig none, fits, overflows;
  fits.bsdfSamples = 2.0f;
  fits.splitDepth = 1;
  overflows.bsdfSamples = 16.0f;
  overflows.splitDepth = 3;
  RenderOutcome plain = test::renderWith("cornell_box.gltf", none, 16, 16, 64, 7);
  RenderOutcome fitted = test::renderWith("cornell_box.gltf", fits, 16, 16, 64, 8);
  RenderOutcome refused = test::renderWith("cornell_box.gltf", overflows, 16, 16, 64, 9);
  EXPECT_EQ(plain.stats.splitsRefused, 0u);
  EXPECT_EQ(fitted.stats.splitsRefused, 0u);
  EXPECT_GT(refused.stats.splitsRefused, 0u);
  const test::RegionStats a = test::whole(plain.film), b = test::whole(refused.film);
  for (int c = 0; c < 3; ++c)
    EXPECT_TRUE(withinSigmas(zTest2(a.mean[c], a.variance[c], b.mean[c], b.variance[c]), 4.5))
        << "channel " << c << ": " << a.mean[c] << " against " << b.mean[c];
}
