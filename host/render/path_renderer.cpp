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
#include "render/time_budget.h"

namespace vkmc {

namespace {
// The samples a pixel of EARS the guard measures (each look), and the fewest of throughput roulette (a sample
// variance needs two; a short render's budget should not go to the comparison).
constexpr uint32_t kEarsGuardSamples = 4;
// EARS's passes before the one the guard measures: the first after training decides from a cache that has learned
// from a few samples a pixel, and measured 0.6x the efficiency of later passes on two_rooms (docs/journal/ears.md).
constexpr uint32_t kEarsGuardWarmPasses = 1;
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
constexpr uint32_t kFirstChunkBounces = 24;
constexpr uint32_t kLaterChunkBounces = 16;
constexpr uint32_t kSamplesPerBatch = 64;           // samples in a float batch sum before it is folded into double
constexpr uint32_t kEarsTrainingPasses = 3;         // EARS's passes that only train (1, 2 and 4 spp)
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
    p.pixel = paths[i].pixel;
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
  pc.seed = earsTraining_ && !earsTrainingKept_          ? settings_.seed ^ kEarsTrainingSeed
            : earsPhase_ == EarsPhase::MeasureThroughput ? settings_.seed ^ kEarsGuardSeed
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
  const RenderKernels::BounceKernels stage = kernels_.bounceKernels(earsTrains, throughputPass());
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
  if (!ears_->enabled() || throughputPass()) return renderWavefront(firstPixel, pixelCount, sampleIndex, samples, false, stats);
  // EARS: the pass's training samples first, as a wavefront of their own whose kernels train the cache; then the
  // cache learns from them, and the rest of the pass runs on kernels without the training code. Every sample's
  // decisions still come from other samples than its own: unbiased. A training pass trains on all its samples.
  ears_->beginPass();
  const uint32_t training = earsTraining_ ? samples : gpu::earsTrainingSamples(pixelCount, samples);
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

// EARS's training passes (kEarsTrainingPasses of 1, 2, 4... spp): they fill the cache and the pixel estimate. The
// first, from an empty cache, is throughput roulette's estimator and stays in the image; the later ones are
// dropped, so the image holds no sample whose decisions came from a barely trained cache (the first passes'
// outliers). Dropping passes chosen in advance is unbiased; their own seed keeps every image sample's random
// numbers apart from those that trained its decisions. Their rays and time are the render's cost. Returns the
// next pass's size.
uint32_t PathRenderer::trainEarsPasses(Film& film, uint32_t& nextSample, RenderStats& stats, Clock::time_point start) {
  const uint32_t pixels = settings_.width * settings_.height;
  uint32_t samples = 1;
  earsTraining_ = true;
  earsOutOfBudget_ = false;
  earsLastPassSecondsPerSample_ = 0.0;
  double firstPassSeconds = 0.0;
  double throughputOverhead = -1.0;  // a pass's fixed seconds, once two throughput passes have measured it
  uint32_t droppedIndex = 0;         // the dropped passes' samples follow each other in their own seed's sequence
  // Under a time budget where the guard may fall back, the first pass is throughput roulette's own (its lean
  // kernels, no training): what it costs says whether learning fits before any training kernel has run (on the
  // stiff furnace one training pass was a quarter of a 4-s budget).
  const bool throughputFirst = settings_.timeBudget > 0.0 && settings_.estimator.earsMayFallBack();
  // What learning still needs after a pass of perSample seconds a sample: the training passes left and, where the
  // guard will compare, a warm-up sample (a budget's first pass takes one), two looks of EARS and throughput
  // roulette's measured passes (whole passes until 4 samples a pixel: measureThroughputForGuard). Those are costed
  // from the first pass: its fixed overhead a pass (measured by a second throughput pass; until then each pass is
  // costed as one first pass, which is optimistic, but every check counts what has elapsed, so the budget's share
  // holds) and the rest by samples.
  auto learningFits = [&](uint32_t pass, uint32_t nextPassSamples, double perSample) {
    uint32_t trainingLeft = 0;
    for (uint32_t later = pass + 1, n = nextPassSamples; later < kEarsTrainingPasses;
         ++later, n = std::min(2 * n, samplesPerPass()))
      trainingLeft += n;
    const bool compares = earsGuardPending_;
    const uint32_t throughputPasses = (kEarsGuardSamples + samplesPerPass() - 1) / samplesPerPass();
    const double overhead = throughputOverhead >= 0.0 ? throughputOverhead : firstPassSeconds;
    const double throughputSeconds = compares ? earsThroughputPassSeconds(firstPassSeconds, 1u, overhead, throughputPasses,
                                                                          throughputPasses * samplesPerPass())
                                              : 0.0;
    const double left = earsLearningSecondsLeft(trainingLeft, compares ? kEarsGuardWarmPasses + 2 * kEarsGuardSamples : 0u,
                                                perSample, throughputSeconds);
    return !(trainingLeft > 0 || compares) || earsLearningFits(settings_.timeBudget, since(start), left);
  };
  for (uint32_t pass = 0; pass < kEarsTrainingPasses && nextSample < settings_.spp; ++pass) {
    const uint64_t raysBefore = stats.rays();
    const auto passStart = Clock::now();
    // The first pass learns from nothing, so it decides everywhere as throughput roulette does: it is an image
    // pass (the render's seed and next sample) and stays; the later ones decide from what it taught and are dropped.
    earsTrainingKept_ = pass == 0;
    const EarsPhase phase = earsPhase_;
    if (pass == 0 && throughputFirst) earsPhase_ = EarsPhase::Throughput;
    renderSamples(earsTrainingKept_ ? nextSample : droppedIndex, samples, stats);
    earsPhase_ = phase;
    if (!earsTrainingKept_) droppedIndex += samples;
    const double passSeconds = since(passStart);
    const double perSample = passSeconds / samples;
    earsLastPassSecondsPerSample_ = perSample;
    if (pass == 0) firstPassSeconds = passSeconds;
    updateEarsStatistics(film, double(stats.rays() - raysBefore) / (double(pixels) * samples));
    if (earsTrainingKept_) {
      foldFilm(film);
      nextSample += samples;
      earsTrainingKept_ = false;
    } else {
      ears_->noteTrainingSamples(samples);
    }
    samples = std::min(2 * samples, samplesPerPass());
    if (!learningFits(pass, samples, perSample)) {
      earsOutOfBudget_ = true;
      break;
    }
    // A second throughput pass tells a pass's fixed overhead from its cost a sample (the guard's costing needs it).
    if (pass == 0 && throughputFirst && earsGuardPending_ && samplesPerPass() >= 2 && nextSample + 2 <= settings_.spp) {
      throughputOverhead = measureThroughputPassOverhead(film, nextSample, stats, firstPassSeconds);
      earsGuard_.passOverhead = throughputOverhead;
      if (!learningFits(pass, samples, perSample)) {
        earsOutOfBudget_ = true;
        break;
      }
    }
  }
  earsTraining_ = false;
  film_.zero();
  resetEarsBatchSums();
  return samples;
}

// A second pass of throughput roulette's own, of 2 samples a pixel and kept: with the first it tells a pass's fixed
// overhead from its cost a sample (t = a + b n). A 1-spp pass is mostly overhead (dark_room at 96x96: 0.0375 s a
// sample, against 0.0085 in a 28-spp pass), and costing the guard's measured pass at its seconds a sample stopped
// learning even under a 32-s budget there (docs/journal/ears.md). Returns that overhead in seconds.
double PathRenderer::measureThroughputPassOverhead(Film& film, uint32_t& nextSample, RenderStats& stats,
                                                   double firstPassSeconds) {
  const uint32_t pixels = settings_.width * settings_.height;
  const uint64_t raysBefore = stats.rays();
  const auto start = Clock::now();
  const EarsPhase phase = earsPhase_;
  earsTrainingKept_ = true;
  earsPhase_ = EarsPhase::Throughput;
  renderSamples(nextSample, 2, stats);
  earsPhase_ = phase;
  const double seconds = since(start);
  earsLastPassSecondsPerSample_ = seconds / 2.0;
  updateEarsStatistics(film, double(stats.rays() - raysBefore) / (double(pixels) * 2));
  foldFilm(film);
  nextSample += 2;
  earsTrainingKept_ = false;
  return earsPassOverhead(firstPassSeconds, 1, seconds, 2, firstPassSeconds);
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

// After a pass under EARS: its statistics, or the guard's measurement of EARS (ears_guard.h; throughput roulette's is
// measureThroughputForGuard's, whose V_img stays out of EARS's factors).
void PathRenderer::afterEarsPass(const Film& film, double raysPerSample, double seconds, uint32_t samples, uint32_t nextSample) {
  switch (earsPhase_) {
    case EarsPhase::Ears: {
      std::vector<PixelSums> pass = updateEarsStatistics(film, raysPerSample);
      if (earsGuard_.watched && !earsGuard_.fellBack) watchEars(pass, samples, seconds, nextSample);
      if (earsGuardPending_ && ++earsWarmPasses_ >= kEarsGuardWarmPasses) earsPhase_ = EarsPhase::MeasureEars;
      return;
    }
    case EarsPhase::Throughput:
      // Shadow-ray roulette's estimate from every sample so far, as without EARS.
      if (settings_.estimator.shadowRrThreshold > 0.0f && ctx_.unifiedMemory()) refreshPixelEstimate(film);
      return;
    case EarsPhase::MeasureEars:
    case EarsPhase::MeasureEarsAgain:
      addEarsPassToTally(updateEarsStatistics(film, raysPerSample), samples, seconds);
      if (earsTally_.samples < kEarsGuardSamples) return;
      if (earsPhase_ == EarsPhase::MeasureEars)
        earsPhase_ = EarsPhase::MeasureThroughput;
      else
        decideEarsGuard(nextSample, true);
      return;
    case EarsPhase::MeasureThroughput:  // measureThroughputForGuard's
      return;
  }
}

// The guard's throughput roulette pass: rendered on a batch of its own (the caller folds the film first) with its
// own seed, measured, then dropped, a rule fixed in advance (unbiased, as EARS's training passes). Had it stayed,
// an image that EARS goes on to render would hold samples of the policy that lost: on two_rooms, where a sample of
// EARS has a fifth of throughput roulette's variance, 28 of them in 173 made the 4-s image 0.79x as efficient as
// EARS's alone.
void PathRenderer::measureThroughputForGuard(const Film& film, uint32_t sampleIndex, uint32_t samples, RenderStats& stats) {
  const auto start = Clock::now();
  renderSamples(sampleIndex, samples, stats);
  const double seconds = since(start);
  std::vector<gpu::FilmPixel> copy;
  const gpu::FilmPixel* batch = currentBatch(copy);
  throughputTally_.addPass(batchPixelSums(batch, film.pixels()), samples, seconds);
  // What both policies' variances are relative to: the smoothed estimate with this pass's samples too (an estimate
  // from the few samples before it left pixels near veach_mis's small lamps near 0, and V in the hundreds).
  earsGuardScale_ = earsPixelEstimate(runningPixelEstimate(film, batch), settings_.width, settings_.height).smoothed;
  film_.zero();
  resetEarsBatchSums();
  if (throughputTally_.samples >= kEarsGuardSamples) decideEarsGuard(sampleIndex, false);
}

void PathRenderer::addEarsPassToTally(const std::vector<PixelSums>& pass, uint32_t samples, double seconds) {
  earsTally_.addPass(pass, samples, seconds);
  earsTally_.trainSeconds += earsPassTrainSeconds_;
  earsTally_.leanSeconds += earsPassLeanSeconds_;
  earsTally_.trainPixelSamples += earsPassTrainPixelSamples_;
  earsTally_.leanPixelSamples += earsPassLeanPixelSamples_;
}

// Each policy's measure from its tally, its variances relative to `scale`: EARS's seconds a sample as in a pass of
// its later size.
PolicyPass PathRenderer::earsMeasure(const std::vector<glm::vec4>& scale) const {
  const uint32_t later = samplesPerPass();
  return {relativeSampleVariance(earsTally_.sums, scale, gpu::kEarsEpsilon),
          earsSecondsPerSample(earsTally_, double(settings_.width) * settings_.height, later, earsTrainingPixelSamples(later)),
          earsTally_.samples};
}
PolicyPass PathRenderer::throughputMeasure(const std::vector<glm::vec4>& scale) const {
  return {relativeSampleVariance(throughputTally_.sums, scale, gpu::kEarsEpsilon),
          throughputTally_.seconds / throughputTally_.samples, throughputTally_.samples};
}

// EARS's passes after auto chose it, measured together against throughput roulette's pass, both relative to the
// latest estimate: where EARS falls behind, throughput roulette renders the rest (EarsGuardOutcome::watched).
void PathRenderer::watchEars(const std::vector<PixelSums>& pass, uint32_t samples, double seconds, uint32_t nextSample) {
  addEarsPassToTally(pass, samples, seconds);
  // Judged on no fewer samples a pixel than throughput roulette's measure, nor than the choice's.
  if (earsTally_.samples < std::max(kEarsGuardSamples, throughputTally_.samples)) return;
  const PolicyPass ears = earsMeasure(earsEstimate_.smoothed), throughput = throughputMeasure(earsEstimate_.smoothed);
  if (!(std::isfinite(ears.relativeVariance) && std::isfinite(throughput.relativeVariance))) return;
  earsGuard_.watchedEars = ears;
  if (!earsFallsBack(EarsFallback::Auto, ears, throughput)) return;
  earsGuard_.fellBack = earsGuard_.switchedLater = true;
  earsGuard_.switchedAt = nextSample;
  earsPhase_ = EarsPhase::Throughput;
  earsTally_ = throughputTally_ = PolicyTally{};
}

void PathRenderer::decideEarsGuard(uint32_t nextSample, bool secondLook) {
  earsPhase_ = EarsPhase::Ears;
  // A second look's estimate holds EARS's next pass: as many samples as the first look's scale, or more.
  const std::vector<glm::vec4>& scale = secondLook ? earsEstimate_.smoothed : earsGuardScale_;
  const PolicyPass ears = earsMeasure(scale), throughput = throughputMeasure(scale);
  const double vEars = ears.relativeVariance, vThroughput = throughput.relativeVariance;
  const EarsFallback mode = settings_.estimator.earsFallback;
  if (!(std::isfinite(vEars) && std::isfinite(vThroughput))) {
    // Nothing to compare (no pixel with two samples): EARS as chosen, or after a first look that EARS lost, the
    // first look's verdict.
    if (secondLook) {
      earsGuard_.ears = earsGuard_.firstEars;
      earsGuard_.compared = earsGuard_.fellBack = true;
      earsGuard_.fromSample = nextSample;
      earsGuard_.decidedAtSeconds = since(passesStart_);
      earsPhase_ = EarsPhase::Throughput;
    }
  } else if (!secondLook && earsGuardLooksAgain(mode, ears, throughput)) {
    earsGuard_.secondLook = true;
    earsGuard_.firstEars = ears;
    earsGuard_.throughput = throughput;
    earsTally_ = PolicyTally{};  // throughput roulette's tally stays, measured against the later estimate
    earsPhase_ = EarsPhase::MeasureEarsAgain;
    return;
  } else {
    earsGuard_.ears = ears;
    earsGuard_.throughput = throughput;
    earsGuard_.compared = true;
    earsGuard_.fellBack = earsFallsBack(mode, ears, throughput);
    earsGuard_.fromSample = nextSample;
    earsGuard_.decidedAtSeconds = since(passesStart_);
    if (earsGuard_.fellBack) earsPhase_ = EarsPhase::Throughput;
  }
  earsGuardPending_ = false;
  earsTally_ = PolicyTally{};
  // Chosen under auto, EARS is watched from here on against throughput roulette's pass, which stays.
  earsGuard_.watched = earsGuard_.compared && !earsGuard_.fellBack && earsGuardWatches(mode);
  if (!earsGuard_.watched) throughputTally_ = PolicyTally{};
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
  // (once the guard has fallen back, the film's own, as without EARS).
  if (ears_->enabled() && earsHaveEstimate_ && earsPhase_ != EarsPhase::Throughput)
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

// EARS before the render's own passes: its estimate, its guard's state, and its training passes. Returns the
// next EARS pass's size; folds the batch (inBatch 0) and, under a budget, sets the next pass's seconds a sample.
uint32_t PathRenderer::startEars(RenderState& state, uint32_t& inBatch, Clock::time_point start, double& secondsPerSample) {
  const uint32_t pixels = settings_.width * settings_.height;
  earsHaveEstimate_ = false;                           // nothing from an earlier render() on this renderer
  if (inBatch > 0) foldFilm(state.film), inBatch = 0;  // the training passes' samples are dropped from the batch
  earsBatchBefore_.assign(pixels, PixelSums{});
  earsHaveEstimate_ = state.film.totalSamples() > 0;  // a resumed render's: the folded film's, smoothed
  if (earsHaveEstimate_) {
    earsEstimate_ = earsPixelEstimate(runningPixelEstimate(state.film), settings_.width, settings_.height);
    setPixelEstimate(earsEstimate_.smoothed);
  }
  // The guard starts over (before the training passes, which must run EARS's kernels).
  earsGuard_ = EarsGuardOutcome{};
  earsTally_ = throughputTally_ = PolicyTally{};
  earsGuardPending_ = settings_.estimator.earsMayFallBack();
  earsWarmPasses_ = 0;
  earsPhase_ = EarsPhase::Ears;
  const uint32_t earsSamples = trainEarsPasses(state.film, state.nextSample, state.stats, start);
  // Under a budget the next pass is sized from the training's last, as the loop's own passes are from theirs (it
  // would otherwise start over at 1 sample a pixel: one more pass of fixed cost).
  if (settings_.timeBudget > 0.0) secondsPerSample = earsLastPassSecondsPerSample_;
  if (earsGuardPending_ && kEarsGuardWarmPasses == 0) earsPhase_ = EarsPhase::MeasureEars;
  if (earsOutOfBudget_) {  // no comparison: throughput roulette where the guard may fall back, else EARS
    earsGuardPending_ = false;
    earsGuard_.outOfBudget = true;
    earsGuard_.fromSample = state.nextSample;
    earsGuard_.decidedAtSeconds = since(start);
    earsGuard_.fellBack = settings_.estimator.earsFallback != EarsFallback::Never;
    earsPhase_ = earsGuard_.fellBack ? EarsPhase::Throughput : EarsPhase::Ears;
  }
  return earsSamples;
}

// The next pass's samples a pixel from sample s: the guard's measured EARS samples, EARS's doubling passes, shadow
// roulette's s + 1, or the pass size; never past spp.
uint32_t PathRenderer::nextPassSamples(uint32_t s, uint32_t perPass, uint32_t earsSamples, bool shadowRoulette) const {
  // The guard measures kEarsGuardSamples a pixel of EARS at each look, in passes no larger than the others: the
  // cache learns from a pass's first samples only (earsTrainingSamples), so a larger second look learns no more.
  const bool measuresEars = earsPhase_ == EarsPhase::MeasureEars || earsPhase_ == EarsPhase::MeasureEarsAgain;
  const bool earsPass = ears_->enabled() && !throughputPass();
  uint32_t samples = measuresEars                          ? std::min(perPass, kEarsGuardSamples - earsTally_.samples)
                     : earsPass                            ? std::min(perPass, earsSamples)
                     : shadowRoulette && !ears_->enabled() ? std::min(perPass, s + 1)
                                                           : perPass;
  return std::min(samples, settings_.spp - s);
}

void PathRenderer::printProgress(uint32_t s, uint32_t firstSample, double elapsed, double secondsBefore,
                                 const RenderStats& stats) const {
  const double budget = settings_.timeBudget;
  double eta = budget > 0.0 ? std::max(0.0, budget - elapsed) : elapsed / (s - firstSample) * (settings_.spp - s);
  std::fprintf(stderr, "\rvkmc: %u/%u spp  %.2f Mrays/s  ETA %.1f s   ", s, settings_.spp,
               stats.rays() / std::max(secondsBefore + elapsed, 1e-9) * 1e-6, eta);
  std::fflush(stderr);
}

void PathRenderer::render(RenderState& state, const RenderControl& control) {
  const uint32_t pixels = settings_.width * settings_.height;
  RenderStats& stats = state.stats;
  const RenderStats before = stats;
  const double secondsBefore = stats.seconds;
  bool showProgress = settings_.progress && isatty(STDERR_FILENO);
  const bool shadowRoulette = settings_.estimator.shadowRrThreshold > 0.0f && ctx_.unifiedMemory();
  uint32_t inBatch = prepareFilm(state, shadowRoulette);
  auto start = Clock::now();
  passesStart_ = start;
  double lastProgress = 0.0, lastCheckpoint = 0.0;
  // Small images take several samples per pixel per pass, so that a pass fills the wavefront.
  const uint32_t maxPerPass = samplesPerPass();
  // A time budget (time_budget.h): the first pass takes one sample (a slow scene must not overrun by much), the
  // later ones are sized from the last pass's seconds a sample.
  uint32_t perPass = settings_.timeBudget > 0.0 ? 1u : maxPerPass;
  const double budget = settings_.timeBudget;
  double secondsPerSample = 0.0;  // the last pass's, per sample a pixel
  auto budgetSpent = [&] { return timeBudgetSpent(budget, since(start)); };
  const uint32_t firstSample = state.nextSample;
  // EARS and shadow-ray roulette learn between passes (the cache and image statistics; the pixel estimate), so
  // their passes start small and double: what they compare against is known early. Shadow roulette's pass from
  // sample s takes s + 1 samples (1, 2, 4, ...), a function of s alone, so a resumed render passes where the
  // uninterrupted one did; EARS's passes double from where its training passes left off.
  uint32_t earsSamples = 1;
  auto stopRequested = [&] { return control.stop && control.stop->load() != 0; };
  if (ears_->enabled() && state.nextSample < settings_.spp && !stopRequested())
    earsSamples = startEars(state, inBatch, start, secondsPerSample);
  for (uint32_t s = state.nextSample; s < settings_.spp;) {
    if (s > firstSample && budgetSpent()) break;
    // Sized here, after the last pass's fold, checkpoint and any measuring pass, by the time left now.
    if (secondsPerSample > 0.0) perPass = timeBudgetPassSamples(budget, since(start), secondsPerSample, maxPerPass);
    if (stopRequested()) {
      state.interrupted = true;
      state.stopSignal = control.stop->load();
      break;
    }
    if (ears_->enabled() && earsPhase_ == EarsPhase::MeasureThroughput) {
      // As large as throughput roulette's later passes, whose per-pass overhead (a pass's bounces, each a
      // dispatch and most nearly empty) it then shares as they will: on veach_mis a 4-sample pass took twice the
      // seconds a sample of a 28-sample one. Dropped, so it advances no sample.
      if (inBatch > 0) foldFilm(state.film), inBatch = 0;
      measureThroughputForGuard(state.film, s, maxPerPass, stats);
      continue;
    }
    const bool earsPass = ears_->enabled() && !throughputPass();
    const uint32_t samples = nextPassSamples(s, perPass, earsSamples, shadowRoulette);
    double passStart = since(start);
    const uint64_t raysBefore = stats.rays();
    renderSamples(s, samples, stats);
    if (ears_->enabled())
      afterEarsPass(state.film, double(stats.rays() - raysBefore) / (double(pixels) * samples), since(start) - passStart, samples,
                    s + samples);
    else if (shadowRoulette)
      refreshPixelEstimate(state.film);
    if (earsPass) earsSamples = std::min(2 * earsSamples, maxPerPass);
    s += samples;
    state.nextSample = s;
    inBatch += samples;
    if (budget > 0.0) secondsPerSample = std::max(since(start) - passStart, 1e-6) / samples;
    bool last = s == settings_.spp || budgetSpent();
    if (inBatch + maxPerPass > kSamplesPerBatch || last) foldFilm(state.film), inBatch = 0;
    double elapsed = since(start);
    if (control.checkpoint && control.checkpointEvery > 0.0 && elapsed - lastCheckpoint >= control.checkpointEvery && !last) {
      snapshot(state, inBatch, secondsBefore + elapsed, before);
      control.checkpoint(state);
      lastCheckpoint = since(start);
    }
    if (showProgress && (elapsed - lastProgress > 0.25 || last))
      lastProgress = elapsed, printProgress(s, firstSample, elapsed, secondsBefore, stats);
  }
  if (showProgress) std::fprintf(stderr, "\n");
  if (ears_->enabled())
    earsGuard_.learningCostSeconds = earsLearningCostSeconds(earsGuard_.decidedAtSeconds, earsGuard_.fromSample - firstSample,
                                                             since(start), state.nextSample - earsGuard_.fromSample);
  snapshot(state, inBatch, secondsBefore + since(start), before);
}

}  // namespace vkmc
