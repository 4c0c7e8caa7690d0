// Pixel reconstruction filters by filter importance sampling (pbrt-v4's approach): a camera sample's point is
// drawn from the filter's |f| around the pixel's centre and the sample weighs f / (p * integral of f), so the film
// stays a plain average per pixel (unbiased for the filtered image: E[weight] = 1) and filtering costs nothing
// per sample. The weight is about constant in magnitude and negative in a filter's negative lobes.
//   Filters are separable, f(x, y) = f1(x) f1(y), zero outside [-radius, radius]^2 (pixels):
//     box:              1
//     gaussian:         max(0, g(x) - g(radius)), g(x) = exp(-x^2 / (2 sigma^2)) (pbrt-v4's, shifted to 0 at the radius)
//     mitchell:         Mitchell-Netravali with B = C = 1/3 over [-2, 2] scaled to the radius (negative lobes)
//     blackman-harris:  the 4-term Blackman-Harris window over [-radius, radius]
//   Sampling: per axis from a piecewise-linear density through |f1| at kPixelFilterIntervals + 1 evenly spaced
//   nodes (so f / p is close to constant, never undefined where f is not 0), f evaluated exactly for the weight:
//   weight = f1(x) f1(y) / (p(x) p(y)) / (integral of f1)^2, as pbrt-v4's FilterSampler, whose film divides by
//   the sum of weights instead. The box of radius 1/2 needs none of it: its point is u itself, weight 1
//   (SPEC_PIXEL_FILTER = kPixelFilterSamplingUniform, the default, so default renders are the unfiltered ones).
//   Table (BINDING_PIXEL_FILTER after its PixelFilterHeader, float[]): cdf at the nodes (intervals + 1, from 0 to
//   1), then the density at the nodes (intervals + 1), both over x in [-radius, radius].
// GLSL: the including file declares the table as pixelFilterTable[]; C++ passes it as a pointer.
#ifndef VKMC_PIXEL_FILTER_H
#define VKMC_PIXEL_FILTER_H
#include "glsl_cpp.h"
#include "layout.h"
#include "sampling.h"
#ifdef __cplusplus
#define VKMC_FILTER_TABLE const float *pixelFilterTable,
#define VKMC_FILTER_TABLE_ARG pixelFilterTable,
#else
#define VKMC_FILTER_TABLE
#define VKMC_FILTER_TABLE_ARG
#endif
VKMC_BEGIN_NAMESPACE

VKMC_CONST uint kPixelFilterIntervals = 256u;  // table intervals over [-radius, radius]
VKMC_FN uint pixelFilterTableSize() { return 2u * (kPixelFilterIntervals + 1u); }
VKMC_FN uint pixelFilterPdfOffset() { return kPixelFilterIntervals + 1u; }
// Blackman-Harris (4-term, -92 dB) coefficients.
VKMC_CONST float kBlackmanHarrisA0 = 0.35875f, kBlackmanHarrisA1 = 0.48829f, kBlackmanHarrisA2 = 0.14128f,
                 kBlackmanHarrisA3 = 0.01168f;

// A camera sample's place: its point in the pixel's frame (the pixel is [0, 1]^2, its centre at 0.5) and weight.
struct FilterSample {
  vec2 point;
  float weight;
};
VKMC_FN FilterSample filterSample(vec2 point, float weight) {
  FilterSample s;
  s.point = point;
  s.weight = weight;
  return s;
}

// The default: the pixel's own box (radius 1/2), the uniform jitter u itself.
VKMC_FN FilterSample samplePixelBox(vec2 u) { return filterSample(u, 1.0f); }

// Mitchell-Netravali's cubic at |x| in [0, 2] (pbrt-v4's Mitchell1D).
VKMC_FN float mitchell1D(float x, float b, float c) {
  x = abs(x);
  if (x <= 1.0f)
    return ((12.0f - 9.0f * b - 6.0f * c) * x * x * x + (-18.0f + 12.0f * b + 6.0f * c) * x * x + (6.0f - 2.0f * b)) *
           (1.0f / 6.0f);
  if (x <= 2.0f)
    return ((-b - 6.0f * c) * x * x * x + (6.0f * b + 30.0f * c) * x * x + (-12.0f * b - 48.0f * c) * x +
            (8.0f * b + 24.0f * c)) *
           (1.0f / 6.0f);
  return 0.0f;
}

// The 1D filter f1 at offset x (pixels) from the pixel's centre; 0 beyond the radius.
VKMC_FN float pixelFilter1D(PixelFilterHeader h, float x) {
  float r = h.radius;
  if (!(abs(x) <= r)) return 0.0f;
  if (h.kind == kPixelFilterGaussian) return max(0.0f, exp(-x * x / (2.0f * h.params.x * h.params.x)) - h.params.y);
  if (h.kind == kPixelFilterMitchell) return mitchell1D(2.0f * x / r, h.params.x, h.params.y);
  if (h.kind == kPixelFilterBlackmanHarris) {
    float t = kPi * x / r;
    return kBlackmanHarrisA0 + kBlackmanHarrisA1 * cos(t) + kBlackmanHarrisA2 * cos(2.0f * t) + kBlackmanHarrisA3 * cos(3.0f * t);
  }
  return 1.0f;  // box
}
VKMC_FN float pixelFilterValue(PixelFilterHeader h, vec2 offset) {
  return pixelFilter1D(h, offset.x) * pixelFilter1D(h, offset.y);
}

