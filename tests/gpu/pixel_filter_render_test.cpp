// Pixel filters in renders (shaders/include/pixel_filter.glsl, accumulate's weight): the furnace stays 2 with every
// filter and both integrators; a sharp emitter edge renders as the filter's integral across it, Mitchell's
// negative lobe included (an exact per-column prediction from the shared filter function, so this checks the
// GLSL sampler and the film's handling of negative samples); the box is the default's plain jitter.
#include <gtest/gtest.h>

#include "../shaders/shared/pixel_filter.h"
#include "render/pixel_filter_table.h"
#include "support/param_name.h"
#include "support/render_helpers.h"

using namespace vkmc;
using namespace vkmc::test;
using vkmc::gpu::pixelFilter1D;
using vkmc::gpu::PixelFilterHeader;

namespace {
struct FilterCase {
  PixelFilter filter;
  Integrator integrator;
};
std::string caseName(const FilterCase& c) { return paramName(pixelFilterSummary(c.filter) + " " + toString(c.integrator)); }

std::vector<FilterCase> cases() {
  return {{pixelFilterFromName("gaussian"), Integrator::Wavefront},
          {pixelFilterFromName("mitchell"), Integrator::Wavefront},
          {pixelFilterFromName("mitchell"), Integrator::Megakernel},
          {pixelFilterFromName("blackman-harris"), Integrator::Wavefront},
          {pixelFilterFromName("box", 1.0), Integrator::Wavefront}};
}

// An emitter of radiance 1 over x < 0 in the plane z = 0, black elsewhere and reflecting nothing: every sample is
// exactly 1 or 0, and the edge projects to the image's middle column boundary.
Scene edgeScene() {
  Scene s;
  Material m;
  m.baseColor = glm::vec3(0.0f);
  m.metallic = 0.0f;
  m.specular = 0.0f;
  m.emission = glm::vec3(1.0f);
  s.materials.push_back(m);
  addQuad(s, glm::vec3(-10.0f, -10.0f, 0.0f), glm::vec3(10.0f, 0.0f, 0.0f), glm::vec3(0.0f, 20.0f, 0.0f), 0);
  return s;
}

// The filtered step at a pixel centre t pixels left of the edge: integral of f1 up to t over its integral.
double filteredStep(const PixelFilterHeader& h, double t) {
  constexpr int n = 4096;
  const double r = h.radius, hi = std::clamp(t, -r, r), w = (hi + r) / n;
  double sum = 0;
  for (int i = 0; i <= n; ++i) sum += pixelFilter1D(h, float(-r + i * w)) * (i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0));
  return sum * w / 3 / pixelFilterIntegral(h);
}
}  // namespace

class PixelFilterRender : public ::testing::TestWithParam<FilterCase> {};

TEST_P(PixelFilterRender, FurnaceStaysTwo) {
  RenderOptions o;
  o.scenePath = scenePath("furnace.gltf");
  o.width = 16, o.height = 16, o.spp = 256, o.seed = 99, o.progress = false;
  o.filter = GetParam().filter;
  o.integrator = GetParam().integrator;
  // Pixel by pixel at 5 sigma needs many-dof variances (sobol's 1 by default, 3 with 4 replicates, would widen the bound to 157
  // sigma or more).
  o.estimator.sampler = Sampler::Independent;
  RenderOutcome r = runRender(sharedContext(), o);
  ASSERT_EQ(r.film.totalNonfinite(), 0u);
  EXPECT_TRUE(regionMatches(whole(r.film), glm::dvec3(2.0), 5.0)) << "image mean";
  int outside = 0;
  for (size_t p = 0; p < r.film.pixels(); ++p)
    for (int c = 0; c < 3; ++c) outside += !pixelMatches(r.film, p, c, 2.0, 5.0);
  EXPECT_EQ(outside, 0) << "pixel channels beyond 5 sigma (Student's bound for their dof)";
}

TEST_P(PixelFilterRender, EdgeIsTheFiltersIntegral) {
  constexpr uint32_t kSide = 16;
  RenderOptions o;
  o.scenePath = "in-memory edge";
  o.width = kSide, o.height = kSide, o.spp = 512, o.seed = 7, o.progress = false;
  o.lookFrom = glm::vec3(0.0f, 0.0f, 1.0f);
  o.lookAt = glm::vec3(0.0f);
  o.fovDegrees = 40.0f;
  o.filter = GetParam().filter;
  o.integrator = GetParam().integrator;
  RenderOutcome r = runRender(sharedContext(), o, edgeScene());
  ASSERT_EQ(r.film.totalNonfinite(), 0u);
  const PixelFilterHeader h = pixelFilterHeader(o.filter);
  bool lobes = false;  // Mitchell's: a column below 0 beside the edge, one above 1 across it
  for (uint32_t c = 0; c < kSide; ++c) {
    const double expected = filteredStep(h, kSide / 2.0 - (c + 0.5));
    RegionStats column = region(r.film, c, 0, c + 1, kSide);
    EXPECT_TRUE(regionMatches(column, glm::dvec3(expected), 5.0))
        << "column " << c << ": " << column.mean.x << " against " << expected;
    if (expected < -0.005) {
      lobes = true;
      EXPECT_LT(column.mean.x, 0.0) << "column " << c << " lies in the negative lobe";
    }
    if (expected > 1.005) {
      EXPECT_GT(column.mean.x, 1.0) << "column " << c << " overshoots";
    }
  }
  EXPECT_EQ(lobes, o.filter.kind == gpu::kPixelFilterMitchell);
}

INSTANTIATE_TEST_SUITE_P(Filters, PixelFilterRender, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return caseName(info.param); });

TEST(PixelFilterRender, PixelBoxIsThePlainJitter) {
  // The default and an explicit box of radius 0.5 are the same render, bit for bit; the edge's columns are then
  // exactly 1 and 0 (every sample lands in its own pixel).
  RenderOptions o;
  o.scenePath = "in-memory edge";
  o.width = 8, o.height = 8, o.spp = 16, o.seed = 7, o.progress = false;
  o.lookFrom = glm::vec3(0.0f, 0.0f, 1.0f);
  o.lookAt = glm::vec3(0.0f);
  RenderOutcome a = runRender(sharedContext(), o, edgeScene());
  o.filter = pixelFilterFromName("box", 0.5);
  RenderOutcome b = runRender(sharedContext(), o, edgeScene());
  for (size_t p = 0; p < a.film.pixels(); ++p)
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(a.film.mean(p, c), b.film.mean(p, c));
      ASSERT_EQ(a.film.mean(p, c), p % 8 < 4 ? 1.0 : 0.0) << "pixel " << p;
    }
}
