// The pixel filters (shaders/shared/pixel_filter.h, host/render/pixel_filter*.cpp): their rows and parsing, the
// filter functions against closed forms, the sampling table, and the sample/pdf/inverse triple's round trips.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "../shaders/shared/pixel_filter.h"
#include "error.h"
#include "render/pixel_filter.h"
#include "render/pixel_filter_table.h"
#include "support/param_name.h"

using namespace vkmc;
using namespace vkmc::gpu;

namespace {
constexpr double kPiD = 3.14159265358979323846;

const std::vector<PixelFilter>& tabulatedFilters() {
  static const std::vector<PixelFilter> filters = {pixelFilterFromName("gaussian"),        pixelFilterFromName("mitchell"),
                                                   pixelFilterFromName("blackman-harris"), pixelFilterFromName("box", 1.0),
                                                   pixelFilterFromName("mitchell", 0.75),  pixelFilterFromName("gaussian", 3.0)};
  return filters;
}
std::string label(const PixelFilter& f) { return pixelFilterSummary(f); }
}  // namespace

TEST(PixelFilter, DefaultsArePbrtV4s) {
  EXPECT_TRUE(PixelFilter{}.isPixelBox());
  EXPECT_EQ(PixelFilter{}.specSampling(), kPixelFilterSamplingUniform);
  EXPECT_EQ(pixelFilterFromName("box").radius, 0.5f);
  EXPECT_EQ(pixelFilterFromName("gaussian").radius, 1.5f);
  EXPECT_EQ(pixelFilterFromName("mitchell").radius, 2.0f);
  EXPECT_EQ(pixelFilterFromName("blackman-harris").radius, 2.0f);
  EXPECT_EQ(pixelFilterFromName("mitchell", 3.0).radius, 3.0f);
  EXPECT_FALSE(pixelFilterFromName("box", 1.0).isPixelBox()) << "a wider box is sampled from the table";
  EXPECT_EQ(pixelFilterFromName("box", 1.0).specSampling(), kPixelFilterSamplingTable);
  for (const PixelFilterRow& r : pixelFilterRows()) EXPECT_EQ(std::string(pixelFilterName(r.kind)), r.name);
}

TEST(PixelFilter, BadNamesAndRadiiAreRefusedWithOneLine) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(pixelFilterFromName("lanczos"), Error);
  EXPECT_THROW(pixelFilterFromName(""), Error);
  EXPECT_THROW(pixelFilterFromName("Box"), Error);
  for (double r : {0.0, -1.0, nan, inf, 16.5, 1e30}) EXPECT_THROW(pixelFilterFromName("mitchell", r), Error) << r;
  EXPECT_NO_THROW(pixelFilterFromName("mitchell", 16.0));
  EXPECT_THROW(validatePixelFilter(PixelFilter{7u, 1.0f}), Error);
  try {
    pixelFilterFromName("lanczos");
  } catch (const Error& e) {
    std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos);
    EXPECT_NE(m.find("blackman-harris"), std::string::npos) << "the message lists the filters";
  }
}

TEST(PixelFilter, JsonRoundTripsAndRefusesUnknownKeys) {
  PixelFilter f = pixelFilterFromJson({{"name", "mitchell"}, {"radius", 1.5}});
  EXPECT_EQ(f.kind, kPixelFilterMitchell);
  EXPECT_EQ(f.radius, 1.5f);
  EXPECT_EQ(pixelFilterFromJson({{"name", "gaussian"}}).radius, 1.5f);
  nlohmann::json echo = pixelFilterJson(f);
  EXPECT_EQ(echo["name"], "mitchell");
  EXPECT_EQ(pixelFilterFromJson({{"name", echo["name"]}, {"radius", echo["radius"]}}).radius, 1.5f);
  EXPECT_THROW(pixelFilterFromJson({{"name", "mitchell"}, {"radius", "2"}}), Error);
  EXPECT_THROW(pixelFilterFromJson({{"name", "mitchell"}, {"sigma", 2}}), Error);
  EXPECT_THROW(pixelFilterFromJson("mitchell"), Error);
  EXPECT_THROW(pixelFilterFromJson({{"name", "mitchell"}, {"radius", -2}}), Error);
}

