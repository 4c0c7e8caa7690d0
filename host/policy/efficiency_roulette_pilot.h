// The pilot of efficiency-optimized roulette (host/estimators/efficiency_roulette.h): a short render without
// roulette or splitting that records per-path, per-depth statistics, and the per-depth scales chosen from them.
#pragma once
#include <cstdint>
#include <vector>

#include "estimators/efficiency_roulette.h"
#include "render/gpu_scene.h"
#include "render/render_settings.h"
#include "vk/context.h"

namespace vkmc {

struct RoulettePilot {
  RouletteTable table;
  double seconds = 0.0;          // the pilot's render time: part of the estimator's cost
  double pipelineSeconds = 0.0;  // its kernels' set-up
};

// settings: the render the scales are for (its estimator's rr_depth and depth cap, its image and camera). pixels:
// the image's pixels the pilot renders (all where empty); --estimator auto learns on a subset sized to its share.
RoulettePilot runRoulettePilot(vk::Context& ctx, const GpuScene& scene, const RenderSettings& settings,
                               const std::vector<uint32_t>& pixels = {});

}  // namespace vkmc
