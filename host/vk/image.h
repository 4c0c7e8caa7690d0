// A 2D array image of RGBA8 texels in device memory, uploaded once and sampled through a UNORM and an SRGB view,
// and the samplers that read it. Owns what it creates.
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>

#include "vk/context.h"

namespace vkmc::vk {

class ArrayImage {
 public:
  // texels: layers x height x width RGBA8 (R in the low byte), layer by layer, row-major.
  ArrayImage(Context& ctx, uint32_t width, uint32_t height, uint32_t layers, const uint32_t* texels);
  ~ArrayImage();
  ArrayImage(const ArrayImage&) = delete;
  ArrayImage& operator=(const ArrayImage&) = delete;
  VkImageView unormView() const { return unorm_; }
  VkImageView srgbView() const { return srgb_; }

 private:
  void upload(uint32_t width, uint32_t height, uint32_t layers, const uint32_t* texels);
  Context& ctx_;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView unorm_ = VK_NULL_HANDLE, srgb_ = VK_NULL_HANDLE;
};

// Single-level, clamp-to-edge sampling at normalized coordinates with the given filter.
class Sampler {
 public:
  Sampler(Context& ctx, VkFilter filter);
  ~Sampler();
  Sampler(const Sampler&) = delete;
  Sampler& operator=(const Sampler&) = delete;
  VkSampler handle() const { return sampler_; }

 private:
  Context& ctx_;
  VkSampler sampler_ = VK_NULL_HANDLE;
};

}  // namespace vkmc::vk
