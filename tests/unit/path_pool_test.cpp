// Path-pool sizing (render/path_pool.h): the pool stays within every buffer limit the device reports.
#include <gtest/gtest.h>

#include <string>

#include "../shaders/shared/layout.h"
#include "error.h"
#include "render/path_pool.h"

using namespace vkmc;

namespace {
VkPhysicalDeviceLimits roomyLimits() {
  VkPhysicalDeviceLimits limits{};
  limits.maxStorageBufferRange = 0xffffffffu;
  limits.maxTexelBufferElements = 1u << 27;
  return limits;
}
RenderSettings settingsFor(uint32_t wavefront, uint32_t lightSamples) {
  RenderSettings s;
  s.width = 4096;
  s.height = 4096;
  s.spp = 64;
  s.maxPathsPerPass = wavefront;
  s.estimator.lightSamples = lightSamples;
  return s;
}
}  // namespace

TEST(PathPool, PathStatesAndShadowRaysFitTheTexelViewsTheKernelsReadThemThrough) {
  VkPhysicalDeviceLimits limits = roomyLimits();
  limits.maxTexelBufferElements = 1u << 20;  // less than a 2^24-path wavefront's 5 texels a path
  for (uint32_t lightSamples : {1u, 4u}) {
    PathPoolSize size = sizePathPool(settingsFor(1u << 24, lightSamples), limits, true);
    EXPECT_LE(uint64_t(size.slots) * gpu::kPathTexels, limits.maxTexelBufferElements);
    EXPECT_LE(size.shadowSlots * gpu::kShadowRayTexels, limits.maxTexelBufferElements);
    EXPECT_GT(size.cameraPaths, 0u);
  }
}

TEST(PathPool, TheWavefrontIsTheBoundWhereTheDeviceHasRoom) {
  PathPoolSize size = sizePathPool(settingsFor(1u << 18, 1), roomyLimits(), true);
  EXPECT_EQ(size.cameraPaths, 1u << 18);
  EXPECT_EQ(size.shadowSlots, uint64_t(size.slots));
}

TEST(PathPool, AnImageWithMorePixelsThanTexelsIsRefusedWithOneLine) {
  VkPhysicalDeviceLimits limits = roomyLimits();
  limits.maxComputeWorkGroupSize[0] = limits.maxComputeWorkGroupInvocations = 1024;
  RenderSettings s = settingsFor(1u << 18, 1);
  s.workgroupSize = 64;
  EXPECT_NO_THROW(checkDeviceLimits(s, limits));
  limits.maxTexelBufferElements = 4096u * 4096u - 1u;  // the pixel estimates are one texel a pixel
  try {
    checkDeviceLimits(s, limits);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("pixel estimates need one texel a pixel"), std::string::npos) << e.what();
  }
}
