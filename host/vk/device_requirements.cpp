// Device requirements of the kernels.
#include "vk/device_requirements.h"

#include "../shaders/shared/layout.h"
#include "../shaders/shared/texture_layout.h"

namespace vkmc::vk {

std::vector<VkFormat> requiredTexelFormats() {
  return {VK_FORMAT_R32G32B32A32_SFLOAT, VK_FORMAT_R32G32B32A32_UINT, VK_FORMAT_R32_UINT};
}

std::vector<std::string> missingRequirements(const DeviceCapabilities& caps) {
  std::vector<std::string> missing;
  // The walk's step counters (SPEC_WALK_STATS), EARS's histogram and the queue appends use subgroup arithmetic,
  // elect and broadcast; every kernel includes common.glsl, so the SPIR-V of all of them declares the capabilities.
  const VkSubgroupFeatureFlags ops =
      VK_SUBGROUP_FEATURE_BASIC_BIT | VK_SUBGROUP_FEATURE_ARITHMETIC_BIT | VK_SUBGROUP_FEATURE_BALLOT_BIT;
  if (!(caps.subgroupStages & VK_SHADER_STAGE_COMPUTE_BIT) || (caps.subgroupOperations & ops) != ops)
    missing.push_back("subgroup basic, arithmetic and ballot operations in compute shaders");
  // The rare counters' and EARS histogram's flush (common.glsl flushRareCounts) gives each of its lanes one counter.
  if (caps.subgroupSize < gpu::kRareCounters)
    missing.push_back("subgroups of at least " + std::to_string(gpu::kRareCounters) + " invocations");
  for (const auto& [format, features] : caps.texelFormats)
    if (!(features & VK_FORMAT_FEATURE_STORAGE_TEXEL_BUFFER_BIT))
      missing.push_back("storage texel buffers of format " + std::to_string(int(format)));
  if (caps.maxWorkgroupSizeX < gpu::kWorkgroupSize || caps.maxWorkgroupInvocations < gpu::kWorkgroupSize)
    missing.push_back("workgroups of " + std::to_string(gpu::kWorkgroupSize) + " invocations");
  if (caps.maxPushConstantsSize < sizeof(gpu::PushConstants))
    missing.push_back(std::to_string(sizeof(gpu::PushConstants)) + " bytes of push constants");
  uint32_t texel = 0;
  for (uint32_t b : gpu::kTexelBindings) texel += b < BINDING_COUNT ? 1u : 0u;
  if (caps.maxStorageImagesPerStage < texel) missing.push_back(std::to_string(texel) + " storage texel buffers per shader stage");
  if (caps.maxStorageBuffersPerStage < BINDING_COUNT - texel - 1)
    missing.push_back(std::to_string(BINDING_COUNT - texel - 1) + " storage buffers per shader stage");
  if (caps.maxSampledImagesPerStage < gpu::kTexturePageViews || caps.maxSamplersPerStage < gpu::kTexturePageViews)
    missing.push_back(std::to_string(gpu::kTexturePageViews) + " sampled images and samplers per shader stage");
  const VkFormatFeatureFlags sampled = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  if ((caps.unormImageFeatures & (sampled | VK_FORMAT_FEATURE_TRANSFER_DST_BIT)) !=
          (sampled | VK_FORMAT_FEATURE_TRANSFER_DST_BIT) ||
      (caps.srgbImageFeatures & sampled) != sampled)
    missing.push_back("linearly filtered R8G8B8A8 UNORM and SRGB sampled images");
  if (!caps.shaderInt64) missing.push_back("64-bit integers in shaders (shaderInt64)");
  return missing;
}

DeviceCapabilities queryCapabilities(VkPhysicalDevice device) {
  VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
  VkPhysicalDeviceProperties2 p2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &subgroup};
  vkGetPhysicalDeviceProperties2(device, &p2);
  const VkPhysicalDeviceLimits& l = p2.properties.limits;
  DeviceCapabilities caps;
  caps.subgroupStages = subgroup.supportedStages;
  caps.subgroupSize = subgroup.subgroupSize;
  caps.subgroupOperations = subgroup.supportedOperations;
  for (VkFormat f : requiredTexelFormats()) {
    VkFormatProperties fp;
    vkGetPhysicalDeviceFormatProperties(device, f, &fp);
    caps.texelFormats.emplace_back(f, fp.bufferFeatures);
  }
  caps.maxWorkgroupSizeX = l.maxComputeWorkGroupSize[0];
  caps.maxWorkgroupInvocations = l.maxComputeWorkGroupInvocations;
  caps.maxPushConstantsSize = l.maxPushConstantsSize;
  caps.maxStorageBuffersPerStage = l.maxPerStageDescriptorStorageBuffers;
  caps.maxStorageImagesPerStage = l.maxPerStageDescriptorStorageImages;
  caps.maxSampledImagesPerStage = l.maxPerStageDescriptorSampledImages;
  caps.maxSamplersPerStage = l.maxPerStageDescriptorSamplers;
  VkFormatProperties fp;
  vkGetPhysicalDeviceFormatProperties(device, VK_FORMAT_R8G8B8A8_UNORM, &fp);
  caps.unormImageFeatures = fp.optimalTilingFeatures;
  vkGetPhysicalDeviceFormatProperties(device, VK_FORMAT_R8G8B8A8_SRGB, &fp);
  caps.srgbImageFeatures = fp.optimalTilingFeatures;
  VkPhysicalDeviceFeatures features;
  vkGetPhysicalDeviceFeatures(device, &features);
  caps.shaderInt64 = features.shaderInt64 == VK_TRUE;
  return caps;
}

}  // namespace vkmc::vk