TEST(PixelFilter, FunctionsMatchTheirDefinitions) {
  PixelFilterHeader g = pixelFilterHeader(pixelFilterFromName("gaussian"));
  const double gR = std::exp(-1.5 * 1.5 / (2 * 0.25));
  EXPECT_NEAR(pixelFilter1D(g, 0.0f), 1.0 - gR, 1e-6);
  EXPECT_NEAR(pixelFilter1D(g, 0.7f), std::exp(-0.49 / 0.5) - gR, 1e-6);
  EXPECT_EQ(pixelFilter1D(g, 1.5f), 0.0f) << "pbrt-v4's Gaussian is shifted to 0 at the radius";
  EXPECT_EQ(pixelFilter1D(g, 1.6f), 0.0f);

  // Mitchell-Netravali, B = C = 1/3 over [-2, 2] scaled to radius 2: 8/9 at 0, 1/18 at 1, zero at 8/7 and 2,
  // negative in between.
  PixelFilterHeader m = pixelFilterHeader(pixelFilterFromName("mitchell"));
  EXPECT_NEAR(pixelFilter1D(m, 0.0f), 8.0 / 9.0, 1e-6);
  EXPECT_NEAR(pixelFilter1D(m, 1.0f), 1.0 / 18.0, 1e-6);
  EXPECT_NEAR(pixelFilter1D(m, 8.0f / 7.0f), 0.0, 1e-6);
  EXPECT_LT(pixelFilter1D(m, 1.5f), 0.0f);
  EXPECT_LT(pixelFilter1D(m, -1.5f), 0.0f);
  EXPECT_NEAR(pixelFilter1D(m, 2.0f), 0.0, 1e-6);  // the cubic in float
  PixelFilterHeader m1 = pixelFilterHeader(pixelFilterFromName("mitchell", 1.0));
  EXPECT_NEAR(pixelFilter1D(m1, 0.5f), 1.0 / 18.0, 1e-6) << "scaled to the radius";

  PixelFilterHeader bh = pixelFilterHeader(pixelFilterFromName("blackman-harris"));
  EXPECT_NEAR(pixelFilter1D(bh, 0.0f), 1.0, 1e-6);
  EXPECT_NEAR(pixelFilter1D(bh, 2.0f), 0.35875 - 0.48829 + 0.14128 - 0.01168, 1e-6);
  EXPECT_NEAR(pixelFilter1D(bh, 1.0f), 0.35875 - 0.14128, 1e-6);

  PixelFilterHeader box = pixelFilterHeader(pixelFilterFromName("box", 1.0));
  EXPECT_EQ(pixelFilter1D(box, 0.99f), 1.0f);
  EXPECT_EQ(pixelFilter1D(box, 1.01f), 0.0f);
  EXPECT_EQ(pixelFilterValue(m, vec2(1.5f, 0.0f)), pixelFilter1D(m, 1.5f) * pixelFilter1D(m, 0.0f));
}

TEST(PixelFilter, IntegralsMatchClosedForms) {
  // Mitchell-Netravali integrates to 1 over [-2, 2] (any B, C), so to radius / 2; Blackman-Harris to 2 r a0.
  for (float r : {0.5f, 2.0f, 5.0f}) {
    EXPECT_NEAR(pixelFilterIntegral(pixelFilterHeader(pixelFilterFromName("mitchell", r))), r / 2.0, 1e-6 * r);
    EXPECT_NEAR(pixelFilterIntegral(pixelFilterHeader(pixelFilterFromName("blackman-harris", r))), 2.0 * r * 0.35875, 1e-6 * r);
    EXPECT_NEAR(pixelFilterIntegral(pixelFilterHeader(pixelFilterFromName("box", r))), 2.0 * r, 1e-6 * r);
    double s = 0.5, gR = std::exp(-r * r / (2 * s * s));
    double gauss = s * std::sqrt(2 * kPiD) * std::erf(r / (s * std::sqrt(2.0))) - 2 * r * gR;
    EXPECT_NEAR(pixelFilterIntegral(pixelFilterHeader(pixelFilterFromName("gaussian", r))), gauss, 1e-6);
  }
  // Mitchell's negative lobes: the integral of |f| exceeds that of f by 7% (1.07^2 = 1.145 in 2D).
  PixelFilterHeader m = pixelFilterHeader(pixelFilterFromName("mitchell"));
  EXPECT_NEAR(pixelFilterIntegral(m, true) / pixelFilterIntegral(m), 1.06997, 1e-4);
}

class PixelFilterTableTest : public ::testing::TestWithParam<PixelFilter> {};

