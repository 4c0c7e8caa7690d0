// A VkBuffer with its memory, optionally mapped, optionally viewed as a texel buffer. Owns what it creates.
#pragma once
#include <vulkan/vulkan.h>

#include <cstddef>

#include "vk/context.h"

namespace vkmc::vk {

enum class MemoryKind { DeviceLocal, HostVisible };

class Buffer {
 public:
  Buffer() = default;
  Buffer(Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryKind kind);
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  void* mapped() const { return mapped_; }
  VkBufferView view() const { return view_; }
  // Texel-buffer view of the whole buffer (storage texel buffer usage required).
  void createView(VkFormat format);
  // Copies host data in, through a staging buffer when the memory is not mappable.
  void upload(const void* data, VkDeviceSize bytes);
  void download(void* data, VkDeviceSize bytes);
  void zero();  // every byte 0: in place when mapped, else by a fill on the device
  // Recorded into a command buffer, each followed by a barrier (kernel.h computeBarrier).
  void recordZero(VkCommandBuffer cmd) const;
  void recordCopyTo(VkCommandBuffer cmd, const Buffer& dst) const;  // the first min(size) bytes

 private:
  void release();
  Context* ctx_ = nullptr;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkBufferView view_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
};

}  // namespace vkmc::vk
