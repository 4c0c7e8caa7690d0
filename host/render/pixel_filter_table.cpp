// The pixel filter's sampling table: |f1| at evenly spaced nodes, normalized to a density, and its cdf.
#include "render/pixel_filter_table.h"

#include <cmath>
#include <cstring>

#include "../shaders/shared/pixel_filter.h"
#include "error.h"

namespace vkmc {

gpu::PixelFilterHeader pixelFilterHeader(const PixelFilter& f) {
  gpu::PixelFilterHeader h{};
  h.kind = f.kind;
  h.radius = f.radius;
  h.invIntegral = 1.0f;
  if (f.kind == gpu::kPixelFilterGaussian) {
    const float s = kGaussianFilterSigma;
    h.params = glm::vec4(s, std::exp(-f.radius * f.radius / (2.0f * s * s)), 0.0f, 0.0f);
  }
  if (f.kind == gpu::kPixelFilterMitchell) h.params = glm::vec4(kMitchellFilterB, kMitchellFilterC, 0.0f, 0.0f);
  return h;
}

double pixelFilterIntegral(const gpu::PixelFilterHeader& h, bool absolute) {
  constexpr int kIntervals = 8192;
  const double r = h.radius, w = 2.0 * r / kIntervals;
  double sum = 0.0;
  for (int i = 0; i <= kIntervals; ++i) {
    double f = gpu::pixelFilter1D(h, static_cast<float>(-r + i * w));
    if (absolute) f = std::abs(f);
    sum += f * (i == 0 || i == kIntervals ? 1.0 : (i % 2 ? 4.0 : 2.0));
  }
  return sum * w / 3.0;
}

PixelFilterTable buildPixelFilterTable(const PixelFilter& filter) {
  validatePixelFilter(filter);
  PixelFilterTable t;
  t.header = pixelFilterHeader(filter);
  const double integral = pixelFilterIntegral(t.header);
  if (!(integral > 0.0) || !std::isfinite(integral)) throw Error("the pixel filter integrates to " + std::to_string(integral));
  t.header.invIntegral = static_cast<float>(1.0 / integral);

  constexpr uint32_t n = gpu::kPixelFilterIntervals;
  const double r = filter.radius, w = 2.0 * r / n;
  std::vector<double> node(n + 1), cdf(n + 1, 0.0);
  for (uint32_t i = 0; i <= n; ++i) node[i] = std::abs(gpu::pixelFilter1D(t.header, static_cast<float>(-r + i * w)));
  for (uint32_t i = 0; i < n; ++i) cdf[i + 1] = cdf[i] + 0.5 * w * (node[i] + node[i + 1]);
  const double total = cdf[n];
  if (!(total > 0.0)) throw Error("the pixel filter's table is empty");
  t.table.resize(gpu::pixelFilterTableSize());
  for (uint32_t i = 0; i <= n; ++i) {
    t.table[i] = static_cast<float>(cdf[i] / total);
    t.table[gpu::pixelFilterPdfOffset() + i] = static_cast<float>(node[i] / total);
  }
  t.table[n] = 1.0f;
  return t;
}

std::vector<float> pixelFilterBufferData(const PixelFilterTable& t) {
  static_assert(sizeof(gpu::PixelFilterHeader) % sizeof(float) == 0);
  std::vector<float> data(sizeof(gpu::PixelFilterHeader) / sizeof(float) + t.table.size());
  std::memcpy(data.data(), &t.header, sizeof(t.header));
  std::memcpy(data.data() + sizeof(t.header) / sizeof(float), t.table.data(), t.table.size() * sizeof(float));
  return data;
}

}  // namespace vkmc
