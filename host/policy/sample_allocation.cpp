#include "policy/sample_allocation.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace vkmc {

namespace {
constexpr int kSmoothingRadius = 1;  // 3x3: 9x9 was no better on glass_bulb's scattered fireflies (docs/journal)
// One pass of a box of kSmoothingRadius, clamped at the ends, along `lines` lines of `length` values `step`
// apart, the lines `lineStep` apart.
void boxPass(const std::vector<double>& in, std::vector<double>& out, uint32_t length, uint32_t lines, size_t step,
             size_t lineStep) {
  for (uint32_t l = 0; l < lines; ++l)
    for (int i = 0; i < int(length); ++i) {
      double acc = 0.0;
      int k = 0;
      for (int j = std::max(0, i - kSmoothingRadius); j <= std::min(int(length) - 1, i + kSmoothingRadius); ++j)
        acc += in[l * lineStep + j * step], ++k;
      out[l * lineStep + i * step] = acc / k;
    }
}

// The clamped counts for scale lambda, before rounding.
double clampedTotal(const std::vector<double>& want, double lambda, double lo, double hi) {
  double total = 0.0;
  for (double w : want) total += std::clamp(lambda * w, lo, hi);
  return total;
}

// Counts in multiples of m that sum to the budget exactly (rounded down to m) where the cap allows: the floors,
// then one m more for the pixels with the largest remainders, then (where caps left budget over) one m more a
// pixel in turn. A round fills whole passes, and a few paths over would cost a whole extra pass.
std::vector<uint32_t> roundToBudget(const std::vector<double>& x, uint64_t budget, uint32_t m, double hi) {
  std::vector<uint32_t> n(x.size());
  std::vector<std::pair<double, size_t>> order(x.size());
  uint64_t total = 0;
  for (size_t p = 0; p < x.size(); ++p) {
    n[p] = uint32_t(std::floor(x[p] / m)) * m;
    total += n[p];
    order[p] = {x[p] - n[p], p};
  }
  std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (uint64_t left = total < budget ? (budget - total) / m : 0; left > 0;) {
    const uint64_t before = left;
    for (size_t k = 0; k < order.size() && left > 0; ++k)
      if (uint32_t& c = n[order[k].second]; c + m <= hi) c += m, --left;
    if (left == before) break;  // every pixel at its cap
  }
  return n;
}

}  // namespace

std::vector<uint32_t> allocateSamples(const std::vector<double>& relVariance, const std::vector<double>& cost, uint64_t budget,
                                      const AllocationLimits& limits) {
  const size_t pixels = relVariance.size();
  std::vector<uint32_t> n(pixels, limits.minimum);
  if (pixels == 0) return n;
  const double m = std::max(1u, limits.multiple);
  const double mean = double(budget) / double(pixels);
  const double lo = std::max<double>(limits.minimum, std::floor(limits.minFactor * mean / m) * m);
  const double hi = std::max(lo, std::floor(limits.maxFactor * mean / m) * m);
  // The image's mean relative variance added to each pixel's: a pixel whose rare bright paths no sample has met
  // yet looks quiet, and the image says how common such paths are.
  double meanV = 0.0;
  for (double v : relVariance) meanV += std::isfinite(v) ? std::max(v, 0.0) : 0.0;
  meanV /= double(pixels);
  std::vector<double> want(pixels);
  double largest = 0.0;
  for (size_t p = 0; p < pixels; ++p) {
    const double c = cost.empty() ? 1.0 : std::max(cost[p], 1e-12);
    const double v = std::isfinite(relVariance[p]) ? std::max(relVariance[p], 0.0) : 0.0;
    want[p] = std::sqrt((v + limits.imagePrior * meanV) / c);
    largest = std::max(largest, want[p]);
  }
  if (!(largest > 0.0)) want.assign(pixels, 1.0), largest = 1.0;
  // The scale whose clamped counts sum to the budget (monotone in lambda: bisection on a log scale).
  double a = 1e-30 / largest, b = 1e30 / largest;
  for (int i = 0; i < 200 && b / a > 1.0 + 1e-9; ++i) {
    const double mid = std::sqrt(a * b);
    (clampedTotal(want, mid, lo, hi) < double(budget) ? a : b) = mid;
  }
  for (size_t p = 0; p < pixels; ++p) want[p] = std::clamp(b * want[p], lo, hi);
  return roundToBudget(want, budget, uint32_t(m), hi);
}

std::vector<double> smoothedRelativeVariance(const std::vector<glm::dvec3>& mean, const std::vector<glm::dvec3>& sampleVariance,
                                             uint32_t width, uint32_t height, double epsilon) {
  std::vector<double> rel(mean.size(), 0.0), smooth(mean.size(), 0.0);
  for (size_t p = 0; p < mean.size(); ++p) {
    double r = 0.0;
    for (int c = 0; c < 3; ++c) r += sampleVariance[p][c] / (mean[p][c] * mean[p][c] + epsilon);
    rel[p] = std::isfinite(r) ? r / 3.0 : 0.0;
  }
  // A separable box, clamped at the image's edges: along the rows, then down the columns.
  std::vector<double> rows(rel.size(), 0.0);
  boxPass(rel, rows, width, height, 1, width);
  boxPass(rows, smooth, height, width, width, 1);
  return smooth;
}

}  // namespace vkmc
