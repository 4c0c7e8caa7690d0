// Kernel planning, building and warm-up for one render.
#include "render/render_kernels.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "../shaders/shared/layout.h"
#include "error.h"
#include "render/background_warm_up.h"
#include "render/kernel_variants.h"
#include "spirv/accumulate_spv.h"
#include "spirv/camera_rays_spv.h"
#include "spirv/ears_copies_spv.h"
#include "spirv/ears_fold_spv.h"
#include "spirv/ears_gather_spv.h"
#include "spirv/ears_train_spv.h"
#include "spirv/intersect_deep_spv.h"
#include "spirv/intersect_spv.h"
#include "spirv/megakernel_spv.h"
#include "spirv/prepare_bounce_spv.h"
#include "spirv/prepare_copies_spv.h"
#include "spirv/prepare_shadow_spv.h"
#include "spirv/shade_atomic_spv.h"
#include "spirv/shade_spv.h"
#include "spirv/shadow_atomic_deep_spv.h"
#include "spirv/shadow_atomic_spv.h"
#include "spirv/shadow_deep_spv.h"
#include "spirv/shadow_spv.h"

namespace vkmc {

namespace {
// A kernel's SPIR-V and its name in the build (shaders/CMakeLists.txt), which names its pre-specialized variants.
struct NamedSpirv {
  const char* build;
  std::span<const uint32_t> words;
};
#define VKMC_SPIRV(kernel) \
  NamedSpirv { #kernel, kSpirv_##kernel }

uint32_t log2Ceil(uint64_t v) {
  uint32_t k = 0;
  while ((uint64_t(1) << k) < v) ++k;
  return k;
}

// ZSobol's Morton index: the pixel's bits (both axes) and then the point's, within one 32-bit word.
constexpr uint32_t kZSobolIndexBits = 32;
uint32_t zsobolPixelBits(uint32_t width, uint32_t height) { return 2 * log2Ceil(std::max(width, height)); }
}  // namespace

ZSobolLayout zsobolLayout(const RenderSettings& s) {
  ZSobolLayout z;
  const uint64_t replicates = s.estimator.replicates;
  z.log2Spp = log2Ceil((uint64_t(s.spp) + replicates - 1) / replicates);
  const uint32_t pixelBits = zsobolPixelBits(s.width, s.height);
  z.digits = pixelBits / 2 + (z.log2Spp + 1) / 2;
  if (s.estimator.sampler == Sampler::ZSobol && pixelBits + z.log2Spp > kZSobolIndexBits)
    throw Error("--sampler zsobol: " + std::to_string(s.width) + "x" + std::to_string(s.height) + " at " + std::to_string(s.spp) +
                " spp needs a Morton index of " + std::to_string(pixelBits + z.log2Spp) +
                " bits, more than 32: use --sampler sobol, fewer samples or a smaller image");
  return z;
}

uint32_t zsobolMaxSpp(uint32_t width, uint32_t height, uint32_t replicates) {
  const uint32_t pixelBits = zsobolPixelBits(width, height);
  if (pixelBits > kZSobolIndexBits) return 0;
  return uint32_t(std::min<uint64_t>(uint64_t(replicates) << (kZSobolIndexBits - pixelBits), uint64_t(1) << 24));
}

SceneFeatures pipelineFeatures(const SceneFeatures& scene, const BvhStats& bvh, bool specialize) {
  if (!specialize) return allFeatures(scene);
  SceneFeatures f = scene;
  f.deepWalks = walksCanOutgrowRegisterStack(bvh);
  f.registerStackEntries = registerStackEntries(bvh);
  return f;
}

namespace {
// The kernel that shades: the megakernel, or the wavefront's shade stage (with float atomics where paths split).
NamedSpirv shadingSpirv(const RenderSettings& s) {
  if (s.integrator == Integrator::Megakernel) return VKMC_SPIRV(megakernel);
  return s.estimator.splitsPaths() ? VKMC_SPIRV(shade_atomic) : VKMC_SPIRV(shade);
}
}  // namespace

KernelPlan planKernels(const RenderSettings& s) {
  KernelPlan plan;
  const EstimatorConfig& est = s.estimator;
  bool shadows = s.features.lights() && est.nee;
  if (s.integrator == Integrator::Megakernel) {
    plan.kernels = {"megakernel", "accumulate"};
  } else {
    plan.kernels = {"camera_rays", "prepare_bounce", "intersect", est.splitsPaths() ? "shade (float atomics)" : "shade"};
  }
  if (shadows && s.integrator == Integrator::Wavefront) {
    plan.kernels.push_back("prepare_shadow");
    plan.kernels.push_back(est.needsFloatAtomics() ? "shadow (float atomics)" : "shadow");
  }
  if (s.integrator == Integrator::Wavefront) plan.kernels.push_back("accumulate");
  if (est.rr == RouletteMode::Ears) {
    for (const char* k : {"prepare_copies", "ears_copies", "ears_gather", "ears_train", "ears_fold"}) plan.kernels.push_back(k);
    plan.kernels.push_back("shade and ears_copies again without training code (a pass's later samples)");
    if (est.earsMayFallBack()) plan.kernels.push_back("shade with throughput roulette (ears_fallback's comparison pass)");
    if (est.earsMayFallBack() && shadows) plan.kernels.push_back("shadow with throughput roulette (the same)");
  }
  plan.specs = {{SPEC_WORKGROUP_SIZE, s.workgroupSize},
                {SPEC_HAS_LIGHTS, s.features.lights() ? 1u : 0u},
                {SPEC_HAS_PUNCTUAL, s.features.punctualLights > 0 ? 1u : 0u},
                {SPEC_HAS_ENVIRONMENT, s.features.environment ? 1u : 0u},
                {SPEC_HAS_GLOSSY, s.features.glossy ? 1u : 0u},
                {SPEC_HAS_TEXTURES, s.features.textures ? 1u : 0u},
                {SPEC_HAS_NORMAL_MAPS, s.features.normalMaps ? 1u : 0u},
                {SPEC_HAS_ALPHA, s.features.alpha ? 1u : 0u},
                {SPEC_CULLS_BACK_FACES, s.features.singleSided ? 1u : 0u},
                {SPEC_HAS_TRANSMISSION, s.features.transmission ? 1u : 0u},
                {SPEC_HAS_CLEARCOAT, s.features.clearcoat ? 1u : 0u},
                {SPEC_HAS_SHEEN, s.features.sheen ? 1u : 0u},
                {SPEC_HAS_IRIDESCENCE, s.features.iridescence ? 1u : 0u},
                {SPEC_HAS_ANISOTROPY, s.features.anisotropy ? 1u : 0u},
                {SPEC_HAS_DISPERSION, s.features.dispersion ? 1u : 0u},
                {SPEC_HAS_DELTA, s.features.delta ? 1u : 0u},
                {SPEC_RECORD_DEPTH_STATS, s.recordDepthStats ? 1u : 0u},
                {SPEC_PIXEL_FILTER, s.filter.specSampling()},
                {SPEC_DEEP_WALKS, s.features.deepWalks ? 1u : 0u},
                {SPEC_REGISTER_STACK, s.features.registerStackEntries}};
  for (const vk::SpecConstant& c : est.specConstants()) plan.specs.push_back(c);
  const ZSobolLayout z = zsobolLayout(s);
  plan.specs.push_back({SPEC_SAMPLER_LOG2_SPP, z.log2Spp});
  plan.specs.push_back({SPEC_SAMPLER_DIGITS, z.digits});
  if (s.prespecializedSpirv) {
    const NamedSpirv shading = shadingSpirv(s);
    plan.spirvVariant = chooseSpirv(shading.build, shading.words, plan.specs).variant;
  }
  return plan;
}

namespace {

// A kernel this render dispatches, and whether a helper thread compiles it (see BackgroundWarmUp).
struct PlannedKernel {
  std::unique_ptr<vk::Kernel>* slot;
  const char* name;
  NamedSpirv source;
  bool lean = false;                     // built with SPEC_EARS_TRAINS 0
  bool throughput = false;               // built with throughput roulette (EARS's guard)
  std::span<const uint32_t> spirv = {};  // what the pipeline is created from: the source or a variant of it
  bool helper = false;
};

// EARS's kernels: its training stages, the lean ones of a pass's later samples, and the guard's throughput ones.
void planEarsKernels(const RenderSettings& settings, bool hasShadowStage, RenderKernels& k, std::vector<PlannedKernel>& planned) {
  const EstimatorConfig& est = settings.estimator;
  planned.push_back({&k.prepareCopies, "prepare_copies", VKMC_SPIRV(prepare_copies)});
  planned.push_back({&k.earsCopies, "ears_copies", VKMC_SPIRV(ears_copies)});
  planned.push_back({&k.earsGather, "ears_gather", VKMC_SPIRV(ears_gather)});
  planned.push_back({&k.earsTrain, "ears_train", VKMC_SPIRV(ears_train)});
  planned.push_back({&k.earsFold, "ears_fold", VKMC_SPIRV(ears_fold)});
  // The same names as the training kernels: the report's stage times add both.
  planned.push_back({&k.shadeLean, "shade", VKMC_SPIRV(shade_atomic), true});
  planned.push_back({&k.earsCopiesLean, "ears_copies", VKMC_SPIRV(ears_copies), true});
  if (est.earsMayFallBack()) planned.push_back({&k.shadeThroughput, "shade", VKMC_SPIRV(shade), false, true});
  if (est.earsMayFallBack() && hasShadowStage) {  // float atomics only where a path has several light samples
    const bool atomics = est.lightSamples > 1;
    planned.push_back({&k.shadowThroughput, "shadow", atomics ? VKMC_SPIRV(shadow_atomic) : VKMC_SPIRV(shadow), false, true});
    if (settings.features.deepWalks)
      planned.push_back({&k.shadowDeepThroughput, "shadow_deep",
                         atomics ? VKMC_SPIRV(shadow_atomic_deep) : VKMC_SPIRV(shadow_deep), false, true});
  }
}

// Every kernel the render dispatches, in dispatch order, each with the slot of RenderKernels it fills.
std::vector<PlannedKernel> planKernelList(const RenderSettings& settings, bool hasShadowStage, RenderKernels& k) {
  const EstimatorConfig& est = settings.estimator;
  std::vector<PlannedKernel> planned;
  if (settings.integrator == Integrator::Megakernel) {
    planned.push_back({&k.megakernel, "megakernel", shadingSpirv(settings)});
  } else {
    planned.push_back({&k.camera, "camera_rays", VKMC_SPIRV(camera_rays)});
    planned.push_back({&k.prepareBounce, "prepare_bounce", VKMC_SPIRV(prepare_bounce)});
    planned.push_back({&k.intersect, "intersect", VKMC_SPIRV(intersect)});
    if (settings.features.deepWalks) planned.push_back({&k.intersectDeep, "intersect_deep", VKMC_SPIRV(intersect_deep)});
    planned.push_back({&k.shade, "shade", shadingSpirv(settings)});
    if (hasShadowStage) {
      const bool atomics = est.needsFloatAtomics();
      planned.push_back({&k.prepareShadow, "prepare_shadow", VKMC_SPIRV(prepare_shadow)});
      planned.push_back({&k.shadow, "shadow", atomics ? VKMC_SPIRV(shadow_atomic) : VKMC_SPIRV(shadow)});
      if (settings.features.deepWalks)
        planned.push_back({&k.shadowDeep, "shadow_deep", atomics ? VKMC_SPIRV(shadow_atomic_deep) : VKMC_SPIRV(shadow_deep)});
    }
  }
  planned.push_back({&k.accumulate, "accumulate", VKMC_SPIRV(accumulate)});
  if (est.rr == RouletteMode::Ears) planEarsKernels(settings, hasShadowStage, k, planned);
  return planned;
}

// The first-dispatch compiles, shared by SPIR-V size: this thread takes the largest kernel, each next one goes to
// the lighter share. (Sizes stand in for compile times: the pre-specialized variants hold little dead code.) A
// kernel past kHelperMaxWords stays here: the helper would create its pipeline a second time, SPIR-V to NIR before
// the dead code goes, which costs about what its compile does, and all of it when the cache is warm.
void shareCompiles(const std::vector<PlannedKernel*>& bySize) {
  constexpr size_t kHelperMaxWords = 32768;
  size_t ownWords = 0, helperWords = 0;
  for (PlannedKernel* p : bySize) {
    p->helper = helperWords < ownWords && p->spirv.size() <= kHelperMaxWords;
    (p->helper ? helperWords : ownWords) += p->spirv.size();
  }
}

// Creating a pipeline is CPU work of its own on llvmpipe (SPIR-V to NIR, before specialization removes anything:
// 0.2 s for the general shade), so two threads create them, the largest first.
template <class SpecsOf>
void createPipelines(vk::Context& ctx, vk::KernelLayout& layout, const std::vector<PlannedKernel*>& bySize, SpecsOf&& specsOf) {
  std::atomic<size_t> next{0};
  auto createSome = [&] {
    for (size_t i = next++; i < bySize.size(); i = next++)
      *bySize[i]->slot = std::make_unique<vk::Kernel>(ctx, layout, bySize[i]->name, bySize[i]->spirv, specsOf(*bySize[i]));
  };
  std::exception_ptr workerError;
  std::thread worker([&] {
    try {
      createSome();
    } catch (...) {
      workerError = std::current_exception();
    }
  });
  try {
    createSome();
  } catch (...) {
    next = bySize.size();  // the worker stops after its current kernel
    worker.join();
    throw;
  }
  worker.join();
  if (workerError) std::rethrow_exception(workerError);
}

}  // namespace

RenderKernels buildRenderKernels(vk::Context& ctx, vk::KernelLayout& layout, const RenderSettings& settings, bool hasShadowStage,
                                 uint32_t pathSlots) {
  const KernelPlan plan = planKernels(settings);
  const std::vector<vk::SpecConstant>& specs = plan.specs;
  RenderKernels k;
  std::vector<PlannedKernel> planned = planKernelList(settings, hasShadowStage, k);
  std::vector<vk::SpecConstant> leanSpecs = specs;
  leanSpecs.push_back({SPEC_EARS_TRAINS, 0u});
  std::vector<vk::SpecConstant> throughputSpecs = specs;
  for (vk::SpecConstant& c : throughputSpecs)
    if (c.id == SPEC_RR_MODE) c.value = uint32_t(RouletteMode::Throughput);
  auto specsOf = [&](const PlannedKernel& p) -> const std::vector<vk::SpecConstant>& {
    return p.throughput ? throughputSpecs : p.lean ? leanSpecs : specs;
  };
  for (PlannedKernel& p : planned)
    p.spirv = settings.prespecializedSpirv ? chooseSpirv(p.source.build, p.source.words, specsOf(p)).spirv : p.source.words;
  std::vector<PlannedKernel*> bySize;
  for (PlannedKernel& p : planned) bySize.push_back(&p);
  std::stable_sort(bySize.begin(), bySize.end(),
                   [](const PlannedKernel* a, const PlannedKernel* b) { return a->spirv.size() > b->spirv.size(); });
  shareCompiles(bySize);
  std::vector<KernelSource> helperShare;
  if (compilesAtFirstDispatch(ctx))
    for (const PlannedKernel& p : planned)
      if (p.helper) helperShare.push_back({p.name, p.spirv, specsOf(p)});
  BackgroundWarmUp helper(std::move(helperShare));
  createPipelines(ctx, layout, bySize, specsOf);
  // Warm-up: every kernel once on empty queues; the helper's share last, once it has compiled them into the cache.
  gpu::PushConstants pc{};
  pc.width = settings.width;
  pc.height = settings.height;
  pc.queueCapacity = pathSlots;
  for (bool helperShare : {false, true}) {
    if (helperShare) helper.wait();
    ctx.runCommands([&](VkCommandBuffer cmd) {
      for (const PlannedKernel& p : planned)
        if (p.helper == helperShare) vk::dispatch(cmd, layout, **p.slot, &pc, sizeof(pc), 1);
    });
  }
  return k;
}

RenderKernels::BounceKernels RenderKernels::bounceKernels(bool earsTrains, bool throughput) const {
  if (throughput && shadeThroughput)
    return {shadeThroughput.get(), nullptr, shadowThroughput ? shadowThroughput.get() : shadow.get(),
            shadowThroughput ? shadowDeepThroughput.get() : shadowDeep.get()};
  if (!earsTrains && shadeLean) return {shadeLean.get(), earsCopiesLean.get(), shadow.get(), shadowDeep.get()};
  return {shade.get(), earsCopies.get(), shadow.get(), shadowDeep.get()};
}

}  // namespace vkmc
