// What a render is asked for (RenderSettings) and what it measured (RenderStats); the plan of its kernels.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "estimators/estimator_config.h"
#include "render/pixel_filter.h"
#include "scene/camera_rig.h"
#include "scene/scene_features.h"
#include "vk/kernel.h"

namespace vkmc {

// Auto: the measured faster one for the device (device_tuning.h), resolved before a render.
enum class Integrator { Wavefront, Megakernel, Auto };
const char* toString(Integrator i);
Integrator integratorFromString(const std::string& name);  // throws Error on an unknown name

struct RenderSettings {
  uint32_t width = 256;
  uint32_t height = 256;
  uint32_t spp = 64;          // with a time budget: the most samples to take
  double timeBudget = 0.0;    // seconds; > 0: whole sample passes until the budget is spent
  EstimatorConfig estimator;  // roulette, splitting, sampling, MIS, depth cap
  SceneFeatures features;     // what the pipelines are specialized for (allFeatures(): general pipelines)
  uint32_t seed = 1;
  glm::vec3 background{0.0f};
  float backdrop = 0.0f;  // > 0: the grey camera rays see where they escape (the studio's and a white world's backdrop)
  PixelFilter filter;     // pixel reconstruction filter (box of radius 0.5: plain jitter)
  CameraRig camera{};
  bool progress = false;                // progress line on stderr
  uint32_t maxPathsPerPass = 1u << 18;  // wavefront size: paths in flight per pass
  bool recordDepthStats = false;        // efficiency-roulette pilot: per-path, per-depth statistics
  uint32_t workgroupSize = 64;          // invocations per workgroup of every kernel: 32, 64, 128 or 256
  Integrator integrator = Integrator::Wavefront;
  bool prespecializedSpirv = true;  // false: pipelines from the general SPIR-V even where a variant matches
  bool sampleRuns = false;          // adaptive sampling's passes of sample runs (PathRenderer::renderSampleRuns)
  bool stageTimes = true;           // a timestamp pair around every dispatch (RenderStats::stageSeconds); false: one a submission
};

// The largest image side and sample count a render accepts (the command line, checkpoints and studies check them).
constexpr uint32_t kMaxImageSide = 16384;
constexpr uint32_t kMaxSpp = 1u << 24;

struct RenderStats {
  double seconds = 0.0;     // wall time of the sample passes
  double gpuSeconds = 0.0;  // the command buffers' GPU time, one timestamp pair each
  uint64_t cameraRays = 0, extensionRays = 0, shadowRays = 0;
  uint64_t primaryRays = 0;        // rays of bounce 0 (= camera rays)
  double primarySeconds = 0.0;     // GPU time of bounce-0 intersection
  double incoherentSeconds = 0.0;  // GPU time of later closest-hit intersections
  std::map<std::string, double> stageSeconds;
  bool stagesUntimed = false;  // some pass ran without stage timestamps (--stage-times off): stageSeconds is partial
  uint32_t passes = 0;
  uint32_t maxBounces = 0;
  uint32_t samplesPerPixel = 0;  // reached (equals spp unless a time budget ended the render)
  uint64_t nonfiniteEmission = 0, nonfiniteLightSamples = 0, nonfiniteThroughput = 0;  // by producing stage
  uint64_t traversalsCut = 0;    // rays whose BVH walk the device's loop limit ended (their samples excluded)
  uint64_t deepWalks = 0;        // walks that outgrew the register stack, deferred to a trace stage's deep pass
  uint64_t deepWalksTraced = 0;  // of those, walks the deep passes traced (all of them, unless a pass was skipped)
  uint64_t splitsRefused = 0;    // vertices that drew a split (BSDF splitting, EARS) when the path pool was full: kept
                                 // whole (q = 1), unbiased, but with less splitting than asked for
  // Queue occupancy: paths queued for intersection and shadow rays queued, per bounce (the last entry sums
  // deeper bounces), over the whole render.
  std::vector<uint64_t> pathsByBounce, shadowRaysByBounce;
  uint64_t rays() const { return cameraRays + extensionRays + shadowRays; }
  // primarySeconds and incoherentSeconds from stageSeconds (0 without stage timestamps).
  void deriveStageTotals() {
    auto it = stageSeconds.find("intersect_primary");
    primarySeconds = it == stageSeconds.end() ? 0.0 : it->second;
    it = stageSeconds.find("intersect");
    incoherentSeconds = it == stageSeconds.end() ? 0.0 : it->second;
  }
};

// The kernels a render dispatches, with the specialization constants each is built with.
struct KernelPlan {
  std::vector<std::string> kernels;
  std::vector<vk::SpecConstant> specs;
  std::string spirvVariant;  // the feature sets of the pre-specialized SPIR-V shading uses; "": the general SPIR-V
};
KernelPlan planKernels(const RenderSettings& settings);

// The ZSobol sampler's Morton-index shape (shaders/shared/sampler.h): log2 of a replicate's point count, and
// the index's base-4 digits. Throws Error where the index would pass 32 bits (zsobol only).
struct ZSobolLayout {
  uint32_t log2Spp = 0, digits = 0;
};
ZSobolLayout zsobolLayout(const RenderSettings& settings);
// The most samples a pixel ZSobol can index at this image size (its Morton index within 32 bits); 0 when not one.
uint32_t zsobolMaxSpp(uint32_t width, uint32_t height, uint32_t replicates);

}  // namespace vkmc