// The table interval of u: the last node i < intervals with cdf[i] <= u (so never an interval of zero mass).
VKMC_FN uint pixelFilterFindInterval(VKMC_FILTER_TABLE float u) {
  uint lo = 0u, hi = kPixelFilterIntervals;
  while (hi - lo > 1u) {
    uint mid = (lo + hi) / 2u;
    if (pixelFilterTable[mid] <= u)
      lo = mid;
    else
      hi = mid;
  }
  return lo;
}

// x in [-radius, radius] with the table's piecewise-linear density p(x) (returned in pdf), by inverting its cdf:
// within an interval of width w and node densities a, b the mass up to t is w (a t + (b - a) t^2 / 2).
VKMC_FN float samplePixelFilter1D(VKMC_FILTER_TABLE PixelFilterHeader h, float u, INOUT(float) pdf) {
  uint i = pixelFilterFindInterval(VKMC_FILTER_TABLE_ARG u);
  float w = 2.0f * h.radius / float(kPixelFilterIntervals);
  float a = pixelFilterTable[pixelFilterPdfOffset() + i], b = pixelFilterTable[pixelFilterPdfOffset() + i + 1u];
  float m = max(u - pixelFilterTable[i], 0.0f) / w;  // the mass to cover in this interval, over its width
  float denominator = a + sqrt(max(a * a + 2.0f * (b - a) * m, 0.0f));
  float t = denominator > 0.0f ? clamp(2.0f * m / denominator, 0.0f, 1.0f) : 0.0f;
  pdf = mix(a, b, t);
  return -h.radius + (float(i) + t) * w;
}

// The table's density at x, and the u that samplePixelFilter1D maps to x (its cdf).
VKMC_FN float pixelFilter1DPdf(VKMC_FILTER_TABLE PixelFilterHeader h, float x) {
  if (!(abs(x) <= h.radius)) return 0.0f;
  float s = (x + h.radius) / (2.0f * h.radius) * float(kPixelFilterIntervals);
  uint i = min(uint(s), kPixelFilterIntervals - 1u);
  return mix(pixelFilterTable[pixelFilterPdfOffset() + i], pixelFilterTable[pixelFilterPdfOffset() + i + 1u], s - float(i));
}
VKMC_FN float invertPixelFilter1DSample(VKMC_FILTER_TABLE PixelFilterHeader h, float x) {
  float s = clamp((x + h.radius) / (2.0f * h.radius), 0.0f, 1.0f) * float(kPixelFilterIntervals);
  uint i = min(uint(s), kPixelFilterIntervals - 1u);
  float t = s - float(i), w = 2.0f * h.radius / float(kPixelFilterIntervals);
  float a = pixelFilterTable[pixelFilterPdfOffset() + i], b = pixelFilterTable[pixelFilterPdfOffset() + i + 1u];
  return pixelFilterTable[i] + w * t * (a + 0.5f * (b - a) * t);
}

// A filtered camera sample: the point drawn per axis, weighted f / (p * integral of f) (0 where p is 0).
VKMC_FN FilterSample samplePixelFilterTable(VKMC_FILTER_TABLE PixelFilterHeader h, vec2 u) {
  float px = 0.0f, py = 0.0f;
  vec2 offset =
      vec2(samplePixelFilter1D(VKMC_FILTER_TABLE_ARG h, u.x, px), samplePixelFilter1D(VKMC_FILTER_TABLE_ARG h, u.y, py));
  float p = px * py;
  float weight = p > 0.0f ? pixelFilterValue(h, offset) / p * (h.invIntegral * h.invIntegral) : 0.0f;
  return filterSample(vec2(0.5f) + offset, weight);
}
VKMC_FN float pixelFilterPdf(VKMC_FILTER_TABLE PixelFilterHeader h, vec2 offset) {
  return pixelFilter1DPdf(VKMC_FILTER_TABLE_ARG h, offset.x) * pixelFilter1DPdf(VKMC_FILTER_TABLE_ARG h, offset.y);
}
VKMC_FN vec2 invertPixelFilterSample(VKMC_FILTER_TABLE PixelFilterHeader h, vec2 point) {
  vec2 offset = point - vec2(0.5f);
  return vec2(invertPixelFilter1DSample(VKMC_FILTER_TABLE_ARG h, offset.x),
              invertPixelFilter1DSample(VKMC_FILTER_TABLE_ARG h, offset.y));
}

VKMC_END_NAMESPACE
#endif
