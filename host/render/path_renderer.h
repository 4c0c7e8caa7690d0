// The path tracer on the device, with one of two integrators built from the same stage functions:
//   wavefront: camera rays -> (intersect -> shade -> shadow)* -> accumulate, stage by stage, paths kept on the
//              device between stages, queues sized on the device and dispatched indirectly;
//   megakernel: one dispatch per sample pass follows every path to its end, then accumulate.
#pragma once
#include <glm/glm.hpp>

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "../shaders/shared/layout.h"
#include "estimators/efficiency_roulette.h"
#include "estimators/estimator_config.h"
#include "render/path_pool.h"
#include "render/render_state.h"
#include "render/render_kernels.h"
#include "render/render_settings.h"
#include "render/ears_cache.h"
#include "passes/ears_guard.h"
#include "passes/pass_policy.h"
#include "passes/ears_image_statistics.h"
#include "render/film.h"
#include "render/gpu_scene.h"
#include "scene/camera_rig.h"
#include "scene/scene_features.h"
#include "vk/kernel.h"

namespace vkmc {

class PathRenderer {
 public:
  // Creates the pipelines and warms them up (the driver compiles at first dispatch); see pipelineSeconds().
  PathRenderer(vk::Context& ctx, const GpuScene& scene, const RenderSettings& settings);
  ~PathRenderer();
  Film render(RenderStats& stats);
  // Renders from `state` (empty, or a checkpoint's) towards settings.spp or the time budget, updating it in
  // place; stops early, with state.interrupted, when control.stop is raised.
  void render(RenderState& state, const RenderControl& control);
  double pipelineSeconds() const { return pipelineSeconds_; }
  uint32_t pathsPerPass() const { return capacity_; }  // camera paths per pass (path_pool.h)
  uint32_t pathSlots() const { return pool_; }         // with room for split children

  // The pieces render() is made of, for a caller that schedules samples itself (dist/distributed_render.h):
  // sample passes of samplesPerPass() samples a pixel, summed in float on the device until a batch of
  // samplesPerBatch() is folded.
  uint32_t samplesPerPass() const;
  uint32_t samplesPerBatch() const;
  void renderSamples(uint32_t firstSample, uint32_t samples, RenderStats& stats);  // one sample pass
  // Adaptive sampling (settings.sampleRuns): each entry's samples of its pixel into the device's batch, in passes
  // of at most pathsPerPass() paths, calling afterPass after each (where the caller folds the batch: an entry has
  // at most samplesPerBatch() samples, and a pass holds a pixel once). Returns false where afterPass said stop.
  struct PixelSamples {
    uint32_t pixel, firstSample, samples;
  };
  bool renderSampleRuns(const std::vector<PixelSamples>& work, RenderStats& stats, const std::function<bool()>& afterPass);
  // renderSampleRuns with each pass's batch folded into `film`; goOn (where given) is asked after each fold.
  bool renderSampleRunsInto(Film& film, const std::vector<PixelSamples>& work, RenderStats& stats,
                            const std::function<bool()>& goOn = nullptr);
  std::vector<gpu::FilmPixel> takeBatch();  // the device's batch, then zeroed
  void restoreBatch(const std::vector<gpu::FilmPixel>& batch);
  void uploadPixelEstimate(const Film& film) { setPixelEstimate(runningPixelEstimate(film)); }
  // The running per-pixel estimate (shadow roulette, EARS): the film's means, w their luminance.
  void setPixelEstimate(const std::vector<glm::vec4>& estimate);
  // Derived stats (GPU seconds, queue occupancy) once the passes are done; the queue counters add to `before`.
  void finishStats(RenderStats& stats, const RenderStats& before);
  // Efficiency roulette: the per-depth scales k_d the kernels read.
  void setRouletteScales(const std::array<float, kRouletteTableDepths>& scales);
  // Pilot statistics gathered by render() when settings.recordDepthStats is set.
  const std::vector<PilotPath>& pilot() const { return pilot_; }
  uint64_t deviceBytes() const { return deviceBytes_; }
  // EARS's cache (placeholders unless the estimator's rr is ears).
  EarsCache& ears() { return *ears_; }
  // EARS's guard: what its comparison measured and chose (compared false where it did not run).
  const EarsGuardOutcome& earsGuard() const { return earsGuard_; }

