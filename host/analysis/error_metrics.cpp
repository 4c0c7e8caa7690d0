// Error metrics between two EXR images.
#include "analysis/error_metrics.h"

#include <algorithm>
#include <cmath>

#include "analysis/student_t.h"
#include "error.h"
#include "render/film.h"

namespace vkmc {
namespace {

// Inverse of the standard normal CDF (Acklam's rational approximation, refined by one Newton step).
double normalQuantile(double p) {
  static const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,  -2.759285104469687e+02,
                             1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
  static const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02, 6.680131188771972e+01,
                             -1.328068155288572e+01};
  static const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                             -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
  static const double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00, 3.754408661907416e+00};
  double q, r, x;
  if (p < 0.02425) {
    q = std::sqrt(-2 * std::log(p));
    x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1);
  } else if (p > 1 - 0.02425) {
    q = std::sqrt(-2 * std::log(1 - p));
    x = -(((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1);
  } else {
    q = p - 0.5;
    r = q * q;
    x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
        (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1);
  }
  double e = 0.5 * std::erfc(-x / std::sqrt(2.0)) - p;
  double u = e * std::sqrt(2 * M_PI) * std::exp(x * x / 2);
  return x - u / (1 + x * u / 2);
}

const std::vector<float>& channel(const ExrImage& img, const char* name, const char* which) {
  auto it = img.channels.find(name);
  if (it == img.channels.end()) throw Error(std::string(which) + " has no channel " + name);
  return it->second;
}

}  // namespace

void requireFinite(const ExrImage& image, const char* which) {
  for (const auto& [name, values] : image.channels) {
    if (name != "R" && name != "G" && name != "B" && name.rfind("variance.", 0) != 0) continue;
    for (size_t p = 0; p < values.size(); ++p)
      if (!std::isfinite(values[p]))
        throw Error(std::string("the ") + which + "'s pixel (" + std::to_string(p % size_t(std::max(image.width, 1))) + ", " +
                    std::to_string(p / size_t(std::max(image.width, 1))) + ") has a non-finite " + name +
                    ": error metrics need finite images");
  }
}

ErrorMetrics compareImages(const ExrImage& a, const ExrImage& b, double alpha, bool perPixelLevel) {
  requireFinite(a, "image");
  requireFinite(b, "reference");
  if (a.width != b.width || a.height != b.height)
    throw Error("image sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) + " against " +
                std::to_string(b.width) + "x" + std::to_string(b.height));
  ErrorMetrics m;
  m.pixels = static_cast<size_t>(a.width) * a.height;
  const char* rgb[] = {"R", "G", "B"};
  const char* var[] = {"variance.R", "variance.G", "variance.B"};
  m.hasZTest = a.channels.count(var[0]) && b.channels.count(var[0]);
  // With both images' degrees of freedom the test is Welch's t (a QMC pixel's variance has only replicates - 1), else the z.
  const bool hasDof = m.hasZTest && a.channels.count("variance.dof") && b.channels.count("variance.dof");
  const std::vector<float>* dofA = hasDof ? &channel(a, "variance.dof", "image") : nullptr;
  const std::vector<float>* dofB = hasDof ? &channel(b, "variance.dof", "reference") : nullptr;
  m.studentT = hasDof;
  // Sidak: each of the 3 * pixels tests at level 1 - (1 - alpha)^(1 / tests), two-sided.
  double perTest = perPixelLevel ? alpha : 1.0 - std::pow(1.0 - alpha, 1.0 / (3.0 * m.pixels));
  m.zThreshold = normalQuantile(1.0 - perTest / 2.0);
  std::vector<bool> pass(m.pixels, true);
  double sumA = 0, sumB = 0;
  for (int c = 0; c < 3; ++c) {
    const auto& va = channel(a, rgb[c], "image");
    const auto& vb = channel(b, rgb[c], "reference");
    const std::vector<float>* sa = m.hasZTest ? &channel(a, var[c], "image") : nullptr;
    const std::vector<float>* sb = m.hasZTest ? &channel(b, var[c], "reference") : nullptr;
    for (size_t p = 0; p < m.pixels; ++p) {
      double x = va[p], y = vb[p], d = x - y;
      m.mse += d * d;
      m.relmse += d * d / (y * y + kRelMseEpsilon);
      m.meanAbsoluteError += std::abs(d);
      sumA += x;
      sumB += y;
      if (m.hasZTest) {
        const double a2 = (*sa)[p], b2 = (*sb)[p], s = std::sqrt(a2 + b2);
        bool passes = s > 0 ? std::abs(d) / s < m.zThreshold : d == 0.0;
        if (hasDof && s > 0) {
          const double dof = welchDof(a2, (*dofA)[p], b2, (*dofB)[p]);
          if (dof < 1e7) passes = studentTwoSidedTail(std::abs(d) / s, dof) > perTest;
        }
        if (!passes) pass[p] = false;
      }
    }
  }
  double n = 3.0 * m.pixels;
  m.mse /= n;
  m.relmse /= n;
  m.meanAbsoluteError /= n;
  m.rmse = std::sqrt(m.mse);
  m.meanDifference = (sumA - sumB) / n;
  if (m.hasZTest) {
    size_t passed = 0;
    for (bool p : pass) passed += p;
    m.zTestPassFraction = double(passed) / m.pixels;
  }
  return m;
}

double referenceRelativeVariance(const ExrImage& reference) {
  const char* rgb[] = {"R", "G", "B"};
  const char* var[] = {"variance.R", "variance.G", "variance.B"};
  double acc = 0.0;
  size_t n = 0;
  for (int c = 0; c < 3; ++c) {
    auto value = reference.channels.find(rgb[c]), variance = reference.channels.find(var[c]);
    if (value == reference.channels.end() || variance == reference.channels.end()) return std::nan("");
    for (size_t p = 0; p < value->second.size() && p < variance->second.size(); ++p, ++n) {
      const double y = value->second[p];
      acc += double(variance->second[p]) / (y * y + kRelMseEpsilon);
    }
  }
  return n ? acc / double(n) : std::nan("");
}

ExrImage errorHeatmap(const ExrImage& a, const ExrImage& b) {
  ExrImage out;
  out.width = a.width;
  out.height = a.height;
  size_t n = static_cast<size_t>(a.width) * a.height;
  const char* rgb[] = {"R", "G", "B"};
  auto& rel = out.channels["Y"];
  rel.assign(n, 0.0f);
  for (int c = 0; c < 3; ++c) {
    const auto& va = channel(a, rgb[c], "image");
    const auto& vb = channel(b, rgb[c], "reference");
    auto& o = out.channels[rgb[c]];
    o.resize(n);
    for (size_t p = 0; p < n; ++p) {
      double d = double(va[p]) - vb[p];
      o[p] = static_cast<float>(d * d);
      rel[p] += static_cast<float>(d * d / (double(vb[p]) * vb[p] + kRelMseEpsilon) / 3.0);
    }
  }
  return out;
}

}  // namespace vkmc
