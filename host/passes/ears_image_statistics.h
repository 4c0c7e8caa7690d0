// The image statistics EARS scales its factors by (shaders/shared/ears.h): the pixel estimate the kernels read,
// and the image's relative variance per sample, V_img, of the pass just rendered.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include "../shaders/shared/layout.h"

namespace vkmc {

// One pixel's samples in a span of passes: their count, and per channel their sum and sum of squares.
struct PixelSums {
  double n = 0.0;
  glm::dvec3 sum{0.0}, sumSq{0.0};
};

// after - before, pixel by pixel: the samples one pass added to the batch. before is taken by value, so a caller
// done with it moves it in and its storage holds the result (a frame's sums are 56 bytes a pixel).
std::vector<PixelSums> passPixelSums(const std::vector<PixelSums>& after, std::vector<PixelSums> before);

// Each pixel's mean so far (film.h runningPixelEstimate), and that mean averaged over the
// (2 kEarsSmoothingRadius + 1)^2 pixels around it: the kernels' t = beta / sqrt(I^2 + eps) and V_img's
// denominators use the smoothed one, as EARS uses a denoised image. A pixel's own mean from a few samples is often
// far below its value (the light not found yet), which would make both huge there.
constexpr int kEarsSmoothingRadius = 2;
struct EarsPixelEstimate {
  std::vector<glm::vec4> mean, smoothed;
};
// Throws if mean does not hold width x height pixels.
EarsPixelEstimate earsPixelEstimate(std::vector<glm::vec4> mean, uint32_t width, uint32_t height);

// EARS's V_img (its recursive_path.cpp): every sample's squared error against its pixel's mean over the earlier
// passes, relative as in relMSE but to the smoothed mean the pass read, (x - I)^2 / (I_smoothed^2 + epsilon),
// averaged over the pass's samples and channels, with the pixels that hold the largest kEarsOutlierShare of it
// left out. The earlier passes' mean is independent of the pass's samples, so a firefly counts in full; measured
// against its own pixel's mean a sample's ratio cannot exceed the pixel's sample count, which made V_img some 80x
// too small (docs/journal/ears.md). (EARS uses its denoised image for both; the raw mean keeps the numerator free of the
// box's blur at edges.) Throws on a size mismatch.
double earsRelativeVariance(const std::vector<PixelSums>& pass, const EarsPixelEstimate& earlier, double epsilon);

}  // namespace vkmc
