// The kernels one render dispatches: chosen for its integrator and estimator, built with its specialization
// constants, and warmed up once on empty queues so that the driver's first-dispatch compile is not timed as
// rendering (llvmpipe compiles at first dispatch; a helper thread takes part of them, BackgroundWarmUp). Where a
// pre-specialized variant of a kernel's SPIR-V matches the render's constants it is used (render/kernel_variants.h).
#pragma once
#include <memory>

#include "bvh/bvh.h"
#include "render/render_settings.h"
#include "vk/kernel.h"

namespace vkmc {

struct RenderKernels {
  std::unique_ptr<vk::Kernel> camera, prepareBounce, intersect, intersectDeep, shade, prepareShadow, shadow, shadowDeep,
      accumulate, megakernel;
  // EARS: the copy stage after shade, and the training after each pass's training wavefront (kernels/ears_*.comp,
  // prepare_copies.comp).
  std::unique_ptr<vk::Kernel> prepareCopies, earsCopies, earsGather, earsTrain, earsFold;
  // EARS: shade and the copy stage once more without the training code (SPEC_EARS_TRAINS 0), for a pass's
  // samples after its training ones (common.glsl earsTrains).
  std::unique_ptr<vk::Kernel> shadeLean, earsCopiesLean;
  // EARS's guard (ears_guard.h): shade and the shadow stage with throughput roulette, for the comparison pass and
  // a fallback (EARS's own shadow stage adds with float atomics and carries its training code: 14% slower).
  std::unique_ptr<vk::Kernel> shadeThroughput, shadowThroughput, shadowDeepThroughput;

  // The kernels of a bounce's shading and shadow stages: those that train EARS's cache, or (where built) those
  // that do not, or (throughput, where built) those of EARS's guard. earsCopies is null unless the rr is ears (and
  // for the guard's kernels); shadow and shadowDeep unless there is a shadow stage; shadowDeep (and intersectDeep)
  // also where no walk can outgrow the register stack (SceneFeatures::deepWalks).
  struct BounceKernels {
    vk::Kernel *shade, *earsCopies, *shadow, *shadowDeep;
  };
  BounceKernels bounceKernels(bool earsTrains, bool throughput = false) const;
};

// The kernels a render dispatches, with the specialization constants each is built with.
KernelPlan planKernels(const RenderSettings& settings);

// What a render's pipelines are specialized for: the scene's features and whether its BVH needs the deep walk
// passes (walksCanOutgrowRegisterStack), or every feature (specialize false: general pipelines, for comparison).
SceneFeatures pipelineFeatures(const SceneFeatures& scene, const BvhStats& bvh, bool specialize);

// Builds and warms up the planned kernels on `layout` (whose buffers must be bound, the control block zeroed).
// pathSlots is the pool size the warm-up's push constants announce.
RenderKernels buildRenderKernels(vk::Context& ctx, vk::KernelLayout& layout, const RenderSettings& settings, bool hasShadowStage,
                                 uint32_t pathSlots);

}  // namespace vkmc
