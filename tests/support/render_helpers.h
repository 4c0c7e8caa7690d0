// Rendering helpers for statistical render tests: one shared Vulkan context, region statistics from the
// film's per-pixel variance of the mean, and their z-tests (z_test.h).
#pragma once
#include <glm/glm.hpp>

#include <set>
#include <string>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <vector>

#include "../shaders/shared/layout.h"
#include "analysis/student_t.h"
#include "app/render_job.h"
#include "render/gpu_scene.h"
#include "vk/kernel.h"
#include "z_test.h"

namespace vkmc::test {

inline vk::Context& sharedContext() {
  static vk::Context ctx;
  return ctx;
}

// Appends the quad o, o + u, o + u + v, o + v (front face along u x v) to an in-memory scene.
inline void addQuad(Scene& s, glm::vec3 o, glm::vec3 u, glm::vec3 v, uint32_t material) {
  glm::vec3 n = glm::normalize(glm::cross(u, v));
  for (glm::vec3 p : {o, o + u, o + u + v, o, o + u + v, o + v}) {
    s.positions.push_back(p);
    s.normals.push_back(n);
    s.bounds.grow(p);
  }
  s.materialIds.insert(s.materialIds.end(), {material, material});
}

// Binds a placeholder buffer to every storage binding a standalone test kernel declares but never touches.
inline void bindPlaceholders(vk::KernelLayout& layout, const vk::Buffer& placeholder, std::initializer_list<uint32_t> except) {
  for (uint32_t b = 0; b < BINDING_COUNT; ++b)
    if (!vk::isTexelBinding(b) && !vk::isImageBinding(b) && std::find(except.begin(), except.end(), b) == except.end())
      layout.bindStorage(b, placeholder);
}

// Viewed placeholder buffers on the renderer's texel bindings (path state, hits, queues, shadow rays, pixel
// estimates), for a standalone kernel that reads some of them only behind a specialization constant: every
// descriptor a kernel uses statically must be written (Vulkan's rule), whether or not the branch runs.
struct RendererTexelPlaceholders {
  std::vector<vk::Buffer> buffers;
  RendererTexelPlaceholders(vk::Context& ctx, vk::KernelLayout& layout) {
    for (uint32_t b : gpu::kRendererTexelBindings) {
      buffers.emplace_back(ctx, 256, VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT, vk::MemoryKind::DeviceLocal);
      buffers.back().createView(sceneTexelFormat(b));
      layout.bindTexel(b, buffers.back());
    }
  }
};

inline std::string scenePath(const std::string& name) { return std::string(VKMC_SOURCE_DIR) + "/scenes/" + name; }

inline RenderOptions optionsFor(const std::string& scene, const EstimatorConfig& e, uint32_t w, uint32_t h, uint32_t spp,
                                uint32_t seed = 4242) {
  RenderOptions o;
  o.scenePath = scenePath(scene);
  o.width = w;
  o.height = h;
  o.spp = spp;
  o.seed = seed;
  o.estimator = e;
  o.progress = false;
  return o;
}

inline RenderOutcome renderWith(const std::string& scene, const EstimatorConfig& e, uint32_t w, uint32_t h, uint32_t spp,
                                uint32_t seed = 4242) {
  return runRender(sharedContext(), optionsFor(scene, e, w, h, spp, seed));
}

// --estimator auto from `start`, the keys in `pinned` kept, with adaptive rounds where asked.
inline RenderOutcome renderAuto(const std::string& scene, uint32_t w, uint32_t h, uint32_t spp, uint32_t seed,
                                const EstimatorConfig& start = {}, std::set<std::string> pinned = {}, bool adaptive = false) {
  RenderOptions o = optionsFor(scene, start, w, h, spp, seed);
  o.estimatorAuto = true;
  o.adaptive = adaptive;
  o.pinnedKeys = std::move(pinned);
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

// One pixel's channel matches an exact value within k sigma, Student's bound for the pixel's degrees of freedom.
inline bool pixelMatches(const Film& f, size_t p, int c, double expected, double k) {
  const double dof = f.varianceDof(p);
  return zTest(f.mean(p, c), expected, std::sqrt(f.varianceOfMean(p, c))).within(studentBoundForSigmas(k, dof));
}

// One pixel's channel in two independent renders agrees within k sigma, sigma and its degrees of freedom by
// Welch (replicates - 1 dof a pixel under the QMC samplers: Student's bound, not the normal's; analysis/student_t.h).
inline bool pixelsAgree(const Film& a, const Film& b, size_t p, int c, double k, double slack = 0.0) {
  const double va = a.varianceOfMean(p, c), vb = b.varianceOfMean(p, c);
  const double dof = welchDof(va, a.varianceDof(p), vb, b.varianceDof(p));
  return zTest2(a.mean(p, c), va, b.mean(p, c), vb, slack).within(studentBoundForSigmas(k, dof));
}

// The colour channels of two independent region estimates as z-tests (z_test.h).
inline std::vector<ZTest> channelZTests(const RegionStats& a, const RegionStats& b) {
  std::vector<ZTest> t;
  for (int c = 0; c < 3; ++c) t.push_back(zTest2(a.mean[c], a.variance[c], b.mean[c], b.variance[c]));
  return t;
}

inline std::vector<ZTest> channelZTests(const RegionStats& a, glm::dvec3 exact) {
  RegionStats b;
  b.mean = exact;
  return channelZTests(a, b);
}

// Largest |z| of the difference of two independent estimates (or of one against an exact value), over the channels.
inline double maxZ(const RegionStats& a, const RegionStats& b) { return maxAbsZ(channelZTests(a, b)); }
inline double maxZ(const RegionStats& a, glm::dvec3 exact) { return maxAbsZ(channelZTests(a, exact)); }

// gtest forms of maxZ(...) < k, whose failure message lists each channel's test.
inline ::testing::AssertionResult regionsAgree(const RegionStats& a, const RegionStats& b, double k) {
  return allBelowSigmas(channelZTests(a, b), k);
}
inline ::testing::AssertionResult regionMatches(const RegionStats& a, glm::dvec3 exact, double k) {
  return allBelowSigmas(channelZTests(a, exact), k);
}

// Per pixel E[(a - u)^2] = Var(a) + Var(u) where both films' variances are honest: the mean over pixels and
// channels of d = (a - u)^2 - (V_a + V_u) is 0 within k of its own standard errors.
inline ::testing::AssertionResult variancesAreHonest(const Film& a, const Film& u, double k) {
  std::vector<double> d;
  for (size_t p = 0; p < a.pixels(); ++p)
    for (int c = 0; c < 3; ++c) {
      const double diff = a.mean(p, c) - u.mean(p, c);
      d.push_back(diff * diff - a.varianceOfMean(p, c) - u.varianceOfMean(p, c));
    }
  double mean = 0.0, ss = 0.0;
  for (double x : d) mean += x;
  mean /= double(d.size());
  for (double x : d) ss += (x - mean) * (x - mean);
  const double se = std::sqrt(ss / double(d.size() - 1) / double(d.size()));
  if (std::abs(mean) < k * se) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "mean of (a - u)^2 - V_a - V_u: " << mean << " +- " << se;
}

}  // namespace vkmc::test
