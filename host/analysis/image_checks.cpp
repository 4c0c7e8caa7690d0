#include "analysis/image_checks.h"

#include <cmath>
#include <cstdio>

#include "io/tone_map.h"

namespace vkmc {

std::optional<std::string> blackImageWarning(const Film& film) {
  size_t black = 0, counted = 0;
  for (size_t p = 0; p < film.pixels(); ++p) {
    const double l = luminance(film.mean(p, 0), film.mean(p, 1), film.mean(p, 2));
    if (!std::isfinite(l)) continue;
    ++counted;
    black += std::abs(l) < kBlackLuminance;
  }
  if (counted == 0 || double(black) < kBlackShare * double(counted)) return std::nullopt;
  char text[320];
  std::snprintf(text, sizeof(text),
                "the image is black (%.1f%% of its pixels): no light reaches the camera. Likely causes: the scene's "
                "lights are enclosed by its meshes, the camera is inside a closed mesh or faces away from the scene, "
                "or the scene has no light (--environment or --background adds one)",
                100.0 * double(black) / double(counted));
  return std::string(text);
}

std::optional<std::string> clippedPreviewWarning(double clippedShare, double stops, bool automatic) {
  if (clippedShare < kClippedShare) return std::nullopt;
  char text[256];
  std::snprintf(text, sizeof(text),
                "the PNG preview is clipped: %.0f%% of its pixels are white at %s%+.2f stops (the EXR is not clipped); "
                "%s",
                100.0 * clippedShare, automatic ? "the automatic exposure of " : "--exposure ", stops,
                automatic ? "the image is mostly far brighter than its log-average" : "try --exposure auto or fewer stops");
  return std::string(text);
}

}  // namespace vkmc
