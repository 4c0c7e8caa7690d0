// Error of an image against a reference: MSE, relMSE, RMSE, mean absolute error, difference of the image
// means, and (when both carry variance channels) the per-pixel z-test of Mitsuba's render regressions.
#pragma once
#include "render/film.h"  // kRelMseEpsilon
#include <string>

#include "io/exr.h"

namespace vkmc {

struct ErrorMetrics {
  double mse = 0.0;
  double relmse = 0.0;  // mean over pixels and channels of (a - b)^2 / (b^2 + epsilon)
  double rmse = 0.0;
  double meanAbsoluteError = 0.0;
  double meanDifference = 0.0;  // mean(a) - mean(b) over pixels and channels
  bool hasZTest = false;
  double zTestPassFraction = 0.0;  // pixels whose every channel passes |a - b| / sqrt(va + vb) < z threshold
  double zThreshold = 0.0;         // the normal's bound at the test's level
  bool studentT = false;           // both images gave variance.dof: each pixel is Welch's t at that level instead
  size_t pixels = 0;
};

// Compares channels R, G, B; the z-test uses variance.R/G/B when both images have them. By default its
// threshold is Sidak-corrected so that on two unbiased renders all pixels pass with probability 1 - alpha;
// perPixelLevel = true tests each value at level alpha instead (for calibration).
ErrorMetrics compareImages(const ExrImage& image, const ExrImage& reference, double alpha = 0.01, bool perPixelLevel = false);
// Throws vkmc::Error naming `which` ("reference") and its first pixel with a non-finite mean or variance: every
// metric would be NaN. compareImages checks both images; a render checks its reference before it starts.
void requireFinite(const ExrImage& image, const char* which);

// A reference's own noise in relMSE terms: the mean over pixels and channels of its variance of the mean over
// (its value^2 + epsilon). An image independent of the reference has an expected relMSE against it of its own
// relative variance plus about this much; NaN where the reference has no variance channels (a constant, or one
// scrambling a pixel).
double referenceRelativeVariance(const ExrImage& reference);

// Per-pixel squared error (R, G, B) and relMSE (Y): an EXR heat map.
ExrImage errorHeatmap(const ExrImage& image, const ExrImage& reference);

}  // namespace vkmc
