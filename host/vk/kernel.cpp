// Pipelines, descriptors and timed dispatches.
#include "vk/kernel.h"

#include <array>

#include "../shaders/shared/layout.h"
#include "../shaders/shared/texture_layout.h"
#include "error.h"

namespace vkmc::vk {

bool isTexelBinding(uint32_t b) {
  for (uint32_t t : gpu::kTexelBindings)
    if (t == b) return true;
  return false;
}

bool isImageBinding(uint32_t b) { return b == BINDING_TEXTURE_PAGES; }

KernelLayout::KernelLayout(Context& ctx) : ctx_(ctx) {
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (uint32_t b = 0; b < BINDING_COUNT; ++b) {
    VkDescriptorSetLayoutBinding lb{};
    lb.binding = b;
    lb.descriptorType = isImageBinding(b)   ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER
                        : isTexelBinding(b) ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER
                                            : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    lb.descriptorCount = isImageBinding(b) ? gpu::kTexturePageViews : 1;
    lb.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    bindings.push_back(lb);
  }
  VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  lci.bindingCount = static_cast<uint32_t>(bindings.size());
  lci.pBindings = bindings.data();
  check(vkCreateDescriptorSetLayout(ctx.device(), &lci, nullptr, &setLayout_), "vkCreateDescriptorSetLayout");

  VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(gpu::PushConstants)};
  VkPipelineLayoutCreateInfo pci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  pci.setLayoutCount = 1;
  pci.pSetLayouts = &setLayout_;
  pci.pushConstantRangeCount = 1;
  pci.pPushConstantRanges = &range;
  check(vkCreatePipelineLayout(ctx.device(), &pci, nullptr, &pipelineLayout_), "vkCreatePipelineLayout");

  std::array<VkDescriptorPoolSize, 3> sizes{{{VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, uint32_t(std::size(gpu::kTexelBindings))},
                                             {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, BINDING_COUNT},
                                             {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, gpu::kTexturePageViews}}};
  VkDescriptorPoolCreateInfo dpci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  dpci.maxSets = 1;
  dpci.poolSizeCount = static_cast<uint32_t>(sizes.size());
  dpci.pPoolSizes = sizes.data();
  check(vkCreateDescriptorPool(ctx.device(), &dpci, nullptr, &pool_), "vkCreateDescriptorPool");
  VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  ai.descriptorPool = pool_;
  ai.descriptorSetCount = 1;
  ai.pSetLayouts = &setLayout_;
  check(vkAllocateDescriptorSets(ctx.device(), &ai, &set_), "vkAllocateDescriptorSets");
  const uint32_t white = 0xffffffffu;
  placeholderImage_ = std::make_unique<ArrayImage>(ctx, 1, 1, 1, &white);
  placeholderSampler_ = std::make_unique<Sampler>(ctx, VK_FILTER_LINEAR);
  for (uint32_t e = 0; e < gpu::kTexturePageViews; ++e)
    bindSampledImage(BINDING_TEXTURE_PAGES, e, placeholderImage_->unormView(), placeholderSampler_->handle());
}

KernelLayout::~KernelLayout() {
  vkDestroyDescriptorPool(ctx_.device(), pool_, nullptr);
  vkDestroyPipelineLayout(ctx_.device(), pipelineLayout_, nullptr);
  vkDestroyDescriptorSetLayout(ctx_.device(), setLayout_, nullptr);
}

void KernelLayout::write(uint32_t binding, uint32_t arrayElement, VkDescriptorType type, const VkDescriptorBufferInfo* buffer,
                         const VkBufferView* texel, const VkDescriptorImageInfo* image) {
  VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  w.dstSet = set_;
  w.dstBinding = binding;
  w.dstArrayElement = arrayElement;
  w.descriptorCount = 1;
  w.descriptorType = type;
  w.pBufferInfo = buffer;
  w.pTexelBufferView = texel;
  w.pImageInfo = image;
  vkUpdateDescriptorSets(ctx_.device(), 1, &w, 0, nullptr);
}

void KernelLayout::bindStorage(uint32_t binding, const Buffer& buffer) {
  VkDescriptorBufferInfo info{buffer.handle(), 0, VK_WHOLE_SIZE};
  write(binding, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &info, nullptr, nullptr);
}

void KernelLayout::bindTexel(uint32_t binding, const Buffer& buffer) {
  VkBufferView view = buffer.view();
  write(binding, 0, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, nullptr, &view, nullptr);
}

