// Buffer creation, staging uploads and readbacks.
#include "vk/buffer.h"

#include "vk/kernel.h"

#include <algorithm>
#include <cstring>
#include <utility>

namespace vkmc::vk {

Buffer::Buffer(Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryKind kind) : ctx_(&ctx), size_(size) {
  VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  bci.size = size == 0 ? 16 : size;
  bci.usage = usage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  check(vkCreateBuffer(ctx.device(), &bci, nullptr, &buffer_), "vkCreateBuffer");
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(ctx.device(), buffer_, &req);
  VkMemoryPropertyFlags required = kind == MemoryKind::HostVisible
                                       ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                                       : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  VkMemoryPropertyFlags preferred = kind == MemoryKind::HostVisible ? VK_MEMORY_PROPERTY_HOST_CACHED_BIT : 0;
  VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  ai.allocationSize = req.size;
  ai.memoryTypeIndex = ctx.findMemoryType(req.memoryTypeBits, required, preferred);
  check(vkAllocateMemory(ctx.device(), &ai, nullptr, &memory_), "vkAllocateMemory");
  check(vkBindBufferMemory(ctx.device(), buffer_, memory_, 0), "vkBindBufferMemory");
  if (kind == MemoryKind::HostVisible) check(vkMapMemory(ctx.device(), memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");
}

Buffer::~Buffer() { release(); }

void Buffer::release() {
  if (!ctx_) return;
  VkDevice d = ctx_->device();
  if (view_) vkDestroyBufferView(d, view_, nullptr);
  if (buffer_) vkDestroyBuffer(d, buffer_, nullptr);
  if (memory_) vkFreeMemory(d, memory_, nullptr);
  ctx_ = nullptr;
}

Buffer::Buffer(Buffer&& o) noexcept { *this = std::move(o); }

Buffer& Buffer::operator=(Buffer&& o) noexcept {
  if (this != &o) {
    release();
    ctx_ = std::exchange(o.ctx_, nullptr);
    buffer_ = std::exchange(o.buffer_, VK_NULL_HANDLE);
    memory_ = std::exchange(o.memory_, VK_NULL_HANDLE);
    view_ = std::exchange(o.view_, VK_NULL_HANDLE);
    size_ = std::exchange(o.size_, 0);
    mapped_ = std::exchange(o.mapped_, nullptr);
  }
  return *this;
}

void Buffer::createView(VkFormat format) {
  VkBufferViewCreateInfo vci{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
  vci.buffer = buffer_;
  vci.format = format;
  vci.offset = 0;
  vci.range = VK_WHOLE_SIZE;
  check(vkCreateBufferView(ctx_->device(), &vci, nullptr, &view_), "vkCreateBufferView");
}

void Buffer::upload(const void* data, VkDeviceSize bytes) {
  if (bytes == 0) return;
  if (mapped_) {
    std::memcpy(mapped_, data, bytes);
    return;
  }
  Buffer staging(*ctx_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryKind::HostVisible);
  std::memcpy(staging.mapped(), data, bytes);
  ctx_->runCommands([&](VkCommandBuffer cmd) {
    VkBufferCopy region{0, 0, bytes};
    vkCmdCopyBuffer(cmd, staging.handle(), buffer_, 1, &region);
  });
}

void Buffer::download(void* data, VkDeviceSize bytes) {
  if (bytes == 0) return;
  if (mapped_) {
    std::memcpy(data, mapped_, bytes);
    return;
  }
  Buffer staging(*ctx_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::HostVisible);
  ctx_->runCommands([&](VkCommandBuffer cmd) {
    VkBufferCopy region{0, 0, bytes};
    vkCmdCopyBuffer(cmd, buffer_, staging.handle(), 1, &region);
  });
  std::memcpy(data, staging.mapped(), bytes);
}

void Buffer::zero() {
  if (mapped_) {
    std::memset(mapped_, 0, size_);
    return;
  }
  ctx_->runCommands([&](VkCommandBuffer cmd) { recordZero(cmd); });
}

void Buffer::recordZero(VkCommandBuffer cmd) const {
  vkCmdFillBuffer(cmd, buffer_, 0, VK_WHOLE_SIZE, 0u);
  computeBarrier(cmd);
}

void Buffer::recordCopyTo(VkCommandBuffer cmd, const Buffer& dst) const {
  VkBufferCopy region{0, 0, std::min(size_, dst.size_)};
  vkCmdCopyBuffer(cmd, buffer_, dst.buffer_, 1, &region);
  computeBarrier(cmd);
}

}  // namespace vkmc::vk
