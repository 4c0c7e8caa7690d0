// The depth loop. One submit per pass in the common case: camera rays, a chunk of bounces recorded with
// indirect dispatches (an empty queue costs an empty dispatch), and an accumulate that the device arms only
// once every path has ended. Survivors past the chunk get further chunks.
#include "render/path_renderer.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "../shaders/shared/layout.h"
#include "../shaders/shared/sampling.h"
#include "error.h"
#include "render/path_pool.h"
#include "render/pixel_filter_table.h"
#include "passes/ears_guard_policy.h"
#include "passes/pass_policies.h"
#include "render/time_budget.h"

namespace vkmc {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
constexpr uint32_t kFirstChunkBounces = 24;
constexpr uint32_t kLaterChunkBounces = 16;
constexpr uint32_t kSamplesPerBatch = 64;           // samples in a float batch sum before it is folded into double
constexpr uint32_t kEarsTrainingSeed = 0x5bd1e995;  // their seeds: the render's, xor this
constexpr uint32_t kEarsGuardSeed = 0x27d4eb2f;     // the guard's dropped throughput pass: the render's, xor this
}  // namespace

const char* toString(Integrator i) {
  return i == Integrator::Megakernel ? "megakernel" : i == Integrator::Auto ? "auto" : "wavefront";
}

Integrator integratorFromString(const std::string& name) {
  if (name == "wavefront") return Integrator::Wavefront;
  if (name == "megakernel") return Integrator::Megakernel;
  if (name == "auto") return Integrator::Auto;
  throw Error("unknown integrator '" + name + "' (auto, wavefront or megakernel)");
}

uint32_t PathRenderer::groupsFor(uint32_t n) const { return (n + settings_.workgroupSize - 1) / settings_.workgroupSize; }

PathRenderer::PathRenderer(vk::Context& ctx, const GpuScene& scene, const RenderSettings& settings)
    : ctx_(ctx), scene_(scene), settings_(settings) {
  const auto& limits = ctx.properties().limits;
  checkDeviceLimits(settings, limits);
  const EstimatorConfig& est = settings.estimator;
  if (settings.integrator == Integrator::Auto) throw Error("internal: the integrator must be resolved before a render");
  const bool megakernel = settings.integrator == Integrator::Megakernel;
  if (megakernel && est.splitsPaths())
    throw Error(
        "bsdf_samples > 1 and rr ears split paths, which needs the wavefront integrator's path pool; use --integrator wavefront");
  if (est.needsFloatAtomics() && !ctx.hasFloatAtomics())
    throw Error("light_samples > 1 needs buffer float atomics (VK_EXT_shader_atomic_float), which this device lacks");
  // A scene without emitters has no shadow stage: its queue is not allocated (a placeholder is bound).
  hasShadowStage_ = settings.features.lights() && est.nee && !megakernel;
  const PathPoolSize size = sizePathPool(settings, limits, hasShadowStage_);
  capacity_ = size.cameraPaths;
  pool_ = size.slots;
  allocateBuffers(uint64_t(settings.width) * settings.height, size);
  bindBuffers();
  auto start = Clock::now();
  control_.zero();
  kernels_ = buildRenderKernels(ctx, *layout_, settings, hasShadowStage_, pool_);
  // Ranges of a first chunk at most: the camera rays, 7 a bounce (EARS's copy stage included), the chunk's end.
  timer_ = std::make_unique<vk::GpuTimer>(ctx, 2 * (3 + 7 * kFirstChunkBounces), settings_.stageTimes);
  pipelineSeconds_ = since(start);
}

