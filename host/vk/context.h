// Vulkan instance, device, compute queue and one-shot command helpers. Headless: no surface, no window.
#pragma once
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace vkmc::vk {

void check(VkResult result, const char* what);

struct ContextOptions {
  int deviceIndex = -1;  // -1: prefer a discrete GPU, else the first device (VKMC_DEVICE overrides)
};

class Context {
 public:
  explicit Context(const ContextOptions& options = {});
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkDevice device() const { return device_; }
  VkPhysicalDevice physicalDevice() const { return physical_; }
  VkQueue queue() const { return queue_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  std::string deviceName() const { return properties_.deviceName; }
  bool hasTimestamps() const { return timestampBits_ > 0; }
  bool hasFloatAtomics() const { return floatAtomics_; }  // shaderBufferFloat32AtomicAdd enabled
  // CPU devices (lavapipe) and integrated GPUs: device memory is host memory, so buffers the host reads or writes
  // each pass are mapped in place; a discrete GPU keeps them device-local and copies (PathRenderer).
  VkPhysicalDeviceType deviceType() const { return properties_.deviceType; }
  uint32_t subgroupSize() const { return subgroupSize_; }
  // lavapipe's SIMD width in bits (its subgroup x 32; lavapipe_environment.h); 0 on other devices.
  unsigned cpuVectorBits() const { return properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? subgroupSize_ * 32u : 0u; }
  bool unifiedMemory() const {
    return properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ||
           properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU;
  }
  double timestampPeriodNs() const { return properties_.limits.timestampPeriod; }
  uint64_t maxAllocationBytes() const { return maxAllocationBytes_; }  // maxMemoryAllocationSize
  uint64_t largestDeviceLocalHeapBytes() const {
    uint64_t best = 0;
    for (uint32_t i = 0; i < memory_.memoryHeapCount; ++i)
      if (memory_.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
        best = std::max<uint64_t>(best, memory_.memoryHeaps[i].size);
    return best;
  }

  uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) const;

  VkCommandBuffer beginCommands();
  // Submits, waits for completion, frees the command buffer.
  void submitAndWait(VkCommandBuffer cmd);
  void runCommands(const std::function<void(VkCommandBuffer)>& record);

 private:
  void readDevice();  // properties, limits, requirements and the compute queue of physical_
  VkInstance instance_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  uint32_t timestampBits_ = 0;
  bool floatAtomics_ = false;
  uint32_t subgroupSize_ = 0;
  uint64_t maxAllocationBytes_ = 0;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_{};
};

}  // namespace vkmc::vk
