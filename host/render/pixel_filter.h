// The pixel reconstruction filter of a render: one row per filter (name, kind, default radius, help), read by the
// parsers (the CLI's --filter/--filter-radius, a study's "filter"), the validation, --help and the report's echo.
// What the filters are and how they are sampled: shaders/shared/pixel_filter.h.
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>

#include "../shaders/shared/layout.h"

namespace vkmc {

inline constexpr float kMaxPixelFilterRadius = 16.0f;  // pixels: a 33 x 33 pixel footprint
inline constexpr float kGaussianFilterSigma = 0.5f;    // pbrt-v4's default, in pixels
inline constexpr float kMitchellFilterB = 1.0f / 3.0f, kMitchellFilterC = 1.0f / 3.0f;

struct PixelFilter {
  uint32_t kind = gpu::kPixelFilterBox;
  float radius = 0.5f;  // pixels, per axis
  // The pixel's own box, sampled as the uniform jitter u with weight 1 (SPEC_PIXEL_FILTER's uniform sampling).
  bool isPixelBox() const { return kind == gpu::kPixelFilterBox && radius == 0.5f; }
  uint32_t specSampling() const { return isPixelBox() ? gpu::kPixelFilterSamplingUniform : gpu::kPixelFilterSamplingTable; }
};

struct PixelFilterRow {
  const char* name;
  uint32_t kind;
  float defaultRadius;
  const char* help;
};
std::span<const PixelFilterRow> pixelFilterRows();
const char* pixelFilterName(uint32_t kind);
std::string pixelFilterHelp();  // the names, their default radii and what they are, for --help

// A filter by name, with its default radius unless one is given; throws Error (naming --filter or
// --filter-radius) on an unknown name or a radius outside (0, kMaxPixelFilterRadius].
PixelFilter pixelFilterFromName(const std::string& name, std::optional<double> radius = std::nullopt);
void validatePixelFilter(const PixelFilter& filter);
// JSON: {"name": NAME, "radius": R} (radius optional), as the report echoes it (with sigma or b, c).
PixelFilter pixelFilterFromJson(const nlohmann::json& j);
nlohmann::json pixelFilterJson(const PixelFilter& filter);
std::string pixelFilterSummary(const PixelFilter& filter);  // "mitchell, radius 2 px (B = C = 1/3)"

}  // namespace vkmc