// Every buffer a pass uses; the megakernel keeps hits and queues in registers, so placeholders stand in for them.
void PathRenderer::allocateBuffers(uint64_t pixels, const PathPoolSize& size) {
  const bool megakernel = settings_.integrator == Integrator::Megakernel;
  auto storage = [&](VkDeviceSize bytes, vk::MemoryKind kind = vk::MemoryKind::DeviceLocal, VkBufferUsageFlags extra = 0) {
    deviceBytes_ += bytes;
    return vk::Buffer(ctx_, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | extra, kind);
  };
  // Path state, hits, queues and shadow rays are also read through texel views (common.glsl). 48 bytes more where
  // a size could be a power of two: llvmpipe keys compiled kernels on whether a texel buffer's is, and the warm-up
  // compiles them for sizes that are not (background_warm_up.cpp).
  auto readAsTexels = [&](VkDeviceSize bytes, uint32_t texelBinding) {
    vk::Buffer b = storage(bytes, vk::MemoryKind::DeviceLocal, VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT);
    b.createView(sceneTexelFormat(texelBinding));
    return b;
  };
  paths_ = readAsTexels(uint64_t(pool_) * sizeof(gpu::PathState), BINDING_PATH_TEXELS);
  hits_ = readAsTexels((megakernel ? 16 : uint64_t(pool_) * 16) + 48, BINDING_HIT_TEXELS);
  const bool ears = settings_.estimator.rr == RouletteMode::Ears;
  queues_ = readAsTexels((megakernel ? 16 : uint64_t(pool_) * 4 * (ears ? 3 : 2)) + 48,
                         BINDING_QUEUE_TEXELS);  // EARS: a copy queue too
  shadowQueue_ = readAsTexels(hasShadowStage_ ? size.shadowSlots * sizeof(gpu::ShadowRay) : 48, BINDING_SHADOW_TEXELS);
  // Room for every item of the larger trace stage, so a deferred walk is never turned away in practice.
  const bool deep = !megakernel && settings_.features.deepWalks;
  deepWalks_ = storage(deep ? std::max<uint64_t>(pool_, size.shadowSlots) * sizeof(uint32_t) : 16);
  // Touched now, not in the first full pass: on lavapipe a buffer's pages are first written by a kernel, and the
  // first pass to fill the pool paid for it (the guard's throughput pass, the first of 28 samples, read 17% slower
  // than the same process's later ones on the Cornell box, which made EARS look better; docs/journal/ears.md).
  ctx_.runCommands([&](VkCommandBuffer cmd) {  // one submit for the five
    for (const vk::Buffer* b : {&paths_, &hits_, &queues_, &shadowQueue_, &deepWalks_}) b->recordZero(cmd);
  });
  // What the host reads or writes every pass: mapped in place on unified memory; on a discrete GPU device-local
  // (the kernels' atomics and the film's read-modify-write stay off the bus), copied at chunk ends and folds.
  const vk::MemoryKind exchange = ctx_.unifiedMemory() ? vk::MemoryKind::HostVisible : vk::MemoryKind::DeviceLocal;
  control_ = storage(sizeof(gpu::Control), exchange, VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
  if (!control_.mapped()) controlMirror_ = vk::Buffer(ctx_, sizeof(gpu::Control), 0, vk::MemoryKind::HostVisible);
  film_ = storage(pixels * sizeof(gpu::FilmPixel), exchange);
  film_.zero();
  pixelEstimate_ =
      storage(notPowerOfTwoTexelBytes(ctx_, pixels * sizeof(glm::vec4)), exchange, VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT);
  pixelEstimate_.createView(sceneTexelFormat(BINDING_PIXEL_ESTIMATE));
  pixelEstimate_.zero();
  rouletteTable_ = storage(gpu::kRouletteTableDepths * sizeof(float), vk::MemoryKind::HostVisible);
  std::array<float, kRouletteTableDepths> noRoulette;
  noRoulette.fill(std::numeric_limits<float>::infinity());
  setRouletteScales(noRoulette);
  depthStats_ =
      storage(settings_.recordDepthStats ? uint64_t(pool_) * gpu::kRouletteTableDepths * 8 : 16, vk::MemoryKind::HostVisible);
  queueStats_ = storage(gpu::kQueueStatsBounces * 8, exchange);
  // Adaptive sampling's runs: a run and a path map word for each camera path at most.
  sampleRuns_ = storage(settings_.sampleRuns ? uint64_t(capacity_) * (gpu::kSampleRunWords + 1) * 4 : 16, exchange);
  // The pixel filter's header and sampling table (read only by filters other than the pixel's box).
  ears_ = std::make_unique<EarsCache>(ctx_, scene_.info(), pool_, settings_.estimator.rr == RouletteMode::Ears,
                                      settings_.estimator.earsLearnsLight(), size.extraShadowSlots);
  deviceBytes_ += ears_->deviceBytes();
  const std::vector<float> filter = pixelFilterBufferData(buildPixelFilterTable(settings_.filter));
  pixelFilter_ = storage(filter.size() * sizeof(float));
  pixelFilter_.upload(filter.data(), filter.size() * sizeof(float));
}

// The control block as the host sees it after a submit (the mirror a chunk's end copied it to, when not mapped).
const gpu::Control& PathRenderer::controlView() const {
  return *static_cast<const gpu::Control*>(control_.mapped() ? control_.mapped() : controlMirror_.mapped());
}

// Zeroes the control block before a pass's first dispatch: in place when mapped, else on the device.
void PathRenderer::resetControl(VkCommandBuffer cmd) {
  if (control_.mapped())
    std::memset(control_.mapped(), 0, sizeof(gpu::Control));
  else
    control_.recordZero(cmd);
}

// Makes the control block readable by the host once `cmd` completes.
void PathRenderer::publishControl(VkCommandBuffer cmd) {
  if (!control_.mapped()) control_.recordCopyTo(cmd, controlMirror_);
}

void PathRenderer::bindBuffers() {
  layout_ = std::make_unique<vk::KernelLayout>(ctx_);
  scene_.bindTo(*layout_);
  layout_->bindStorage(BINDING_PATHS, paths_);
  layout_->bindTexel(BINDING_PATH_TEXELS, paths_);
  layout_->bindTexel(BINDING_HIT_TEXELS, hits_);
  layout_->bindTexel(BINDING_QUEUE_TEXELS, queues_);
  layout_->bindTexel(BINDING_SHADOW_TEXELS, shadowQueue_);
  layout_->bindStorage(BINDING_HITS, hits_);
  layout_->bindStorage(BINDING_RAY_QUEUES, queues_);
  layout_->bindStorage(BINDING_SHADOW_QUEUE, shadowQueue_);
  layout_->bindStorage(BINDING_DEEP_WALKS, deepWalks_);
  layout_->bindStorage(BINDING_CONTROL, control_);
  layout_->bindStorage(BINDING_FILM, film_);
  layout_->bindTexel(BINDING_PIXEL_ESTIMATE, pixelEstimate_);
  layout_->bindStorage(BINDING_ROULETTE_TABLE, rouletteTable_);
  layout_->bindStorage(BINDING_DEPTH_STATS, depthStats_);
  layout_->bindStorage(BINDING_QUEUE_STATS, queueStats_);
  layout_->bindStorage(BINDING_PIXEL_FILTER, pixelFilter_);
  layout_->bindStorage(BINDING_SAMPLE_RUNS, sampleRuns_);
  ears_->bindTo(*layout_);
}

PathRenderer::~PathRenderer() = default;

void PathRenderer::setRouletteScales(const std::array<float, kRouletteTableDepths>& scales) {
  std::memcpy(rouletteTable_.mapped(), scales.data(), sizeof(float) * scales.size());
}

void PathRenderer::collectPilot(uint32_t pathCount) {
  std::vector<gpu::PathState> paths(pathCount);
  paths_.download(paths.data(), pathCount * sizeof(gpu::PathState));
  const auto* stats = static_cast<const glm::vec2*>(depthStats_.mapped());
  for (uint32_t i = 0; i < pathCount; ++i) {
    PilotPath p;
    p.radiance = gpu::luminance(glm::vec3(paths[i].radiance));
    p.lastDepth = paths[i].depth;
    p.pixel = gpu::pathPixelOf(paths[i].pixel);  // without the spectral channel's bits above it
    for (uint32_t d = 0; d < kRouletteTableDepths; ++d) {
      p.beta[d] = stats[i * kRouletteTableDepths + d].x;
      p.gathered[d] = stats[i * kRouletteTableDepths + d].y;
    }
    if (std::isfinite(p.radiance)) pilot_.push_back(p);
  }
}

gpu::PushConstants PathRenderer::passConstants(uint32_t firstPixel, uint32_t pixelCount, uint32_t sampleIndex,
                                               uint32_t samples) const {
  gpu::PushConstants pc{};
  const uint32_t count = pixelCount * samples;
  pc.pathCount = count;
  pc.pixelCount = pixelCount;
  pc.samplesPerPass = samples;
  pc.firstPixel = firstPixel;
  pc.sampleIndex = sampleIndex;
  pc.width = settings_.width;
  pc.height = settings_.height;
  pc.seed = plan_.use == PassUse::Training   ? settings_.seed ^ kEarsTrainingSeed
            : plan_.use == PassUse::Measured ? settings_.seed ^ kEarsGuardSeed
                                             : settings_.seed;
  pc.queueCapacity = pool_;
  const CameraRig& cam = settings_.camera;
  pc.cameraOrigin = glm::vec4(cam.origin, cam.orthographic ? float(gpu::kCameraOrthographic) : float(gpu::kCameraPerspective));
  pc.cameraForward = glm::vec4(cam.forward, 0.0f);
  pc.cameraRight = glm::vec4(cam.right, 0.0f);
  pc.cameraUp = glm::vec4(cam.up, 0.0f);
  pc.background = gpu::encodeBackground(settings_.background, settings_.backdrop);
  return pc;
}

// Ray counts and non-finite values by stage, from the control block after a pass.
void PathRenderer::collectCounters(RenderStats& stats) {
  const gpu::Control* control = &controlView();
  stats.cameraRays += control->cameraRays;
  stats.extensionRays += control->extensionRays;
  stats.shadowRays += control->shadowRays;
  stats.primaryRays += control->cameraRays;
  stats.nonfiniteEmission += control->nonfiniteEmission;
  stats.nonfiniteLightSamples += control->nonfiniteLightSamples;
  stats.nonfiniteThroughput += control->nonfiniteThroughput;
  stats.traversalsCut += control->walksCut;
  stats.deepWalks += control->deepWalksDeferred;
  stats.deepWalksTraced += control->deepWalksTraced;
  stats.splitsRefused += control->splitsRefused;
}

// Submits a command buffer begun with timer_->reset and waits: its GPU time and (where timed) its stages' to stats.
void PathRenderer::submitTimed(VkCommandBuffer cmd, RenderStats& stats) {
  timer_->close(cmd);
  ctx_.submitAndWait(cmd);
  timer_->collect(stats.stageSeconds, &stats.gpuSeconds);
}

// Megakernel: one dispatch follows every path of the pass to its end, then accumulate; one submit.
uint32_t PathRenderer::renderMegakernelPass(const gpu::PushConstants& pc, RenderStats& stats) {
  VkCommandBuffer cmd = ctx_.beginCommands();
  resetControl(cmd);
  timer_->reset(cmd);
  vk::dispatch(cmd, *layout_, *kernels_.megakernel, &pc, sizeof(pc), groupsFor(pc.pathCount), timer_.get());
  vk::dispatch(cmd, *layout_, *kernels_.accumulate, &pc, sizeof(pc), groupsFor(pc.pixelCount), timer_.get());
  publishControl(cmd);
  submitTimed(cmd, stats);
  collectCounters(stats);
  return 0;
}

void PathRenderer::recordCameraRays(VkCommandBuffer cmd, const gpu::PushConstants& pc, uint32_t paths) {
  vk::dispatch(cmd, *layout_, *kernels_.camera, &pc, sizeof(pc), groupsFor(paths), timer_.get());
}

// One bounce: queue sizes into dispatch arguments, intersection (and its deep pass), shading, shadow rays.
void PathRenderer::recordBounce(VkCommandBuffer cmd, const gpu::PushConstants& pc, bool prepared, bool earsTrains) {
  vk::GpuTimer* timer = timer_.get();
  const RenderKernels::BounceKernels stage = kernels_.bounceKernels(earsTrains, plan_.kernels == PassKernels::Throughput);
  if (!prepared) vk::dispatch(cmd, *layout_, *kernels_.prepareBounce, &pc, sizeof(pc), 1, timer);
  // A trace stage's time includes its deep pass (the walks it deferred).
  if (timer) timer->begin(cmd, pc.bounce == 0 ? "intersect_primary" : "intersect");
  vk::dispatchIndirect(cmd, *layout_, *kernels_.intersect, &pc, sizeof(pc), control_, offsetof(gpu::Control, rayArgs));
  if (kernels_.intersectDeep)
    vk::dispatchIndirect(cmd, *layout_, *kernels_.intersectDeep, &pc, sizeof(pc), control_, offsetof(gpu::Control, deepArgs));
  if (timer) timer->end(cmd);
  vk::dispatchIndirect(cmd, *layout_, *stage.shade, &pc, sizeof(pc), control_, offsetof(gpu::Control, rayArgs), timer);
  if (stage.earsCopies) {
    vk::dispatch(cmd, *layout_, *kernels_.prepareCopies, &pc, sizeof(pc), 1, timer);
    vk::dispatchIndirect(cmd, *layout_, *stage.earsCopies, &pc, sizeof(pc), control_, offsetof(gpu::Control, copyArgs), timer);
  }
  if (!hasShadowStage_) return;
  vk::dispatch(cmd, *layout_, *kernels_.prepareShadow, &pc, sizeof(pc), 1, timer);
  if (timer) timer->begin(cmd, "shadow");
  vk::dispatchIndirect(cmd, *layout_, *stage.shadow, &pc, sizeof(pc), control_, offsetof(gpu::Control, shadowArgs));
  if (stage.shadowDeep)
    vk::dispatchIndirect(cmd, *layout_, *stage.shadowDeep, &pc, sizeof(pc), control_, offsetof(gpu::Control, deepArgs));
  if (timer) timer->end(cmd);
}

// The end of a chunk: prepares the next bounce, and accumulates the film once no path is alive (the device arms
// the dispatch).
void PathRenderer::recordAccumulate(VkCommandBuffer cmd, const gpu::PushConstants& pc) {
  vk::dispatch(cmd, *layout_, *kernels_.prepareBounce, &pc, sizeof(pc), 1, timer_.get());
  vk::dispatchIndirect(cmd, *layout_, *kernels_.accumulate, &pc, sizeof(pc), control_, offsetof(gpu::Control, accumulateArgs),
                       timer_.get());
}

uint32_t PathRenderer::renderPass(uint32_t firstPixel, uint32_t pixelCount, uint32_t sampleIndex, uint32_t samples,
                                  RenderStats& stats) {
  if (settings_.integrator == Integrator::Megakernel)
    return renderMegakernelPass(passConstants(firstPixel, pixelCount, sampleIndex, samples), stats);
  if (!ears_->enabled() || plan_.kernels == PassKernels::Throughput)
    return renderWavefront(firstPixel, pixelCount, sampleIndex, samples, false, stats);
  // EARS: the pass's training samples first, as a wavefront of their own whose kernels train the cache; then the
  // cache learns from them, and the rest of the pass runs on kernels without the training code. Every sample's
  // decisions still come from other samples than its own: unbiased. A training pass trains on all its samples.
  ears_->beginPass();
  const uint32_t training = plan_.kernels == PassKernels::EarsTraining ? samples : gpu::earsTrainingSamples(pixelCount, samples);
  const auto trainStart = Clock::now();
  uint32_t bounces = renderWavefront(firstPixel, pixelCount, sampleIndex, training, true, stats);
  trainEars(pixelCount * training, stats);
  earsPassTrainSeconds_ += since(trainStart);
  earsPassTrainPixelSamples_ += double(pixelCount) * training;
  if (training < samples) {
    const auto leanStart = Clock::now();
    bounces =
        std::max(bounces, renderWavefront(firstPixel, pixelCount, sampleIndex + training, samples - training, false, stats));
    earsPassLeanSeconds_ += since(leanStart);
    earsPassLeanPixelSamples_ += double(pixelCount) * (samples - training);
  }
  return bounces;
}

uint32_t PathRenderer::renderWavefront(uint32_t firstPixel, uint32_t pixelCount, uint32_t sampleIndex, uint32_t samples,
                                       bool earsTrains, RenderStats& stats) {
  return renderWavefront(passConstants(firstPixel, pixelCount, sampleIndex, samples), earsTrains, stats);
}

uint32_t PathRenderer::renderWavefront(gpu::PushConstants pc, bool earsTrains, RenderStats& stats) {
  pc.earsTrains = earsTrains ? 1u : 0u;
  const uint32_t count = pc.pathCount;
  if (settings_.recordDepthStats) {  // -1: "no decision recorded at this depth"
    auto* stats = static_cast<float*>(depthStats_.mapped());
    std::fill(stats, stats + size_t(pool_) * kRouletteTableDepths * 2, -1.0f);
  }
  const uint32_t maxDepth = settings_.estimator.maxDepth;
  const uint32_t depthCap = maxDepth == 0 ? UINT32_MAX : maxDepth + 1;  // +1: the last hit's emission
  uint32_t bounce = 0;
  bool first = true;
  while (true) {
    uint32_t chunk = std::min(first ? kFirstChunkBounces : kLaterChunkBounces, depthCap - std::min(depthCap, bounce));
    chunk = std::max(chunk, 1u);
    VkCommandBuffer cmd = ctx_.beginCommands();
    if (first) resetControl(cmd);
    timer_->reset(cmd);
    if (first) recordCameraRays(cmd, pc, count);
    for (uint32_t b = bounce; b < bounce + chunk; ++b) {
      pc.bounce = b;
      recordBounce(cmd, pc, /*prepared=*/!first && b == bounce, earsTrains);  // the last chunk's end prepared its first bounce
    }
    bounce += chunk;
    pc.bounce = bounce;
    recordAccumulate(cmd, pc);
    publishControl(cmd);
    submitTimed(cmd, stats);
    first = false;
    uint32_t alive = controlView().rayQueueCount[bounce & 1u];
    if (alive == 0) break;
    if (bounce >= depthCap) throw Error("internal error: paths alive past the depth cap");
  }
  collectCounters(stats);
  if (settings_.recordDepthStats) collectPilot(count);
  return bounce;
}

void PathRenderer::trainEars(uint32_t cameras, RenderStats& stats) {
  gpu::PushConstants pc{};
  pc.queueCapacity = pool_;
  // The training wavefront's camera paths and the copies they split off (listed by the kernels).
  const uint32_t slots = cameras + ears_->trainingChildren();
  VkCommandBuffer cmd = ctx_.beginCommands();
  timer_->reset(cmd);
  pc.pathCount = cameras;
  vk::dispatch(cmd, *layout_, *kernels_.earsGather, &pc, sizeof(pc), groupsFor(slots), timer_.get());
  vk::dispatch(cmd, *layout_, *kernels_.earsTrain, &pc, sizeof(pc), groupsFor(ears_->trainingRecords() + slots), timer_.get());
  pc.pathCount = ears_->cellCount();
  vk::dispatch(cmd, *layout_, *kernels_.earsFold, &pc, sizeof(pc), groupsFor(pc.pathCount), timer_.get());
  submitTimed(cmd, stats);
  ears_->clearTrainingLists();
}

// The device's unfolded batch: in place where the film is mapped (lavapipe), else downloaded into `copy`.
const gpu::FilmPixel* PathRenderer::currentBatch(std::vector<gpu::FilmPixel>& copy) {
  const auto* batch = static_cast<const gpu::FilmPixel*>(film_.mapped());
  if (batch) return batch;
  copy.resize(size_t(settings_.width) * settings_.height);
  film_.download(copy.data(), copy.size() * sizeof(gpu::FilmPixel));
  return copy.data();
}

// EARS after a pass: V_img of the pass against the earlier passes' estimate, then the next pass's estimate. The
// kernels read the smoothed estimate (EARS reads a denoised one): a pixel's own mean from a few samples is often
// far below its value, which would make t, and V_img's ratios, huge there.
std::vector<PixelSums> PathRenderer::updateEarsStatistics(const Film& film, double raysPerSample) {
  std::vector<gpu::FilmPixel> copy;
  const gpu::FilmPixel* batch = currentBatch(copy);
  std::vector<PixelSums> after = batchPixelSums(batch, film.pixels());
  std::vector<PixelSums> pass = passPixelSums(after, std::move(earsBatchBefore_));
  // Without earlier samples (the first training pass) there is nothing to measure against: V_img 0, no factor,
  // throughput roulette for the next pass too.
  ears_->setImageStatistics(raysPerSample,
                            earsHaveEstimate_ ? earsRelativeVariance(pass, earsEstimate_, gpu::kEarsEpsilon) : 0.0);
  earsBatchBefore_ = std::move(after);
  earsEstimate_ = earsPixelEstimate(runningPixelEstimate(film, batch), settings_.width, settings_.height);
  earsHaveEstimate_ = true;
  setPixelEstimate(earsEstimate_.smoothed);
  return pass;
}

double PathRenderer::earsTrainingPixelSamples(uint32_t samples) const {
  const uint32_t pixels = settings_.width * settings_.height;
  double n = 0.0;
  for (uint32_t first = 0; first < pixels; first += capacity_) {
    const uint32_t tile = std::min(capacity_, pixels - first);
    n += double(tile) * gpu::earsTrainingSamples(tile, samples);
  }
  return n;
}

void PathRenderer::refreshPixelEstimate(const Film& film) {
  std::vector<gpu::FilmPixel> copy;
  setPixelEstimate(runningPixelEstimate(film, currentBatch(copy)));
}

void PathRenderer::foldFilm(Film& film) {
  const size_t pixels = film.pixels();
  if (film_.mapped()) {
    film.addBatch(static_cast<const gpu::FilmPixel*>(film_.mapped()));
  } else {
    std::vector<gpu::FilmPixel> batch(pixels);
    film_.download(batch.data(), pixels * sizeof(gpu::FilmPixel));
    film.addBatch(batch.data());
  }
  // Under EARS the estimate of the passes so far, as updateEarsStatistics computed it from the film this folds
  // (once the guard has fallen back to passes that do not learn, the film's own, as without EARS).
  if (ears_->enabled() && earsHaveEstimate_ && (!policy_ || policy_->learning()))
    setPixelEstimate(earsEstimate_.smoothed);
  else
    uploadPixelEstimate(film);
  film_.zero();
  resetEarsBatchSums();
}

void PathRenderer::setPixelEstimate(const std::vector<glm::vec4>& estimate) {
  pixelEstimate_.upload(estimate.data(), estimate.size() * sizeof(glm::vec4));
}

Film PathRenderer::render(RenderStats& stats) {
  RenderState state;
  state.stats = stats;
  render(state, RenderControl{});
  stats = state.stats;
  return std::move(state.film);
}

uint32_t PathRenderer::samplesPerPass() const {
  const uint32_t pixels = settings_.width * settings_.height;
  return std::clamp(capacity_ / std::max(pixels, 1u), 1u, kSamplesPerBatch);
}

uint32_t PathRenderer::samplesPerBatch() const { return kSamplesPerBatch / samplesPerPass() * samplesPerPass(); }

void PathRenderer::renderSamples(uint32_t s, uint32_t samples, RenderStats& stats) {
  const uint32_t pixels = settings_.width * settings_.height;
  earsPassTrainSeconds_ = earsPassLeanSeconds_ = earsPassTrainPixelSamples_ = earsPassLeanPixelSamples_ = 0.0;
  if (!settings_.stageTimes) stats.stagesUntimed = true;
  for (uint32_t first = 0; first < pixels; first += capacity_) {
    uint32_t bounces = renderPass(first, std::min(capacity_, pixels - first), s, samples, stats);
    stats.maxBounces = std::max(stats.maxBounces, bounces);
    ++stats.passes;
  }
}

// Packs the runs into passes of at most capacity_ camera paths, a run split where a pass fills. A pass holds a
// pixel once (accumulate adds without atomics): a run whose pixel the pass holds already starts the next pass.
bool PathRenderer::renderSampleRuns(const std::vector<PixelSamples>& work, RenderStats& stats,
                                    const std::function<bool()>& afterPass) {
  if (!settings_.sampleRuns) throw Error("internal error: a renderer without sample runs asked to render them");
  if (ears_->enabled()) throw Error("internal error: rr ears renders pixel ranges only");
  if (!settings_.stageTimes) stats.stagesUntimed = true;
  std::vector<uint32_t> runs, pathRun;
  std::vector<uint32_t> passOfPixel(size_t(settings_.width) * settings_.height, UINT32_MAX);
  uint32_t pass = 0;
  bool goOn = true;
  auto flush = [&] {
    if (pathRun.empty()) return;
    const uint32_t count = uint32_t(runs.size() / gpu::kSampleRunWords);
    runs.insert(runs.end(), pathRun.begin(), pathRun.end());
    sampleRuns_.upload(runs.data(), runs.size() * sizeof(uint32_t));
    gpu::PushConstants pc = passConstants(0, count, 0, 1);
    pc.pathCount = uint32_t(pathRun.size());
    pc.sampleRuns = 1;
    const uint32_t bounces =
        settings_.integrator == Integrator::Megakernel ? renderMegakernelPass(pc, stats) : renderWavefront(pc, false, stats);
    stats.maxBounces = std::max(stats.maxBounces, bounces);
    ++stats.passes, ++pass;
    runs.clear(), pathRun.clear();
    goOn = afterPass();
  };
  for (const PixelSamples& w : work) {
    if (passOfPixel.at(w.pixel) == pass) flush();
    for (uint32_t done = 0; done < w.samples && goOn;) {
      const uint32_t take = std::min(w.samples - done, capacity_ - uint32_t(pathRun.size()));
      const uint32_t run = uint32_t(runs.size() / gpu::kSampleRunWords);
      runs.insert(runs.end(), {w.pixel, uint32_t(pathRun.size()), take, w.firstSample + done});
      pathRun.insert(pathRun.end(), take, run);
      passOfPixel[w.pixel] = pass;
      done += take;
      if (pathRun.size() == capacity_) flush();
    }
    if (!goOn) return false;
  }
  flush();
  return goOn;
}

bool PathRenderer::renderSampleRunsInto(Film& film, const std::vector<PixelSamples>& work, RenderStats& stats,
                                        const std::function<bool()>& goOn) {
  return renderSampleRuns(work, stats, [&] {
    const std::vector<gpu::FilmPixel> batch = takeBatch();
    film.addBatch(batch.data());
    return !goOn || goOn();
  });
}

std::vector<gpu::FilmPixel> PathRenderer::takeBatch() {
  std::vector<gpu::FilmPixel> batch(size_t(settings_.width) * settings_.height);
  film_.download(batch.data(), batch.size() * sizeof(gpu::FilmPixel));
  film_.zero();
  return batch;
}

void PathRenderer::restoreBatch(const std::vector<gpu::FilmPixel>& batch) {
  film_.upload(batch.data(), batch.size() * sizeof(gpu::FilmPixel));
}

void PathRenderer::finishStats(RenderStats& stats, const RenderStats& before) {
  stats.deriveStageTotals();
  // Queue occupancy: this run's device counters over what the stats held when it started.
  std::vector<glm::uvec2> queueStats(gpu::kQueueStatsBounces);
  queueStats_.download(queueStats.data(), gpu::kQueueStatsBounces * sizeof(glm::uvec2));
  stats.pathsByBounce = before.pathsByBounce;
  stats.shadowRaysByBounce = before.shadowRaysByBounce;
  stats.pathsByBounce.resize(gpu::kQueueStatsBounces, 0);
  stats.shadowRaysByBounce.resize(gpu::kQueueStatsBounces, 0);
  for (uint32_t b = 0; b < gpu::kQueueStatsBounces; ++b) {
    stats.pathsByBounce[b] += queueStats[b].x;
    stats.shadowRaysByBounce[b] += queueStats[b].y;
  }
}

void PathRenderer::snapshot(RenderState& state, uint32_t inBatch, double seconds, const RenderStats& before) {
  const size_t pixels = state.film.pixels();
  state.batchSamples = inBatch;
  state.batch.clear();
  if (inBatch > 0) {
    state.batch.resize(pixels);
    film_.download(state.batch.data(), pixels * sizeof(gpu::FilmPixel));
  }
  state.stats.seconds = seconds;
  state.stats.samplesPerPixel = state.nextSample;
  finishStats(state.stats, before);
}

// The film and the device's batch of a new or a resumed render; returns the samples already in the batch.
uint32_t PathRenderer::prepareFilm(RenderState& state, bool shadowRoulette) {
  const uint32_t pixels = settings_.width * settings_.height;
  if (state.film.pixels() == 0) {
    state.film = Film(settings_.width, settings_.height);
  } else if (state.film.width != settings_.width || state.film.height != settings_.height) {
    throw Error("internal error: resumed film size differs from the render's");
  }
  state.film.replicateVariance = settings_.estimator.sampler != Sampler::Independent;
  state.film.replicates = settings_.estimator.replicates;
  state.interrupted = false;
  queueStats_.zero();
  // A resumed render continues the device's float batch where it stopped, with the estimate of the folded film.
  const uint32_t inBatch = state.batchSamples;
  if (inBatch > 0) film_.upload(state.batch.data(), size_t(pixels) * sizeof(gpu::FilmPixel));
  // Shadow-ray roulette refreshes its estimate after every pass, from the batch too, where the film is mapped
  // (a discrete GPU would download the film each pass: there, at each fold, as before). A resume does the same.
  // Under EARS both read EARS's smoothed estimate instead (updateEarsStatistics): as unbiased.
  if (shadowRoulette)
    refreshPixelEstimate(state.film);
  else if (state.film.totalSamples() + state.film.totalNonfinite() > 0)
    uploadPixelEstimate(state.film);
  state.batch.clear();
  state.batchSamples = 0;
  return inBatch;
}

// EARS before the render's passes: its statistics' start, from a resumed render's folded film where there is one.
void PathRenderer::startEars(RenderState& state, uint32_t& inBatch) {
  const uint32_t pixels = settings_.width * settings_.height;
  earsHaveEstimate_ = false;                           // nothing from an earlier render() on this renderer
  if (inBatch > 0) foldFilm(state.film), inBatch = 0;  // the training passes' samples are dropped from the batch
  earsBatchBefore_.assign(pixels, PixelSums{});
  earsHaveEstimate_ = state.film.totalSamples() > 0;  // a resumed render's: the folded film's, smoothed
  if (earsHaveEstimate_) {
    earsEstimate_ = earsPixelEstimate(runningPixelEstimate(state.film), settings_.width, settings_.height);
    setPixelEstimate(earsEstimate_.smoothed);
  }
}

std::unique_ptr<PassPolicy> PathRenderer::passPolicy(bool shadowRoulette) const {
  if (ears_->enabled()) {
    EarsGuardSettings s;
    s.fallback = settings_.estimator.earsFallback;
    s.compares = settings_.estimator.earsMayFallBack();
    s.timeBudget = settings_.timeBudget;
    s.maxPassSamples = samplesPerPass();
    s.pixels = double(settings_.width) * settings_.height;
    s.trainingPixelSamples = earsTrainingPixelSamples(samplesPerPass());
    return std::make_unique<EarsGuardPolicy>(s);
  }
  if (shadowRoulette) return std::make_unique<ShadowRoulettePacing>();
  return std::make_unique<UniformPasses>();
}

void PathRenderer::dropBatch() {
  film_.zero();
  resetEarsBatchSums();
  batchHoldsTraining_ = false;
}

// Carries out one plan: its batch (a measured pass gets one of its own and drops it; training passes follow the
// kept samples' fold, and their batch is dropped when training ends), its seed and kernels, then what learns from
// it: EARS's statistics, or the plain pixel estimate that shadow roulette reads.
PassOutcome PathRenderer::runPlannedPass(const PassPlan& plan, RenderState& state, uint32_t& inBatch, bool shadowRoulette) {
  const uint32_t pixels = settings_.width * settings_.height;
  if (plan.use != PassUse::Image && inBatch > 0) foldFilm(state.film), inBatch = 0;
  if (plan.use != PassUse::Training && batchHoldsTraining_) dropBatch();
  plan_ = plan;
  PassOutcome o;
  o.plan = plan;
  const uint64_t raysBefore = state.stats.rays();
  const double passStart = since(passesStart_);
  renderSamples(plan.use == PassUse::Training ? droppedIndex_ : state.nextSample, plan.samples, state.stats);
  o.seconds = since(passesStart_) - passStart;
  o.trainSeconds = earsPassTrainSeconds_, o.leanSeconds = earsPassLeanSeconds_;
  o.trainPixelSamples = earsPassTrainPixelSamples_, o.leanPixelSamples = earsPassLeanPixelSamples_;
  if (plan.use == PassUse::Measured) {
    std::vector<gpu::FilmPixel> copy;
    const gpu::FilmPixel* batch = currentBatch(copy);
    passSums_ = batchPixelSums(batch, state.film.pixels());
    passScale_ = earsPixelEstimate(runningPixelEstimate(state.film, batch), settings_.width, settings_.height).smoothed;
    dropBatch();
    o.sums = &passSums_, o.scale = &passScale_;
  } else if (plan.learns) {
    passSums_ = updateEarsStatistics(state.film, double(state.stats.rays() - raysBefore) / (double(pixels) * plan.samples));
    o.sums = &passSums_, o.scale = &earsEstimate_.smoothed;  // the estimate the next pass reads
  } else if (shadowRoulette) {
    refreshPixelEstimate(state.film);
  }
  if (plan.use == PassUse::Image) state.nextSample += plan.samples, inBatch += plan.samples;
  if (plan.use == PassUse::Training) {
    droppedIndex_ += plan.samples;
    batchHoldsTraining_ = true;
    ears_->noteTrainingSamples(plan.samples);
  }
  o.nextSample = state.nextSample;
  o.elapsed = since(passesStart_);
  plan_ = PassPlan{};
  return o;
}

void PathRenderer::printProgress(uint32_t s, uint32_t firstSample, double elapsed, double secondsBefore,
                                 const RenderStats& stats) const {
  const double budget = settings_.timeBudget;
  double eta = budget > 0.0 ? std::max(0.0, budget - elapsed) : elapsed / (s - firstSample) * (settings_.spp - s);
  std::fprintf(stderr, "\rvkmc: %u/%u spp  %.2f Mrays/s  ETA %.1f s   ", s, settings_.spp,
               stats.rays() / std::max(secondsBefore + elapsed, 1e-9) * 1e-6, eta);
  std::fflush(stderr);
}

// The pass loop: the policy plans each pass (pass_policy.h); a time budget sizes them and stops the render, as a
// stop request does. Image passes are folded, checkpointed and shown; the others only measure or train.
void PathRenderer::render(RenderState& state, const RenderControl& control) {
  RenderStats& stats = state.stats;
  const RenderStats before = stats;
  const double secondsBefore = stats.seconds;
  const bool showProgress = settings_.progress && isatty(STDERR_FILENO);
  const bool shadowRoulette = settings_.estimator.shadowRrThreshold > 0.0f && ctx_.unifiedMemory();
  uint32_t inBatch = prepareFilm(state, shadowRoulette);
  passesStart_ = Clock::now();
  droppedIndex_ = 0, batchHoldsTraining_ = false;
  policy_ = passPolicy(shadowRoulette);
  PassPolicy* policy = policy_.get();
  if (ears_->enabled()) startEars(state, inBatch);
  const double budget = settings_.timeBudget;
  PassContext context;
  context.spp = settings_.spp;
  context.maxPassSamples = samplesPerPass();
  // A time budget (time_budget.h): the first pass takes one sample (a slow scene must not overrun by much), the
  // later ones are sized from the last pass's seconds a sample.
  context.passSamples = budget > 0.0 ? 1u : context.maxPassSamples;
  double secondsPerSample = 0.0, lastProgress = 0.0, lastCheckpoint = 0.0;
  const uint32_t firstSample = state.nextSample;
  auto budgetSpent = [&] { return timeBudgetSpent(budget, since(passesStart_)); };
  while (true) {
    if (state.nextSample > firstSample && budgetSpent()) break;
    if (control.stop && control.stop->load() != 0) {
      state.interrupted = true;
      state.stopSignal = control.stop->load();
      break;
    }
    context.nextSample = state.nextSample;
    context.elapsed = since(passesStart_);
    if (secondsPerSample > 0.0)
      context.passSamples = timeBudgetPassSamples(budget, context.elapsed, secondsPerSample, context.maxPassSamples);
    const PassPlan plan = policy->next(context);
    if (plan.stop()) break;
    const double passStart = since(passesStart_);
    policy->record(runPlannedPass(plan, state, inBatch, shadowRoulette));
    // The pass's seconds with what the host does after it (EARS's statistics, the guard): the next pass pays them too.
    if (budget > 0.0 && plan.use != PassUse::Measured)
      secondsPerSample = std::max(since(passesStart_) - passStart, 1e-6) / plan.samples;
    if (plan.use != PassUse::Image) continue;
    const bool last = state.nextSample == settings_.spp || budgetSpent();
    if (inBatch + context.maxPassSamples > kSamplesPerBatch || last) foldFilm(state.film), inBatch = 0;
    const double elapsed = since(passesStart_);
    if (control.checkpoint && control.checkpointEvery > 0.0 && elapsed - lastCheckpoint >= control.checkpointEvery && !last) {
      snapshot(state, inBatch, secondsBefore + elapsed, before);
      control.checkpoint(state);
      lastCheckpoint = since(passesStart_);
    }
    if (showProgress && (elapsed - lastProgress > 0.25 || last))
      lastProgress = elapsed, printProgress(state.nextSample, firstSample, elapsed, secondsBefore, stats);
  }
  if (showProgress) std::fprintf(stderr, "\n");
  if (batchHoldsTraining_) dropBatch();  // stopped during training: its samples are not the image's
  context.nextSample = state.nextSample;
  context.elapsed = since(passesStart_);
  policy->finish(context, firstSample);
  if (const auto* ears = dynamic_cast<const EarsGuardPolicy*>(policy)) earsGuard_ = ears->outcome();
  snapshot(state, inBatch, secondsBefore + since(passesStart_), before);
}

}  // namespace vkmc
