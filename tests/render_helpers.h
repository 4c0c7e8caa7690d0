// Rendering helpers for statistical render tests: one shared Vulkan context, region statistics from the
// film's per-pixel variance of the mean, and two-sample z-tests.
#pragma once
#include <glm/glm.hpp>

#include <string>

#include "app/render_job.h"

namespace vkmc::test {

inline vk::Context& sharedContext() {
  static vk::Context ctx;
  return ctx;
}

inline std::string scenePath(const std::string& name) { return std::string(VKMC_SOURCE_DIR) + "/scenes/" + name; }

inline RenderOutcome renderWith(const std::string& scene, const EstimatorConfig& e, uint32_t w, uint32_t h, uint32_t spp,
                                uint32_t seed = 4242) {
  RenderOptions o;
  o.scenePath = scenePath(scene);
  o.width = w;
  o.height = h;
  o.spp = spp;
  o.seed = seed;
  o.estimator = e;
  o.progress = false;
  return runRender(sharedContext(), o);
}

// Mean over a pixel rectangle [x0, x1) x [y0, y1) and the variance of that mean (pixels are independent).
struct RegionStats {
  glm::dvec3 mean{0.0};
  glm::dvec3 variance{0.0};
};

inline RegionStats region(const Film& f, uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1) {
  RegionStats r;
  double n = 0;
  for (uint32_t y = y0; y < y1; ++y)
    for (uint32_t x = x0; x < x1; ++x) {
      size_t p = size_t(y) * f.width + x;
      for (int c = 0; c < 3; ++c) {
        r.mean[c] += f.mean(p, c);
        r.variance[c] += f.varianceOfMean(p, c);
      }
      n += 1;
    }
  r.mean /= n;
  r.variance /= n * n;
  return r;
}

inline RegionStats whole(const Film& f) { return region(f, 0, 0, f.width, f.height); }

// Largest |z| of the difference of two independent estimates, over the channels.
inline double maxZ(const RegionStats& a, const RegionStats& b) {
  double z = 0;
  for (int c = 0; c < 3; ++c) {
    double s = std::sqrt(a.variance[c] + b.variance[c]);
    if (s > 0) z = std::max(z, std::abs(a.mean[c] - b.mean[c]) / s);
  }
  return z;
}

inline double maxZ(const RegionStats& a, glm::dvec3 exact) {
  RegionStats b;
  b.mean = exact;
  return maxZ(a, b);
}

}  // namespace vkmc::test