void KernelLayout::bindSampledImage(uint32_t binding, uint32_t arrayElement, VkImageView view, VkSampler sampler) {
  VkDescriptorImageInfo info{sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  write(binding, arrayElement, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, nullptr, nullptr, &info);
}

Kernel::Kernel(Context& ctx, const KernelLayout& layout, std::string name, std::span<const uint32_t> spirv,
               std::vector<SpecConstant> specs)
    : ctx_(ctx), name_(std::move(name)) {
  VkShaderModuleCreateInfo smci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  smci.codeSize = spirv.size_bytes();
  smci.pCode = spirv.data();
  VkShaderModule module;
  check(vkCreateShaderModule(ctx.device(), &smci, nullptr, &module), "vkCreateShaderModule");

  std::vector<VkSpecializationMapEntry> entries;
  std::vector<uint32_t> values;
  for (const SpecConstant& s : specs) {
    entries.push_back({s.id, static_cast<uint32_t>(values.size() * sizeof(uint32_t)), sizeof(uint32_t)});
    values.push_back(s.value);
  }
  VkSpecializationInfo si{static_cast<uint32_t>(entries.size()), entries.data(), values.size() * sizeof(uint32_t), values.data()};
  VkComputePipelineCreateInfo cpci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  cpci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  cpci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  cpci.stage.module = module;
  cpci.stage.pName = "main";
  cpci.stage.pSpecializationInfo = &si;
  cpci.layout = layout.pipelineLayout();
  VkResult r = vkCreateComputePipelines(ctx.device(), VK_NULL_HANDLE, 1, &cpci, nullptr, &pipeline_);
  vkDestroyShaderModule(ctx.device(), module, nullptr);
  check(r, ("vkCreateComputePipelines(" + name_ + ")").c_str());
}

Kernel::~Kernel() { vkDestroyPipeline(ctx_.device(), pipeline_, nullptr); }

GpuTimer::GpuTimer(Context& ctx, uint32_t maxQueries, bool perDispatch)
    : ctx_(ctx), capacity_(perDispatch ? maxQueries : 0), perDispatch_(perDispatch) {
  if (!ctx.hasTimestamps()) return;
  VkQueryPoolCreateInfo qci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  qci.queryType = VK_QUERY_TYPE_TIMESTAMP;
  qci.queryCount = capacity_ + 2;
  check(vkCreateQueryPool(ctx.device(), &qci, nullptr, &pool_), "vkCreateQueryPool");
}

GpuTimer::~GpuTimer() {
  if (pool_) vkDestroyQueryPool(ctx_.device(), pool_, nullptr);
}

void GpuTimer::reset(VkCommandBuffer cmd) {
  names_.clear();
  opened_ = closed_ = rangeOpen_ = false;
  if (!pool_) return;
  vkCmdResetQueryPool(cmd, pool_, 0, capacity_ + 2);
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool_, capacity_);
  opened_ = true;
}

void GpuTimer::begin(VkCommandBuffer cmd, const std::string& name) {
  if (!pool_ || !perDispatch_ || 2 * (names_.size() + 1) > capacity_) return;
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool_, static_cast<uint32_t>(2 * names_.size()));
  names_.push_back(name);
  rangeOpen_ = true;
}

void GpuTimer::end(VkCommandBuffer cmd) {
  if (!pool_ || !rangeOpen_) return;
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_, static_cast<uint32_t>(2 * names_.size() - 1));
  rangeOpen_ = false;
}

void GpuTimer::close(VkCommandBuffer cmd) {
  if (!pool_ || !opened_) return;
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_, capacity_ + 1);
  closed_ = true;
}

void GpuTimer::collect(std::map<std::string, double>& totals, double* bufferSeconds) {
  if (!pool_) return;
  // Seconds between query first + 2i and first + 2i + 1, for each of `pairs` pairs.
  auto pairSeconds = [&](uint32_t first, size_t pairs) {
    std::vector<uint64_t> ticks(2 * pairs);
    check(vkGetQueryPoolResults(ctx_.device(), pool_, first, static_cast<uint32_t>(ticks.size()), ticks.size() * sizeof(uint64_t),
                                ticks.data(), sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
          "vkGetQueryPoolResults");
    std::vector<double> seconds(pairs);
    for (size_t i = 0; i < pairs; ++i)
      seconds[i] = static_cast<double>(ticks[2 * i + 1] - ticks[2 * i]) * ctx_.timestampPeriodNs() * 1e-9;
    return seconds;
  };
  if (!names_.empty()) {
    const std::vector<double> seconds = pairSeconds(0, names_.size());
    for (size_t i = 0; i < names_.size(); ++i) totals[names_[i]] += seconds[i];
  }
  if (bufferSeconds && opened_ && closed_) *bufferSeconds += pairSeconds(capacity_, 1)[0];
  names_.clear();
  opened_ = closed_ = false;
}

void computeBarrier(VkCommandBuffer cmd) {
  VkMemoryBarrier mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  mb.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
  mb.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT |
                     VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT |
                           VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_HOST_BIT,
                       0, 1, &mb, 0, nullptr, 0, nullptr);
}

namespace {
void bindKernel(VkCommandBuffer cmd, const KernelLayout& layout, const Kernel& kernel, const void* push, uint32_t pushSize) {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, kernel.pipeline());
  VkDescriptorSet set = layout.set();
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout.pipelineLayout(), 0, 1, &set, 0, nullptr);
  vkCmdPushConstants(cmd, layout.pipelineLayout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, pushSize, push);
}
}  // namespace

void dispatch(VkCommandBuffer cmd, const KernelLayout& layout, const Kernel& kernel, const void* push, uint32_t pushSize,
              uint32_t groups, GpuTimer* timer) {
  bindKernel(cmd, layout, kernel, push, pushSize);
  if (timer) timer->begin(cmd, kernel.name());
  // 1D grids beyond the 65535-group limit fold into 2D; kernels index with invocationIndex().
  uint32_t x = groups, y = 1;
  while (x > 65535) {
    x = (x + 1) / 2;
    y *= 2;
  }
  vkCmdDispatch(cmd, x, y, 1);
  if (timer) timer->end(cmd);
  computeBarrier(cmd);
}

void dispatchIndirect(VkCommandBuffer cmd, const KernelLayout& layout, const Kernel& kernel, const void* push, uint32_t pushSize,
                      const Buffer& args, VkDeviceSize offset, GpuTimer* timer) {
  bindKernel(cmd, layout, kernel, push, pushSize);
  if (timer) timer->begin(cmd, kernel.name());
  vkCmdDispatchIndirect(cmd, args.handle(), offset);
  if (timer) timer->end(cmd);
  computeBarrier(cmd);
}

}  // namespace vkmc::vk
