// Compute kernels: the one descriptor-set layout every kernel shares, pipelines built from embedded SPIR-V
// with specialization constants, and named dispatches timed by timestamp queries.
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/image.h"

namespace vkmc::vk {

struct SpecConstant {
  uint32_t id;
  uint32_t value;
};

// Whether a binding is a storage texel buffer (gpu::kTexelBindings) rather than a storage buffer or, for
// BINDING_TEXTURE_PAGES, an array of combined image samplers.
bool isTexelBinding(uint32_t binding);
bool isImageBinding(uint32_t binding);

// Descriptor set layout (all bindings of layout.h), push-constant range, one descriptor set. The image binding
// starts out pointing at a 1x1 placeholder: lavapipe crashes binding a set with an unwritten image descriptor.
class KernelLayout {
 public:
  explicit KernelLayout(Context& ctx);
  ~KernelLayout();
  KernelLayout(const KernelLayout&) = delete;
  KernelLayout& operator=(const KernelLayout&) = delete;

  void bindStorage(uint32_t binding, const Buffer& buffer);
  void bindTexel(uint32_t binding, const Buffer& buffer);  // buffer must have a view
  void bindSampledImage(uint32_t binding, uint32_t arrayElement, VkImageView view, VkSampler sampler);
  VkPipelineLayout pipelineLayout() const { return pipelineLayout_; }
  VkDescriptorSet set() const { return set_; }

 private:
  void write(uint32_t binding, uint32_t arrayElement, VkDescriptorType type, const VkDescriptorBufferInfo* buffer,
             const VkBufferView* texel, const VkDescriptorImageInfo* image);
  Context& ctx_;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  std::unique_ptr<ArrayImage> placeholderImage_;
  std::unique_ptr<Sampler> placeholderSampler_;
};

class Kernel {
 public:
  Kernel(Context& ctx, const KernelLayout& layout, std::string name, std::span<const uint32_t> spirv,
         std::vector<SpecConstant> specs);
  ~Kernel();
  Kernel(const Kernel&) = delete;
  Kernel& operator=(const Kernel&) = delete;
  const std::string& name() const { return name_; }
  VkPipeline pipeline() const { return pipeline_; }

 private:
  Context& ctx_;
  std::string name_;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
};

// Timestamp pairs around named dispatches (ranges), and one pair around a whole command buffer (reset/close);
// collect() sums the seconds per name and the buffer's. Without ranges (perDispatch false) begin and end write
// nothing: on lavapipe a timestamp costs about as much as a small dispatch, 6-18% of a render's time, most
// where passes are small (docs/journal/performance.md, "Stage timestamps").
class GpuTimer {
 public:
  GpuTimer(Context& ctx, uint32_t maxQueries, bool perDispatch = true);
  ~GpuTimer();
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;
  void reset(VkCommandBuffer cmd);  // and the command buffer's first timestamp
  void begin(VkCommandBuffer cmd, const std::string& name);
  void end(VkCommandBuffer cmd);
  void close(VkCommandBuffer cmd);  // the command buffer's last timestamp (before submitting)
  // After the command buffer completed: adds each range's seconds to totals[name], and the buffer's between reset
  // and close to *bufferSeconds.
  void collect(std::map<std::string, double>& totals, double* bufferSeconds = nullptr);
  bool enabled() const { return pool_ != VK_NULL_HANDLE; }

 private:
  Context& ctx_;
  VkQueryPool pool_ = VK_NULL_HANDLE;
  uint32_t capacity_ = 0;  // of ranges' queries; the buffer's pair follows them
  bool perDispatch_ = true;
  bool opened_ = false, closed_ = false;
  bool rangeOpen_ = false;  // the last begin() wrote its stamp (a full pool writes none)
  std::vector<std::string> names_;
};

// Records one compute dispatch: bind, push constants, dispatch (direct or indirect), barrier after.
void dispatch(VkCommandBuffer cmd, const KernelLayout& layout, const Kernel& kernel, const void* push, uint32_t pushSize,
              uint32_t groups, GpuTimer* timer = nullptr);
void dispatchIndirect(VkCommandBuffer cmd, const KernelLayout& layout, const Kernel& kernel, const void* push, uint32_t pushSize,
                      const Buffer& args, VkDeviceSize offset, GpuTimer* timer = nullptr);
void computeBarrier(VkCommandBuffer cmd);

}  // namespace vkmc::vk
