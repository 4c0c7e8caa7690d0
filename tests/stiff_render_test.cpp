// Stiff cases rendered against analytic answers; rows go to the stability table (tools/stability_table.sh).
#include <gtest/gtest.h>

#include "render_helpers.h"
#include "stability_row.h"

using namespace vkmc;
using namespace vkmc::test;

namespace {
// Stiff case 2: L(x, z) = rho / pi * Le * A * h^2 / (h^2 + x^2 + z^2)^2, averaged over pixel (i, j)'s footprint
// (x in -1 + 2 [i, i + 1] / n, z likewise with j: the orthographic camera of scenes/stiff/tiny_light.gltf).
double tinyLightPixel(uint32_t i, uint32_t j, uint32_t n) {
  const int sub = 64;
  double sum = 0;
  for (int a = 0; a < sub; ++a)
    for (int b = 0; b < sub; ++b) {
      double x = -1 + 2 * (i + (a + 0.5) / sub) / n, z = -1 + 2 * (j + (b + 0.5) / sub) / n, d2 = 1 + x * x + z * z;
      sum += 0.5 / 3.14159265358979323846 * 1e6 * 1e-6 / (d2 * d2);
    }
  return sum / (sub * sub);
}
}  // namespace

TEST(StiffRender, TinyIntenseLightMatchesTheAnalyticRadiance) {
  const uint32_t n = 16;
  RenderOutcome r = renderWith("stiff/tiny_light.gltf", EstimatorConfig{}, n, n, 256);
  ASSERT_EQ(r.film.totalNonfinite(), 0u);
  double expectedMean = 0;
  for (uint32_t j = 0; j < n; ++j)
    for (uint32_t i = 0; i < n; ++i) expectedMean += tinyLightPixel(i, j, n) / (n * n);
  RegionStats s = whole(r.film);
  double z = (s.mean.x - expectedMean) / std::sqrt(s.variance.x);
  EXPECT_LT(std::abs(z), 3.0) << "image mean " << s.mean.x << " expected " << expectedMean;
  stabilityRow("2", "tiny intense light (1 mm^2, Le 1e6): image mean", std::to_string(expectedMean), s.mean.x, std::sqrt(s.variance.x),
               std::abs(z) < 3.0);
  for (auto [i, j] : {std::pair{8u, 8u}, std::pair{3u, 12u}, std::pair{0u, 0u}}) {
    size_t p = size_t(j) * n + i;
    double expected = tinyLightPixel(i, j, n), sigma = std::sqrt(r.film.varianceOfMean(p, 0));
    double zp = (r.film.mean(p, 0) - expected) / sigma;
    EXPECT_LT(std::abs(zp), 3.0) << "pixel " << i << "," << j;
    stabilityRow("2", "tiny intense light: pixel (" + std::to_string(i) + "," + std::to_string(j) + ")", std::to_string(expected),
                 r.film.mean(p, 0), sigma, std::abs(zp) < 3.0);
  }
  // BSDF sampling alone finds a 1e-6 sr light about once in ten million samples: the estimate stays finite and
  // non-negative (nearly black) and its sampled variance is no evidence of accuracy, which the report shows.
  EstimatorConfig off;
  off.nee = false;
  RenderOutcome b = renderWith("stiff/tiny_light.gltf", off, n, n, 64);
  EXPECT_EQ(b.film.totalNonfinite(), 0u);
  EXPECT_GE(whole(b.film).mean.x, 0.0);
  EXPECT_LT(whole(b.film).mean.x, expectedMean);
  stabilityRow("2", "tiny intense light, NEE off (64 spp): finite, practically black", "finite, <= " + std::to_string(expectedMean),
               whole(b.film).mean.x, std::sqrt(whole(b.film).variance.x), b.film.totalNonfinite() == 0);
}
