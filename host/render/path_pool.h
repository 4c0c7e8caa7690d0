// How many paths one pass of a render holds, within the device's limits: camera paths per pass, path slots for
// them and their split children, shadow-ray slots. Refuses settings the device cannot hold, with one line.
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>

#include "render/render_settings.h"

namespace vkmc {

struct PathPoolSize {
  uint32_t cameraPaths = 0;  // per pass
  uint32_t slots = 0;        // camera paths and room for split children (pathPoolFactor)
  uint64_t shadowSlots = 0;  // shadow rays one bounce may queue (0 without a shadow stage)
  uint64_t extraShadowSlots = 0;  // of them, those past light_samples per path slot (EARS's split light samples)
};

// Throws Error when the workgroup size or the image's film does not fit the device.
void checkDeviceLimits(const RenderSettings& settings, const VkPhysicalDeviceLimits& limits);
PathPoolSize sizePathPool(const RenderSettings& settings, const VkPhysicalDeviceLimits& limits, bool hasShadowStage);

}  // namespace vkmc
