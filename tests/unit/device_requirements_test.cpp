// The device checks (host/vk/device_requirements.h): a device with everything passes, each shortfall is named,
// and the texel formats checked are the ones the scene buffers use.
#include <gtest/gtest.h>

#include <algorithm>

#include "../shaders/shared/layout.h"
#include "render/gpu_scene.h"
#include "vk/device_requirements.h"

using namespace vkmc;

namespace {
vk::DeviceCapabilities capable() {
  vk::DeviceCapabilities c;
  c.subgroupStages = VK_SHADER_STAGE_COMPUTE_BIT;
  c.subgroupSize = 32;
  c.subgroupOperations = VK_SUBGROUP_FEATURE_BASIC_BIT | VK_SUBGROUP_FEATURE_ARITHMETIC_BIT | VK_SUBGROUP_FEATURE_BALLOT_BIT;
  for (VkFormat f : vk::requiredTexelFormats()) c.texelFormats.emplace_back(f, VK_FORMAT_FEATURE_STORAGE_TEXEL_BUFFER_BIT);
  c.maxWorkgroupSizeX = c.maxWorkgroupInvocations = 1024;
  c.maxPushConstantsSize = 128;
  c.maxStorageBuffersPerStage = c.maxStorageImagesPerStage = 64;
  c.maxSampledImagesPerStage = c.maxSamplersPerStage = 16;
  c.unormImageFeatures = c.srgbImageFeatures = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
                                               VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT |
                                               VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
  c.shaderInt64 = true;
  return c;
}

bool names(const std::vector<std::string>& missing, const std::string& what) {
  return missing.size() == 1 && missing[0].find(what) != std::string::npos;
}
}  // namespace

TEST(DeviceRequirements, ACapableDeviceLacksNothing) { EXPECT_TRUE(vk::missingRequirements(capable()).empty()); }

TEST(DeviceRequirements, EachShortfallIsNamed) {
  vk::DeviceCapabilities c = capable();
  c.subgroupOperations = VK_SUBGROUP_FEATURE_BASIC_BIT | VK_SUBGROUP_FEATURE_ARITHMETIC_BIT;
  EXPECT_TRUE(names(vk::missingRequirements(c), "subgroup basic, arithmetic and ballot"));
  c = capable();
  c.subgroupStages = VK_SHADER_STAGE_FRAGMENT_BIT;
  EXPECT_TRUE(names(vk::missingRequirements(c), "in compute shaders"));
  c = capable();
  c.subgroupSize = 2;
  EXPECT_TRUE(names(vk::missingRequirements(c), "subgroups of at least 4 invocations"));
  c = capable();
  c.texelFormats[1].second = 0;
  EXPECT_TRUE(
      names(vk::missingRequirements(c), "storage texel buffers of format " + std::to_string(int(c.texelFormats[1].first))));
  c = capable();
  c.maxWorkgroupInvocations = 32;
  EXPECT_TRUE(names(vk::missingRequirements(c), "workgroups of 64"));
  c = capable();
  c.maxPushConstantsSize = 16;
  EXPECT_TRUE(names(vk::missingRequirements(c), "bytes of push constants"));
  c = capable();
  c.maxStorageImagesPerStage = 1;
  EXPECT_TRUE(names(vk::missingRequirements(c), "storage texel buffers per shader stage"));
  c = capable();
  c.maxStorageBuffersPerStage = 1;
  EXPECT_TRUE(names(vk::missingRequirements(c), "storage buffers per shader stage"));
  c = capable();
  c.maxSampledImagesPerStage = 1;
  EXPECT_TRUE(names(vk::missingRequirements(c), "sampled images and samplers per shader stage"));
  c = capable();
  c.srgbImageFeatures = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
  EXPECT_TRUE(names(vk::missingRequirements(c), "R8G8B8A8 UNORM and SRGB sampled images"));
  c = capable();
  c.shaderInt64 = false;
  EXPECT_TRUE(names(vk::missingRequirements(c), "shaderInt64"));
}

TEST(DeviceRequirements, TheCheckedFormatsAreTheSceneBuffersFormats) {
  std::vector<VkFormat> checked = vk::requiredTexelFormats();
  for (uint32_t b : gpu::kTexelBindings)
    EXPECT_NE(std::find(checked.begin(), checked.end(), sceneTexelFormat(b)), checked.end()) << "binding " << b;
}

// llvmpipe keys compiled kernels on whether a texel buffer's texel count is a power of two; the warm-up compiles
// for counts that are not, so the render's buffers must not be one either (render/gpu_scene.h notPowerOfTwoBytes).
TEST(DeviceRequirements, TexelBufferSizesAreNeverAPowerOfTwo) {
  EXPECT_EQ(notPowerOfTwoBytes(0), 48u);  // 16 and 32 are powers of two
  EXPECT_EQ(notPowerOfTwoBytes(16), 48u);
  EXPECT_EQ(notPowerOfTwoBytes(48), 48u);  // not one: unchanged
  EXPECT_EQ(notPowerOfTwoBytes(512), 528u);
  EXPECT_EQ(notPowerOfTwoBytes(256 * 256 * 16), 256u * 256u * 16u + 16u);
  for (size_t size = 16; size <= (size_t(1) << 24); size += 16 * ((size >> 6) + 1)) {
    const size_t bytes = notPowerOfTwoBytes(size);
    EXPECT_NE(bytes & (bytes - 1), 0u) << size;
    EXPECT_GE(bytes, size);
    EXPECT_LE(bytes, size + 32) << "at most two texels of padding";
    EXPECT_EQ(bytes % 16, 0u) << "whole 16-byte texels";
  }
  // Never past the device's texel limit: at exactly the limit (a power of two) the size stays as it is.
  EXPECT_EQ(notPowerOfTwoBytes(65536 * 16, 65536 * 16), 65536u * 16u);
  EXPECT_EQ(notPowerOfTwoBytes(65536 * 16, 65536 * 16 + 16), 65536u * 16u + 16u);
}
