// What vkmc chooses for a device when the user does not: the integrator, the workgroup size, the wavefront's
// paths in flight per pass and whether every stage is timed. One rule per row; docs/journal/performance.md has what measured each
// ("Chosen per device").
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>

#include "render/render_settings.h"

namespace vkmc {

struct DeviceTuning {
  Integrator integrator = Integrator::Wavefront;  // for estimators that do not split paths (those need the pool)
  uint32_t workgroupSize = 64;
  uint32_t wavefrontPaths = 1u << 18;
  bool stageTimes = true;  // a timestamp pair around every dispatch (RenderSettings::stageTimes)
};

// type: the device's VkPhysicalDeviceType; subgroupSize: its subgroup width (16 on lavapipe where vkmc chooses it,
// vk/lavapipe_environment.h; 8 with AVX2; 32 on NVIDIA, 32 or 64 on AMD).
DeviceTuning deviceTuning(VkPhysicalDeviceType type, uint32_t subgroupSize);

}  // namespace vkmc
