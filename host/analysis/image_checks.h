// Plain-language checks of a finished image, each a warning that says what is wrong and its likely cause: an image
// that came out (nearly) black, a PNG preview clipped to white.
#pragma once
#include <optional>
#include <string>

#include "render/film.h"

namespace vkmc {

constexpr double kBlackLuminance = 1e-9;  // below this a pixel's mean counts as black
constexpr double kBlackShare = 0.99;      // the share of black pixels that makes an image black
constexpr double kClippedShare = 0.25;    // the share of white PNG pixels that makes a preview clipped

// When at least kBlackShare of the pixels' means are black (non-finite ones aside).
std::optional<std::string> blackImageWarning(const Film& film);
// When at least kClippedShare of the preview's pixels are white in some channel at a fixed exposure.
std::optional<std::string> clippedPreviewWarning(double clippedShare, double stops, bool automatic);

}  // namespace vkmc