 private:
  uint32_t renderPass(uint32_t firstPixel, uint32_t pixelCount, uint32_t sampleIndex, uint32_t samples, RenderStats& stats);
  // One wavefront: camera rays for `samples` samples of each pixel, every bounce until no path is alive, and their
  // accumulation. earsTrains: under EARS, with the kernels that train the cache.
  uint32_t renderWavefront(uint32_t firstPixel, uint32_t pixelCount, uint32_t sampleIndex, uint32_t samples, bool earsTrains,
                           RenderStats& stats);
  uint32_t renderWavefront(gpu::PushConstants pc, bool earsTrains, RenderStats& stats);
  // The wavefront's stages, recorded into one command buffer.
  void recordCameraRays(VkCommandBuffer cmd, const gpu::PushConstants& pc, uint32_t paths);
  void recordBounce(VkCommandBuffer cmd, const gpu::PushConstants& pc, bool prepared, bool earsTrains);
  void recordAccumulate(VkCommandBuffer cmd, const gpu::PushConstants& pc);
  void allocateBuffers(uint64_t pixels, const PathPoolSize& size);
  void bindBuffers();
  uint32_t renderMegakernelPass(const gpu::PushConstants& pc, RenderStats& stats);
  gpu::PushConstants passConstants(uint32_t firstPixel, uint32_t pixelCount, uint32_t sampleIndex, uint32_t samples) const;
  const gpu::Control& controlView() const;
  void resetControl(VkCommandBuffer cmd);
  void publishControl(VkCommandBuffer cmd);
  void collectCounters(RenderStats& stats);
  void submitTimed(VkCommandBuffer cmd, RenderStats& stats);
  void foldFilm(Film& film);
  // EARS after a training wavefront of `cameras` camera paths: their sums into the cache.
  void trainEars(uint32_t cameras, RenderStats& stats);
  // render()'s steps: the film before the passes, EARS's start, the pass policy, one planned pass, the progress line.
  uint32_t prepareFilm(RenderState& state, bool shadowRoulette);
  void startEars(RenderState& state, uint32_t& inBatch);
  std::unique_ptr<PassPolicy> passPolicy(bool shadowRoulette) const;
  PassOutcome runPlannedPass(const PassPlan& plan, RenderState& state, uint32_t& inBatch, bool shadowRoulette);
  void printProgress(uint32_t s, uint32_t firstSample, double elapsed, double secondsBefore, const RenderStats& stats) const;
  // The plan of the pass in flight (kernels and seed), and what the device's batch holds.
  PassPlan plan_;
  uint32_t droppedIndex_ = 0;           // training passes' samples follow each other in their own seed's sequence
  bool batchHoldsTraining_ = false;     // the batch holds training samples, zeroed when training ends
  std::unique_ptr<PassPolicy> policy_;  // the render's (render() makes it; a fold asks it whether EARS still learns)
  std::chrono::steady_clock::time_point passesStart_;
  std::vector<PixelSums> passSums_;   // what a measured or learning pass tells its policy (PassOutcome)
  std::vector<glm::vec4> passScale_;  // a measured pass's (a learning pass's is EARS's own estimate)
  void dropBatch();
  // EARS after a pass: V_img of the pass against the earlier passes' estimate, then the next pass's estimate.
  // Returns the pass's sums (after - before).
  std::vector<PixelSums> updateEarsStatistics(const Film& film, double raysPerSample);
  // What V_img measures a pass against: the batch's sums before it (zeroed with the batch), and the pixel
  // estimate the pass read (none before the render's first samples).
  void resetEarsBatchSums() { earsBatchBefore_.assign(earsBatchBefore_.size(), PixelSums{}); }
  std::vector<PixelSums> earsBatchBefore_;
  EarsPixelEstimate earsEstimate_;
  bool earsHaveEstimate_ = false;
  EarsGuardOutcome earsGuard_;  // the last render's (EarsGuardPolicy::outcome)
  // The EARS pass in progress, over its tiles: its training part (wavefront and cache update) and the rest.
  double earsPassTrainSeconds_ = 0.0, earsPassLeanSeconds_ = 0.0;
  double earsPassTrainPixelSamples_ = 0.0, earsPassLeanPixelSamples_ = 0.0;
  // The pixel-samples that train in a pass of `samples` a pixel over the whole image (tile by tile).
  double earsTrainingPixelSamples(uint32_t samples) const;
  // Shadow-ray roulette's pixel estimate from every sample so far (the unfolded batch's too), after each pass.
  void refreshPixelEstimate(const Film& film);
  const gpu::FilmPixel* currentBatch(std::vector<gpu::FilmPixel>& copy);
  // The state as of the last pass: seconds, queue occupancy, and the device's unfolded batch.
  void snapshot(RenderState& state, uint32_t inBatch, double seconds, const RenderStats& before);
  uint32_t groupsFor(uint32_t invocations) const;

  vk::Context& ctx_;
  const GpuScene& scene_;
  RenderSettings settings_;
  uint32_t capacity_ = 0;  // camera paths per pass
  uint32_t pool_ = 0;      // path slots: camera paths and split children (sizePathPool)
  bool hasShadowStage_ = true;
  std::unique_ptr<vk::KernelLayout> layout_;
  RenderKernels kernels_;
  std::unique_ptr<vk::GpuTimer> timer_;
  vk::Buffer paths_, hits_, queues_, shadowQueue_, deepWalks_, control_, film_, pixelEstimate_, rouletteTable_, depthStats_,
      queueStats_, pixelFilter_, sampleRuns_;
  vk::Buffer controlMirror_;  // host-visible copy of control_ where control_ is device-local
  std::unique_ptr<EarsCache> ears_;
  std::vector<PilotPath> pilot_;
  void collectPilot(uint32_t pathCount);
  double pipelineSeconds_ = 0.0;
  uint64_t deviceBytes_ = 0;
};

}  // namespace vkmc
