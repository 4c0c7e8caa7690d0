// Array images: creation, staging upload with layout transitions, views; samplers.
#include "vk/image.h"

#include <cstring>
#include <vector>

#include "error.h"
#include "vk/buffer.h"

namespace vkmc::vk {

ArrayImage::ArrayImage(Context& ctx, uint32_t width, uint32_t height, uint32_t layers, const uint32_t* texels) : ctx_(ctx) {
  VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  ici.flags = VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT;  // the SRGB view of UNORM texels
  ici.imageType = VK_IMAGE_TYPE_2D;
  ici.format = VK_FORMAT_R8G8B8A8_UNORM;
  ici.extent = {width, height, 1};
  ici.mipLevels = 1;
  ici.arrayLayers = layers;
  ici.samples = VK_SAMPLE_COUNT_1_BIT;
  ici.tiling = VK_IMAGE_TILING_OPTIMAL;
  ici.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  check(vkCreateImage(ctx.device(), &ici, nullptr, &image_), "vkCreateImage");
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(ctx.device(), image_, &req);
  VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  ai.allocationSize = req.size;
  ai.memoryTypeIndex = ctx.findMemoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0);
  VkResult r = vkAllocateMemory(ctx.device(), &ai, nullptr, &memory_);
  if (r != VK_SUCCESS) {
    vkDestroyImage(ctx.device(), image_, nullptr);
    throw Error("textures too big for the device: " + std::to_string(req.size >> 20) +
                " MiB of texture pages could not be allocated");
  }
  check(vkBindImageMemory(ctx.device(), image_, memory_, 0), "vkBindImageMemory");
  upload(width, height, layers, texels);
  for (VkFormat f : {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_R8G8B8A8_SRGB}) {
    VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vci.image = image_;
    vci.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    vci.format = f;
    vci.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, layers};
    check(vkCreateImageView(ctx.device(), &vci, nullptr, f == VK_FORMAT_R8G8B8A8_SRGB ? &srgb_ : &unorm_), "vkCreateImageView");
  }
}

ArrayImage::~ArrayImage() {
  VkDevice d = ctx_.device();
  vkDestroyImageView(d, srgb_, nullptr);
  vkDestroyImageView(d, unorm_, nullptr);
  vkDestroyImage(d, image_, nullptr);
  vkFreeMemory(d, memory_, nullptr);
}

void ArrayImage::upload(uint32_t width, uint32_t height, uint32_t layers, const uint32_t* texels) {
  const VkDeviceSize layerBytes = VkDeviceSize(width) * height * 4;
  Buffer staging(ctx_, layerBytes * layers, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryKind::HostVisible);
  std::memcpy(staging.mapped(), texels, layerBytes * layers);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, layers};
  region.imageExtent = {width, height, 1};
  auto transition = [&](VkCommandBuffer cmd, VkImageLayout from, VkImageLayout to, VkAccessFlags src, VkAccessFlags dst,
                        VkPipelineStageFlags srcStage, VkPipelineStageFlags dstStage) {
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.oldLayout = from;
    b.newLayout = to;
    b.srcAccessMask = src;
    b.dstAccessMask = dst;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image_;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, layers};
    vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &b);
  };
  ctx_.runCommands([&](VkCommandBuffer cmd) {
    transition(cmd, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT,
               VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    vkCmdCopyBufferToImage(cmd, staging.handle(), image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
               VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  });
}

Sampler::Sampler(Context& ctx, VkFilter filter) : ctx_(ctx) {
  VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  sci.magFilter = sci.minFilter = filter;
  sci.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  sci.addressModeU = sci.addressModeV = sci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  sci.maxLod = 0.0f;
  check(vkCreateSampler(ctx.device(), &sci, nullptr, &sampler_), "vkCreateSampler");
}

Sampler::~Sampler() { vkDestroySampler(ctx_.device(), sampler_, nullptr); }

}  // namespace vkmc::vk
