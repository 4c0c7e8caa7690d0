// How many paths one pass of a render holds, within the device's limits: camera paths per pass, path slots for
// them and their split children, shadow-ray slots. Refuses settings the device cannot hold, with one line.
#pragma once
#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <string>

#include "render/render_settings.h"

namespace vkmc {

// What --workgroup and --wavefront accept. Below 32 invocations the indirect dispatch of a full path pool (~1.7M
// paths) would pass 65535 workgroups.
constexpr std::array<uint32_t, 4> kWorkgroupSizes = {32, 64, 128, 256};
constexpr uint32_t kMinWavefrontPaths = 1024, kMaxWavefrontPaths = 1u << 24;
std::string workgroupSizesText();  // "32, 64, 128 or 256"
std::string wavefrontRangeText();  // "1024 to 16777216"

struct PathPoolSize {
  uint32_t cameraPaths = 0;       // per pass
  uint32_t slots = 0;             // camera paths and room for split children (pathPoolFactor)
  uint64_t shadowSlots = 0;       // shadow rays one bounce may queue (0 without a shadow stage)
  uint64_t extraShadowSlots = 0;  // of them, those past light_samples per path slot (EARS's split light samples)
};

// Throws Error when the workgroup size or the image's film does not fit the device.
void checkDeviceLimits(const RenderSettings& settings, const VkPhysicalDeviceLimits& limits);
PathPoolSize sizePathPool(const RenderSettings& settings, const VkPhysicalDeviceLimits& limits, bool hasShadowStage);

}  // namespace vkmc
