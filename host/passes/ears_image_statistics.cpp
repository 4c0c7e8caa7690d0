// EARS's image statistics between passes (ears_image_statistics.h).
#include "passes/ears_image_statistics.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "error.h"

namespace vkmc {

std::vector<PixelSums> passPixelSums(const std::vector<PixelSums>& after, std::vector<PixelSums> before) {
  before.resize(after.size());  // none before: zeros
  for (size_t p = 0; p < after.size(); ++p) {
    before[p].n = after[p].n - before[p].n;
    before[p].sum = after[p].sum - before[p].sum;
    before[p].sumSq = after[p].sumSq - before[p].sumSq;
  }
  return before;
}

EarsPixelEstimate earsPixelEstimate(std::vector<glm::vec4> mean, uint32_t width, uint32_t height) {
  EarsPixelEstimate e;
  e.mean = std::move(mean);
  // A separable box, clipped at the image's edges.
  auto blur = [&](const std::vector<glm::vec4>& in, bool alongX) {
    std::vector<glm::vec4> out(in.size());
    for (uint32_t y = 0; y < height; ++y)
      for (uint32_t x = 0; x < width; ++x) {
        glm::dvec4 sum(0.0);
        int n = 0;
        for (int d = -kEarsSmoothingRadius; d <= kEarsSmoothingRadius; ++d) {
          const int xx = int(x) + (alongX ? d : 0), yy = int(y) + (alongX ? 0 : d);
          if (xx < 0 || yy < 0 || xx >= int(width) || yy >= int(height)) continue;
          sum += glm::dvec4(in[size_t(yy) * width + size_t(xx)]);
          ++n;
        }
        out[size_t(y) * width + x] = glm::vec4(sum / double(n));
      }
    return out;
  };
  if (e.mean.size() != size_t(width) * height) throw Error("internal error: EARS's pixel estimate is not the image's size");
  e.smoothed = blur(blur(e.mean, true), false);
  return e;
}

namespace {
// Per pixel the summed error of its samples and their count, averaged over the samples with the pixels of the
// largest errors left out (EARS leaves out its largest samples): a few fireflies would otherwise set V_img, so
// lower every factor, so roulette harder, which makes more fireflies.
double outlierRejectedMean(const std::vector<double>& error, const std::vector<double>& samples) {
  // The share rounded to the nearest pixel count (kEarsOutlierShare is a float), at least one.
  const size_t share = size_t(std::llround(double(error.size()) * double(gpu::kEarsOutlierShare)));
  const size_t dropped = std::min(error.size(), std::max<size_t>(share, 1));
  const size_t kept = error.size() - dropped;
  if (kept == 0) return 0.0;
  std::vector<size_t> order(error.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::nth_element(order.begin(), order.begin() + std::ptrdiff_t(kept - 1), order.end(),
                   [&](size_t a, size_t b) { return error[a] < error[b]; });
  double sum = 0.0, n = 0.0;
  for (size_t k = 0; k < kept; ++k) sum += error[order[k]], n += samples[order[k]];
  return n > 0.0 ? sum / n : 0.0;
}
}  // namespace

double earsRelativeVariance(const std::vector<PixelSums>& pass, const EarsPixelEstimate& earlier, double epsilon) {
  if (earlier.mean.size() != pass.size() || earlier.smoothed.size() != pass.size())
    throw Error("internal error: EARS's pixel estimate and the pass's sums differ in size");
  std::vector<double> error, samples;
  for (size_t p = 0; p < pass.size(); ++p) {
    const PixelSums& s = pass[p];
    if (!(s.n >= 1.0)) continue;
    double e = 0.0;
    for (int c = 0; c < 3; ++c) {
      // Sum over the samples of (x - I)^2 = sum x^2 - 2 I sum x + n I^2.
      const double i = earlier.mean[p][c], scale = earlier.smoothed[p][c];
      e += std::max(0.0, s.sumSq[c] - 2.0 * i * s.sum[c] + s.n * i * i) / (scale * scale + epsilon);
    }
    error.push_back(e / 3.0);
    samples.push_back(s.n);
  }
  return outlierRejectedMean(error, samples);
}

}  // namespace vkmc
