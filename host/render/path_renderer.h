// The path tracer on the device, with one of two integrators built from the same stage functions:
//   wavefront: camera rays -> (intersect -> shade -> shadow)* -> accumulate, stage by stage, paths kept on the
//              device between stages, queues sized on the device and dispatched indirectly;
//   megakernel: one dispatch per sample pass follows every path to its end, then accumulate.
#pragma once
#include <glm/glm.hpp>

#include <map>
#include <memory>
#include <string>

#include "../shaders/shared/layout.h"
#include "estimators/efficiency_roulette.h"
#include "estimators/estimator_config.h"
#include "render/film.h"
#include "render/gpu_scene.h"
#include "scene/camera_rig.h"
#include "scene/scene_features.h"
#include "vk/kernel.h"

namespace vkmc {

enum class Integrator { Wavefront, Megakernel };
const char* toString(Integrator i);
Integrator integratorFromString(const std::string& name);  // throws Error on an unknown name

struct RenderSettings {
  uint32_t width = 256;
  uint32_t height = 256;
  uint32_t spp = 64;           // with a time budget: the most samples to take
  double timeBudget = 0.0;     // seconds; > 0: whole sample passes until the budget is spent
  EstimatorConfig estimator;   // roulette, splitting, sampling, MIS, depth cap
  SceneFeatures features;      // what the pipelines are specialized for (allFeatures(): general pipelines)
  uint32_t seed = 1;
  glm::vec3 background{0.0f};
  CameraRig camera{};
  bool progress = false;       // progress line on stderr
  uint32_t maxPathsPerPass = 1u << 18;  // wavefront size: paths in flight per pass
  bool recordDepthStats = false;         // efficiency-roulette pilot: per-path, per-depth statistics
  uint32_t workgroupSize = 64;           // invocations per workgroup of every kernel: 32, 64, 128 or 256
  Integrator integrator = Integrator::Wavefront;
};

struct RenderStats {
  double seconds = 0.0;          // wall time of the sample passes
  double gpuSeconds = 0.0;       // sum of kernel timestamps
  uint64_t cameraRays = 0, extensionRays = 0, shadowRays = 0;
  uint64_t primaryRays = 0;      // rays of bounce 0 (= camera rays)
  double primarySeconds = 0.0;   // GPU time of bounce-0 intersection
  double incoherentSeconds = 0.0;  // GPU time of later closest-hit intersections
  std::map<std::string, double> stageSeconds;
  uint32_t passes = 0;
  uint32_t maxBounces = 0;
  uint32_t samplesPerPixel = 0;  // reached (equals spp unless a time budget ended the render)
  uint64_t nonfiniteEmission = 0, nonfiniteLightSamples = 0, nonfiniteThroughput = 0;  // by producing stage
  uint64_t traversalsCut = 0;  // rays whose BVH walk the device's loop limit ended (their samples excluded)
  uint64_t deepWalks = 0;      // walks that outgrew the register stack, deferred to a trace stage's deep pass
  uint64_t deepWalksTraced = 0;  // of those, walks the deep passes traced (all of them, unless a pass was skipped)
  // Queue occupancy: paths queued for intersection and shadow rays queued, per bounce (the last entry sums
  // deeper bounces), over the whole render.
  std::vector<uint64_t> pathsByBounce, shadowRaysByBounce;
  uint64_t rays() const { return cameraRays + extensionRays + shadowRays; }
};

// The kernels a render dispatches, with the specialization constants each is built with.
struct KernelPlan {
  std::vector<std::string> kernels;
  std::vector<vk::SpecConstant> specs;
};
KernelPlan planKernels(const RenderSettings& settings);

class PathRenderer {
 public:
  // Creates the pipelines and warms them up (the driver compiles at first dispatch); see pipelineSeconds().
  PathRenderer(vk::Context& ctx, const GpuScene& scene, const RenderSettings& settings);
  ~PathRenderer();
  Film render(RenderStats& stats);
  double pipelineSeconds() const { return pipelineSeconds_; }
  // Efficiency roulette: the per-depth scales k_d the kernels read.
  void setRouletteScales(const std::array<float, kRouletteTableDepths>& scales);
  // Pilot statistics gathered by render() when settings.recordDepthStats is set.
  const std::vector<PilotPath>& pilot() const { return pilot_; }
  uint64_t deviceBytes() const { return deviceBytes_; }

 private:
  struct Kernels;
  uint32_t renderPass(uint32_t firstPixel, uint32_t pixelCount, uint32_t sampleIndex, uint32_t samples, RenderStats& stats);
  uint32_t renderMegakernelPass(const gpu::PushConstants& pc, RenderStats& stats);
  gpu::PushConstants passConstants(uint32_t firstPixel, uint32_t pixelCount, uint32_t sampleIndex, uint32_t samples) const;
  void collectCounters(RenderStats& stats);
  void foldFilm(Film& film);
  uint32_t groupsFor(uint32_t invocations) const;

  vk::Context& ctx_;
  const GpuScene& scene_;
  RenderSettings settings_;
  uint32_t capacity_ = 0;  // camera paths per pass
  uint32_t pool_ = 0;      // path slots: camera paths and split children
  bool hasShadowStage_ = true;
  std::unique_ptr<vk::KernelLayout> layout_;
  std::unique_ptr<Kernels> kernels_;
  std::unique_ptr<vk::GpuTimer> timer_;
  vk::Buffer paths_, hits_, queues_, shadowQueue_, deepWalks_, control_, film_, pixelEstimate_, rouletteTable_, depthStats_, queueStats_;
  std::vector<PilotPath> pilot_;
  void collectPilot(uint32_t pathCount);
  double pipelineSeconds_ = 0.0;
  uint64_t deviceBytes_ = 0;
};

}  // namespace vkmc
