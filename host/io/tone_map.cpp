#include "io/tone_map.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "error.h"

namespace vkmc {

std::optional<double> parseExposure(const std::string& text) {
  if (text == "auto") return std::nullopt;
  char* end = nullptr;
  const double stops = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(stops) || std::abs(stops) > 100.0)
    throw Error("--exposure must be auto or a finite number of stops in [-100, 100] (got '" + text + "')");
  return stops;
}

ToneMap parseToneMap(const std::string& text) {
  if (text == "neutral") return ToneMap::Neutral;
  if (text == "clamp") return ToneMap::Clamp;
  throw Error("--tonemap must be neutral or clamp (got '" + text + "')");
}

const char* toneMapName(ToneMap t) { return t == ToneMap::Neutral ? "neutral" : "clamp"; }

double luminance(double r, double g, double b) { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }

double autoExposureStops(const std::vector<double>& luminance) {
  // The log-average of the lit pixels: those above a thousandth of the 95th percentile. Black pixels (a subject
  // against a black world) would otherwise drag the average toward 0 and blow the subject out.
  std::vector<double> positive;
  for (double l : luminance)
    if (std::isfinite(l) && l > 0.0) positive.push_back(l);
  if (positive.empty()) return 0.0;
  auto p95 = positive.begin() + std::ptrdiff_t(0.95 * double(positive.size() - 1));
  std::nth_element(positive.begin(), p95, positive.end());
  const double floor = kLitFraction * *p95;
  double sum = 0.0;
  size_t n = 0;
  for (double l : positive)
    if (l > floor) sum += std::log(l), ++n;
  const double logAverage = std::exp(sum / double(n));
  return std::clamp(std::log2(kMiddleGrey / logAverage), -kMaxAutoStops, kMaxAutoStops);
}

// Khronos PBR Neutral (github.com/KhronosGroup/ToneMapping, PBR_Neutral): colours lose a small offset (at most
// 0.04, for the black level) and pass otherwise unchanged up to 0.76; brighter ones are compressed toward a peak
// of 1 and desaturated as they approach it.
std::array<double, 3> pbrNeutral(std::array<double, 3> c) {
  constexpr double kStartCompression = 0.8 - 0.04, kDesaturation = 0.15;
  const double x = std::min({c[0], c[1], c[2]});
  const double offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
  for (double& v : c) v -= offset;
  const double peak = std::max({c[0], c[1], c[2]});
  if (peak < kStartCompression) return c;
  constexpr double d = 1.0 - kStartCompression;
  const double newPeak = 1.0 - d * d / (peak + d - kStartCompression);
  const double g = 1.0 - 1.0 / (kDesaturation * (peak - newPeak) + 1.0);
  for (double& v : c) v = (v * newPeak / peak) * (1.0 - g) + newPeak * g;
  return c;
}

uint8_t toSrgb8(double linear) {
  double v = std::clamp(std::isfinite(linear) ? linear : 0.0, 0.0, 1.0);
  v = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  return static_cast<uint8_t>(std::lround(v * 255.0));
}

double highlightStops(std::vector<double> scene) {
  std::erase_if(scene, [](double l) { return !(std::isfinite(l) && l > 0.0); });
  if (scene.empty()) return kMaxAutoStops;
  // The value with at most kHighlightShare of the values above it: it lands on the limit, they pass it.
  const size_t above = size_t(kHighlightShare * double(scene.size()));
  auto high = scene.begin() + std::ptrdiff_t(scene.size() - 1 - above);
  std::nth_element(scene.begin(), high, scene.end());
  return std::log2(kHighlightLimit / *high);
}

double exposureFor(const PreviewLook& look, const std::vector<double>& luminance, const std::vector<double>& scene) {
  if (look.exposureStops) return *look.exposureStops;
  return std::clamp(std::min(autoExposureStops(luminance), highlightStops(scene)), -kMaxAutoStops, kMaxAutoStops);
}

std::array<uint8_t, 3> previewPixel(std::array<double, 3> rgb, double stops, ToneMap toneMap) {
  const double scale = std::exp2(stops);
  for (double& v : rgb) v = std::isfinite(v) ? std::max(v * scale, 0.0) : 0.0;
  if (toneMap == ToneMap::Neutral) rgb = pbrNeutral(rgb);
  return {toSrgb8(rgb[0]), toSrgb8(rgb[1]), toSrgb8(rgb[2])};
}

}  // namespace vkmc
