// What vkmc's kernels need of a Vulkan device, checked once when the device is opened so that a device lacking
// one stops with a line naming it (not a driver error at the first pipeline): subgroup operations, the storage
// texel buffer formats, the texture pages' image formats, 64-bit integers, workgroup size, push constants and descriptors per
// stage.
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

namespace vkmc::vk {

struct DeviceCapabilities {
  VkShaderStageFlags subgroupStages = 0;
  uint32_t subgroupSize = 0;
  VkSubgroupFeatureFlags subgroupOperations = 0;
  std::vector<std::pair<VkFormat, VkFormatFeatureFlags>> texelFormats;  // each format the kernels read, its buffer features
  uint32_t maxWorkgroupSizeX = 0, maxWorkgroupInvocations = 0;
  uint32_t maxPushConstantsSize = 0;
  uint32_t maxStorageBuffersPerStage = 0, maxStorageImagesPerStage = 0;  // texel buffers count as storage images
  uint32_t maxSampledImagesPerStage = 0, maxSamplersPerStage = 0;
  VkFormatFeatureFlags unormImageFeatures = 0, srgbImageFeatures = 0;  // optimal tiling, R8G8B8A8 UNORM / SRGB
  bool shaderInt64 = false;  // the kernels store 16-byte words as two 64-bit halves (common.glsl wordPairs)
};

// The formats of the scene's storage texel buffers (gpu_scene.cpp's qualifiers: rgba32f, rgba32ui, r32ui).
std::vector<VkFormat> requiredTexelFormats();

// Everything the device lacks, one phrase each ("subgroup arithmetic in compute shaders", ...); empty when it
// has all.
std::vector<std::string> missingRequirements(const DeviceCapabilities& caps);

// The device's capabilities as missingRequirements reads them.
DeviceCapabilities queryCapabilities(VkPhysicalDevice device);

}  // namespace vkmc::vk
