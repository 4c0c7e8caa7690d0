// Filter importance sampling (shaders/shared/pixel_filter.h), run as C++ from the shared header: the sampled points
// follow |f| (chi-square on a 2D grid against the exact filter, not the table), and the weights make the
// estimator unbiased for the filter: E[w] = 1 (a constant image stays constant) and E[w g(x)] = integral f g /
// integral f for g(x) = x^2 and a step (the filtered edge, negative lobes included).
#include <gtest/gtest.h>

#include <cmath>

#include "../shaders/shared/pixel_filter.h"
#include "../shaders/shared/rng.h"
#include "render/pixel_filter_table.h"
#include "support/chi2.h"
#include "support/param_name.h"
#include "support/z_test.h"

using namespace vkmc;
using namespace vkmc::gpu;

namespace {
constexpr uint32_t kSamples = 1000000;
constexpr int kGrid = 21, kSubdiv = 16;

std::vector<PixelFilter> filters() {
  return {pixelFilterFromName("gaussian"), pixelFilterFromName("mitchell"), pixelFilterFromName("blackman-harris"),
          pixelFilterFromName("box", 1.0), pixelFilterFromName("mitchell", 1.0)};
}
int tests() { return static_cast<int>(filters().size()); }

vec2 u2(uint32_t i, uint32_t stream) {
  uint key = pathKey(stream, i, 0u);
  return vec2(randomUnit(key, 0u), randomUnit(key, 1u));
}

// Integral of f1 * g over [-r, r] by Simpson (8192 intervals), g a function of x.
template <typename G>
double filterMoment(const PixelFilterHeader& h, G g) {
  constexpr int n = 8192;
  const double r = h.radius, w = 2 * r / n;
  double sum = 0;
  for (int i = 0; i <= n; ++i) {
    double x = -r + i * w;
    sum += pixelFilter1D(h, float(x)) * g(x) * (i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0));
  }
  return sum * w / 3;
}
}  // namespace

class PixelFilterSampling : public ::testing::TestWithParam<PixelFilter> {};

TEST_P(PixelFilterSampling, PointsFollowTheAbsoluteFilter) {
  const PixelFilterTable t = buildPixelFilterTable(GetParam());
  const float r = t.header.radius;
  std::vector<double> observed(kGrid * kGrid, 0.0), expected(kGrid * kGrid, 0.0);
  for (uint32_t i = 0; i < kSamples; ++i) {
    FilterSample s = samplePixelFilterTable(t.table.data(), t.header, u2(i, 77));
    vec2 o = s.point - vec2(0.5f);
    ASSERT_TRUE(std::abs(o.x) <= r && std::abs(o.y) <= r) << "a point outside the filter's support";
    int cx = std::min(kGrid - 1, int((o.x + r) / (2 * r) * kGrid)), cy = std::min(kGrid - 1, int((o.y + r) / (2 * r) * kGrid));
    observed[cy * kGrid + cx] += 1.0;
  }
  // Expected counts from the exact |f| (separable: the cell's mass is the product of the axes' masses).
  std::vector<double> axis(kGrid, 0.0);
  double total = 0.0;
  for (int c = 0; c < kGrid; ++c) {
    for (int k = 0; k < kSubdiv; ++k) {
      double x = -r + (c * kSubdiv + k + 0.5) * (2.0 * r / (kGrid * kSubdiv));
      axis[c] += std::abs(pixelFilter1D(t.header, float(x)));
    }
    total += axis[c];
  }
  for (int y = 0; y < kGrid; ++y)
    for (int x = 0; x < kGrid; ++x) expected[y * kGrid + x] = axis[x] * axis[y] / (total * total) * kSamples;
  auto res = test::chi2FromCounts(observed, expected);
  EXPECT_GT(res.pValue, test::sidakLevel(tests())) << res.table;
}

TEST_P(PixelFilterSampling, WeightsMakeTheFilteredEstimateUnbiased) {
  const PixelFilterTable t = buildPixelFilterTable(GetParam());
  const double integral = pixelFilterIntegral(t.header);
  // g(x, y) = 1, x^2, and a step at x = -0.7 r (reaching into Mitchell's negative lobe).
  const double edge = -0.7 * t.header.radius;
  auto step = [&](double x) { return x < edge ? 1.0 : 0.0; };
  const double expected[3] = {1.0, filterMoment(t.header, [](double x) { return x * x; }) / integral,
                              filterMoment(t.header, step) / integral};
  double sum[3] = {0, 0, 0}, sumSq[3] = {0, 0, 0};
  for (uint32_t i = 0; i < kSamples; ++i) {
    FilterSample s = samplePixelFilterTable(t.table.data(), t.header, u2(i, 91));
    double x = s.point.x - 0.5;
    double v[3] = {s.weight, s.weight * x * x, s.weight * step(x)};
    for (int k = 0; k < 3; ++k) sum[k] += v[k], sumSq[k] += v[k] * v[k];
  }
  if (GetParam().kind == kPixelFilterMitchell) {
    EXPECT_LT(expected[2], 0.0) << "the step's filtered value is in the lobe";
  }
  for (int k = 0; k < 3; ++k) {
    double mean = sum[k] / kSamples, var = (sumSq[k] / kSamples - mean * mean) / kSamples;
    EXPECT_TRUE(test::withinSigmas(test::zTest(mean, expected[k], std::sqrt(var), 1e-6), 5.0))
        << "moment " << k << ": " << mean << " against " << expected[k];
  }
}

INSTANTIATE_TEST_SUITE_P(Filters, PixelFilterSampling, ::testing::ValuesIn(filters()),
                         [](const auto& info) { return test::paramName(pixelFilterSummary(info.param)); });