TEST_P(PixelFilterTableTest, TableIsADensityAndItsCdf) {
  const PixelFilterTable t = buildPixelFilterTable(GetParam());
  ASSERT_EQ(t.table.size(), pixelFilterTableSize());
  EXPECT_NEAR(t.header.invIntegral, 1.0 / pixelFilterIntegral(t.header), 1e-6 / pixelFilterIntegral(t.header));
  EXPECT_EQ(t.table[0], 0.0f);
  EXPECT_EQ(t.table[kPixelFilterIntervals], 1.0f);
  const double w = 2.0 * t.header.radius / kPixelFilterIntervals;
  double mass = 0.0;
  for (uint32_t i = 0; i < kPixelFilterIntervals; ++i) {
    EXPECT_LE(t.table[i], t.table[i + 1]);
    const float a = t.table[pixelFilterPdfOffset() + i], b = t.table[pixelFilterPdfOffset() + i + 1];
    EXPECT_GE(a, 0.0f);
    mass += 0.5 * w * (a + b);
    EXPECT_NEAR(t.table[i + 1], mass, 1e-6);
  }
  EXPECT_NEAR(mass, 1.0, 1e-6);
}

TEST_P(PixelFilterTableTest, SamplesInvertAndReportTheirPdf) {
  const PixelFilterTable t = buildPixelFilterTable(GetParam());
  const float* table = t.table.data();
  const float r = t.header.radius;
  for (int k = 0; k < 4000; ++k) {
    float u = (k + 0.5f) / 4000.0f;
    float pdf = -1.0f;
    float x = samplePixelFilter1D(table, t.header, u, pdf);
    ASSERT_GE(x, -r);
    ASSERT_LE(x, r);
    EXPECT_NEAR(pdf, pixelFilter1DPdf(table, t.header, x), 1e-3f * pdf + 1e-6f) << "u " << u;
    EXPECT_NEAR(invertPixelFilter1DSample(table, t.header, x), u, 2e-5f) << "x " << x;
  }
  // The 2D sample: the point around the pixel's centre, its inverse and its weight f / (p * integral).
  FilterSample s = samplePixelFilterTable(table, t.header, vec2(0.3f, 0.8f));
  vec2 back = invertPixelFilterSample(table, t.header, s.point);
  EXPECT_NEAR(back.x, 0.3f, 2e-5f);
  EXPECT_NEAR(back.y, 0.8f, 2e-5f);
  vec2 offset = s.point - vec2(0.5f);
  EXPECT_NEAR(
      s.weight,
      pixelFilterValue(t.header, offset) / pixelFilterPdf(table, t.header, offset) * t.header.invIntegral * t.header.invIntegral,
      1e-3f * std::abs(s.weight));
}

TEST_P(PixelFilterTableTest, WeightsAreNearlyConstantInMagnitude) {
  // The table's density follows |f| closely, so |weight| stays near (integral |f| / integral f)^2 wherever |f| is
  // not tiny (f / p dips where f crosses zero or vanishes at the radius).
  const PixelFilterTable t = buildPixelFilterTable(GetParam());
  const double ratio = pixelFilterIntegral(t.header, true) / pixelFilterIntegral(t.header);
  const double expected = ratio * ratio;
  int far = 0, n = 0;
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 200; ++j, ++n) {
      FilterSample s = samplePixelFilterTable(t.table.data(), t.header, vec2((i + 0.5f) / 200, (j + 0.5f) / 200));
      ASSERT_TRUE(std::isfinite(s.weight));
      ASSERT_LE(std::abs(s.weight), 1.5 * expected);
      far += std::abs(std::abs(s.weight) / expected - 1.0) > 0.05;
    }
  EXPECT_LT(far, n / 20) << "more than 5% of the weights are off by 5%";
}

INSTANTIATE_TEST_SUITE_P(Filters, PixelFilterTableTest, ::testing::ValuesIn(tabulatedFilters()),
                         [](const auto& info) { return test::paramName(label(info.param)); });

TEST(PixelFilter, PixelBoxIsTheUniformJitterItself) {
  for (float u : {0.0f, 0.25f, 0.5f, 0.99999994f}) {
    FilterSample s = samplePixelBox(vec2(u, 1.0f - u));
    EXPECT_EQ(s.point, vec2(u, 1.0f - u));
    EXPECT_EQ(s.weight, 1.0f);
  }
}
