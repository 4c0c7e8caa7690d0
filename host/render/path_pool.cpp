// Path-pool sizing: the wavefront's size bounded by every buffer's storage range and texel count.
#include "render/path_pool.h"

#include <algorithm>
#include <string>

#include "../shaders/shared/layout.h"
#include "error.h"

namespace vkmc {

std::string workgroupSizesText() {
  std::string text;
  for (size_t i = 0; i < kWorkgroupSizes.size(); ++i)
    text += (i == 0 ? "" : i + 1 == kWorkgroupSizes.size() ? " or " : ", ") + std::to_string(kWorkgroupSizes[i]);
  return text;
}

std::string wavefrontRangeText() { return std::to_string(kMinWavefrontPaths) + " to " + std::to_string(kMaxWavefrontPaths); }

void checkDeviceLimits(const RenderSettings& settings, const VkPhysicalDeviceLimits& limits) {
  const uint32_t ws = settings.workgroupSize;
  if (std::find(kWorkgroupSizes.begin(), kWorkgroupSizes.end(), ws) == kWorkgroupSizes.end())
    throw Error("--workgroup must be " + workgroupSizesText() + " (got " + std::to_string(ws) + ")");
  if (ws > limits.maxComputeWorkGroupSize[0] || ws > limits.maxComputeWorkGroupInvocations)
    throw Error("--workgroup " + std::to_string(ws) + " exceeds this device's limit of " +
                std::to_string(std::min(limits.maxComputeWorkGroupSize[0], limits.maxComputeWorkGroupInvocations)));
  if (settings.maxPathsPerPass < kMinWavefrontPaths || settings.maxPathsPerPass > kMaxWavefrontPaths)
    throw Error("--wavefront must be " + wavefrontRangeText() + " paths per pass (got " +
                std::to_string(settings.maxPathsPerPass) + ")");
  uint64_t filmBytes = uint64_t(settings.width) * settings.height * sizeof(gpu::FilmPixel);
  if (filmBytes > limits.maxStorageBufferRange)
    throw Error("image " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                " is too large: its film needs " + std::to_string(filmBytes >> 20) +
                " MiB, the device's storage-buffer limit is " + std::to_string(limits.maxStorageBufferRange >> 20) + " MiB");
  // The pixel estimates are read as texels, one a pixel (common.glsl loadPixelEstimate).
  if (uint64_t(settings.width) * settings.height > limits.maxTexelBufferElements)
    throw Error("image " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                " is too large: its pixel estimates need one texel a pixel, the device allows " +
                std::to_string(limits.maxTexelBufferElements) + " texels");
}

PathPoolSize sizePathPool(const RenderSettings& settings, const VkPhysicalDeviceLimits& limits, bool hasShadowStage) {
  const EstimatorConfig& est = settings.estimator;
  uint64_t pixels = static_cast<uint64_t>(settings.width) * settings.height;
  uint64_t plannedSamples = settings.timeBudget > 0.0 ? std::min<uint64_t>(settings.spp, 64) : settings.spp;
  uint32_t capacity = static_cast<uint32_t>(std::min<uint64_t>(pixels * plannedSamples, settings.maxPathsPerPass));
  capacity = std::min<uint32_t>(capacity, limits.maxStorageBufferRange / sizeof(gpu::PathState));
  // The pool holds camera paths and split children; each pooled path queues up to M shadow rays per bounce, and
  // under EARS the copies' split light samples share one more per slot (ears_shade.glsl earsLightSamples).
  const uint32_t poolFactor = est.pathPoolFactor();
  const uint32_t shadowPerSlot = est.lightSamples + (est.earsLearnsLight() && est.earsLightMax > 1.0f ? 1u : 0u);
  capacity = std::min<uint32_t>(capacity, limits.maxStorageBufferRange / (sizeof(gpu::PathState) * poolFactor));
  capacity = std::min<uint32_t>(capacity, limits.maxStorageBufferRange / (sizeof(gpu::ShadowRay) * shadowPerSlot * poolFactor));
  // The kernels read path states and shadow rays through texel views (common.glsl): their texels must fit too.
  const uint64_t texels = limits.maxTexelBufferElements;
  capacity = std::min<uint64_t>(capacity, texels / (gpu::kPathTexels * poolFactor));
  capacity = std::min<uint64_t>(capacity, texels / (uint64_t(gpu::kShadowRayTexels) * shadowPerSlot * poolFactor));
  if (est.rr == RouletteMode::Ears) {  // each slot's training records, and their light records
    const uint64_t recordBytes = sizeof(gpu::EarsRecord) + (est.earsLearnsLight() ? gpu::kEarsLightRecordBytes : 0);
    capacity = std::min<uint64_t>(capacity, limits.maxStorageBufferRange / (recordBytes * gpu::kEarsDepths * poolFactor));
  }
  PathPoolSize size;
  size.cameraPaths = std::max(capacity, 1u);
  size.slots = size.cameraPaths * poolFactor;
  size.shadowSlots = hasShadowStage ? uint64_t(size.slots) * shadowPerSlot : 0;
  size.extraShadowSlots = hasShadowStage ? uint64_t(size.slots) * (shadowPerSlot - est.lightSamples) : 0;
  return size;
}

}  // namespace vkmc
