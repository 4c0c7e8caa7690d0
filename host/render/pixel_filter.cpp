// The pixel filters' rows, their parsing, validation and echo.
#include "render/pixel_filter.h"

#include <cmath>
#include <sstream>

#include "error.h"

namespace vkmc {

namespace {
// Default radii as pbrt-v4's (box 0.5, gaussian 1.5 with sigma 0.5, mitchell 2); Blackman-Harris over 2 pixels is
// about as wide as that Gaussian (standard deviation 0.55 px against its 0.48 px).
constexpr PixelFilterRow kRows[] = {
    {"box", gpu::kPixelFilterBox, 0.5f, "uniform in the pixel (the default; radius 0.5 is plain jitter)"},
    {"gaussian", gpu::kPixelFilterGaussian, 1.5f, "sigma 0.5 px, shifted to 0 at the radius (pbrt-v4's)"},
    {"mitchell", gpu::kPixelFilterMitchell, 2.0f, "Mitchell-Netravali, B = C = 1/3, negative lobes"},
    {"blackman-harris", gpu::kPixelFilterBlackmanHarris, 2.0f, "4-term Blackman-Harris window"},
};

std::string formatRadius(double r) {
  std::ostringstream s;
  s << r;
  return s.str();
}
}  // namespace

std::span<const PixelFilterRow> pixelFilterRows() { return kRows; }

const char* pixelFilterName(uint32_t kind) {
  for (const PixelFilterRow& r : kRows)
    if (r.kind == kind) return r.name;
  return "unknown";
}

std::string pixelFilterHelp() {
  std::string text = "pixel reconstruction filter, sampled by filter importance sampling:";
  for (const PixelFilterRow& r : kRows)
    text += std::string(" ") + r.name + " (radius " + formatRadius(r.defaultRadius) + ": " + r.help + ");";
  text.back() = '.';
  return text;
}

void validatePixelFilter(const PixelFilter& f) {
  bool known = false;
  for (const PixelFilterRow& r : kRows) known = known || r.kind == f.kind;
  if (!known) throw Error("--filter: unknown filter kind " + std::to_string(f.kind));
  if (!(f.radius > 0.0f && f.radius <= kMaxPixelFilterRadius))
    throw Error("--filter-radius must be a number of pixels in (0, " + formatRadius(kMaxPixelFilterRadius) + "], got " +
                formatRadius(f.radius));
}

PixelFilter pixelFilterFromName(const std::string& name, std::optional<double> radius) {
  for (const PixelFilterRow& r : kRows) {
    if (name != r.name) continue;
    if (radius && !(*radius > 0.0 && *radius <= kMaxPixelFilterRadius))
      throw Error("--filter-radius must be a number of pixels in (0, " + formatRadius(kMaxPixelFilterRadius) + "], got " +
                  formatRadius(*radius));
    PixelFilter f{r.kind, radius ? static_cast<float>(*radius) : r.defaultRadius};
    validatePixelFilter(f);
    return f;
  }
  std::string names;
  for (const PixelFilterRow& r : kRows) names += std::string(names.empty() ? "" : ", ") + r.name;
  throw Error("--filter '" + name + "' is not a filter (" + names + ")");
}

PixelFilter pixelFilterFromJson(const nlohmann::json& j) {
  if (!j.is_object() || !j.contains("name") || !j["name"].is_string())
    throw Error("filter must be {\"name\": NAME, \"radius\": R} (radius optional)");
  for (const auto& [key, value] : j.items())
    if (key != "name" && key != "radius") throw Error("filter: unknown key '" + key + "' (name, radius)");
  std::optional<double> radius;
  if (j.contains("radius")) {
    if (!j["radius"].is_number()) throw Error("filter: radius must be a number of pixels");
    radius = j["radius"].get<double>();
  }
  return pixelFilterFromName(j["name"].get<std::string>(), radius);
}

nlohmann::json pixelFilterJson(const PixelFilter& f) {
  nlohmann::json j = {{"name", pixelFilterName(f.kind)}, {"radius", f.radius}};
  if (f.kind == gpu::kPixelFilterGaussian) j["sigma"] = kGaussianFilterSigma;
  if (f.kind == gpu::kPixelFilterMitchell) j["b"] = kMitchellFilterB, j["c"] = kMitchellFilterC;
  j["sampling"] = f.isPixelBox() ? "uniform jitter in the pixel" : "filter importance sampling (weight f / p)";
  return j;
}

std::string pixelFilterSummary(const PixelFilter& f) {
  std::string text = std::string(pixelFilterName(f.kind)) + ", radius " + formatRadius(f.radius) + " px";
  if (f.kind == gpu::kPixelFilterGaussian) text += " (sigma " + formatRadius(kGaussianFilterSigma) + ")";
  if (f.kind == gpu::kPixelFilterMitchell) text += " (B = C = 1/3)";
  return text;
}

}  // namespace vkmc
