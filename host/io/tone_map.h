// How the PNG preview shows a physical (linear, unbounded) image; the EXR is never tone-mapped.
//   exposure: `auto` scales the image so that the log-average luminance of its lit pixels lands on middle grey
//             (Reinhard et al. 2002, "Photographic tone reproduction", key 0.18), or a fixed number of stops;
//             under the studio or a white world, lowered where that would expose more than a tenth of the
//             scene's pixels (those showing more than the grey backdrop) past 2, where the neutral tone map
//             nears white;
//   tone map: `neutral`, the Khronos PBR Neutral operator (colours below 0.76 kept, less a black offset of at
//             most 0.04; highlights compressed toward white), or `clamp` (linear, values above 1 clipped);
//   then the sRGB transfer function to 8 bits.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vkmc {

enum class ToneMap { Neutral, Clamp };

struct PreviewLook {
  ToneMap toneMap = ToneMap::Neutral;
  std::optional<double> exposureStops;  // empty: automatic
};

// "auto" or a number of stops in [-100, 100]; "neutral" or "clamp". Throw vkmc::Error naming the flag.
std::optional<double> parseExposure(const std::string& text);
ToneMap parseToneMap(const std::string& text);
const char* toneMapName(ToneMap t);

constexpr double kMiddleGrey = 0.18;
constexpr double kMaxAutoStops = 24.0;  // a nearly black image is not scaled past this
constexpr double kLitFraction = 1e-3;   // lit: above this fraction of the 95th percentile of positive luminances
// The stops that bring the log-average of the lit values of `luminance` to middle grey (non-finite and
// non-positive values ignored); 0 for an image with no positive value.
double autoExposureStops(const std::vector<double>& luminance);
double luminance(double r, double g, double b);  // Rec. 709 weights

std::array<double, 3> pbrNeutral(std::array<double, 3> rgb);
uint8_t toSrgb8(double linear);  // clamped to [0, 1]; NaN as 0

// Automatic exposure keeps the scene's highlights: at most kHighlightShare of the scene's lit pixels exposed past
// kHighlightLimit, which PBR Neutral shows at 96% of white (a gradation still; a 6,830-lux sun on a board filling a
// fifth of the image would otherwise leave it white while the backdrop keeps the log-average low).
constexpr double kHighlightShare = 0.1;
constexpr double kHighlightLimit = 2.0;
// The most stops that keep the highlights of `scene` (the luminances of the pixels that show the scene);
// kMaxAutoStops where none is positive.
double highlightStops(std::vector<double> scene);
// The stops a look applies to an image of these luminances: its fixed stops, or the automatic ones (the whole
// image's key, lowered to keep the highlights of `scene`, the pixels showing more than a backdrop).
double exposureFor(const PreviewLook& look, const std::vector<double>& luminance, const std::vector<double>& scene);
// One pixel through the look at `stops`: exposure, tone map, sRGB.
std::array<uint8_t, 3> previewPixel(std::array<double, 3> rgb, double stops, ToneMap toneMap);

}  // namespace vkmc
