// The per-device defaults (render/device_tuning.h): each device type gets its row, and every choice is one the
// renderer accepts.
#include <gtest/gtest.h>

#include "render/device_tuning.h"

using namespace vkmc;

TEST(DeviceTuning, LavapipeKeepsTheMeasuredWavefrontDefaults) {
  DeviceTuning t = deviceTuning(VK_PHYSICAL_DEVICE_TYPE_CPU, 8);
  EXPECT_EQ(t.integrator, Integrator::Wavefront);
  EXPECT_EQ(t.workgroupSize, 64u);
  EXPECT_EQ(t.wavefrontPaths, 1u << 18);
  EXPECT_FALSE(t.stageTimes) << "a timestamp costs lavapipe about a small dispatch";
}

TEST(DeviceTuning, ADiscreteGpuRunsTheMegakernelWithMorePathsInFlight) {
  DeviceTuning t = deviceTuning(VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, 32);
  EXPECT_EQ(t.integrator, Integrator::Megakernel);
  EXPECT_EQ(t.workgroupSize, 64u);
  EXPECT_EQ(t.wavefrontPaths, 1u << 20);
  EXPECT_EQ(deviceTuning(VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU, 32).integrator, Integrator::Wavefront);
  EXPECT_TRUE(t.stageTimes);
  EXPECT_TRUE(deviceTuning(VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU, 32).stageTimes);
}

TEST(DeviceTuning, EveryChoiceIsAWorkgroupSizeTheRendererAcceptsAndHoldsASubgroup) {
  for (VkPhysicalDeviceType type : {VK_PHYSICAL_DEVICE_TYPE_CPU, VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU,
                                    VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_PHYSICAL_DEVICE_TYPE_OTHER})
    for (uint32_t subgroup : {1u, 4u, 8u, 16u, 32u, 64u, 128u}) {
      DeviceTuning t = deviceTuning(type, subgroup);
      EXPECT_TRUE(t.workgroupSize == 64 || t.workgroupSize == 128 || t.workgroupSize == 256) << t.workgroupSize;
      EXPECT_EQ(t.workgroupSize % subgroup, 0u) << "subgroup " << subgroup;
      EXPECT_GE(t.wavefrontPaths, 1024u);
      EXPECT_LE(t.wavefrontPaths, 1u << 24);
    }
}
