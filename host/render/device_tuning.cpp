// Per-device defaults, each from a measurement where one exists (docs/journal/performance.md).
#include "render/device_tuning.h"

#include <algorithm>

namespace vkmc {

DeviceTuning deviceTuning(VkPhysicalDeviceType type, uint32_t subgroupSize) {
  DeviceTuning t;
  const bool discrete = type == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU;
  // Megakernel on a discrete GPU: 1.3-2.3x the wavefront's samples/s on an H200 (no host round trip between
  // stages); on lavapipe the wavefront (its SIMD programs idle less with one stage per dispatch). Integrated GPUs
  // are unmeasured and keep the wavefront.
  t.integrator = discrete ? Integrator::Megakernel : Integrator::Wavefront;
  // lavapipe: 32 to 256 measured alike (it loops a workgroup over 8-wide programs); 64 keeps two NVIDIA warps or
  // one AMD wave64 per workgroup. A device whose subgroups are wider gets one subgroup per workgroup.
  t.workgroupSize = std::clamp(subgroupSize, 64u, 256u);
  // Paths in flight: 2^18 keeps lavapipe's queues in its caches' reach; a discrete GPU holds ~10^5-10^6
  // resident invocations (an H200: 132 SMs x 2048), and at 2^18 its 1024x1024 wavefront ran 64 passes of 16
  // bounce-stage round trips each. 2^20 quarters the passes (unmeasured: tools/gpu_check.sh sweeps it).
  t.wavefrontPaths = discrete ? 1u << 20 : 1u << 18;
  // Stage timestamps: on lavapipe each costs about what a small dispatch does (~70 us), 6% of a 256x256 Cornell
  // box render and 11-18% at 96x96, where a pass's near-empty bounces are most of its dispatches; GPUs write
  // them in the command stream.
  t.stageTimes = type != VK_PHYSICAL_DEVICE_TYPE_CPU;
  return t;
}

}  // namespace vkmc
