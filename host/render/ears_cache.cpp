// EARS's cache: buffers sized to the device, the grid laid over the scene, the image factor between passes.
#include "render/ears_cache.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "../shaders/shared/sampling.h"

namespace vkmc {

namespace {
constexpr uint32_t kMaxCells = 1u << 19;  // 32 MiB: far more cells than a scene's surfaces fill at 64 per side
}

EarsCache::EarsCache(vk::Context& ctx, const GpuSceneInfo& scene, uint32_t pathSlots, bool enabled) : enabled_(enabled) {
  const VkDeviceSize range = ctx.properties().limits.maxStorageBufferRange;
  auto storage = [&](VkDeviceSize bytes, vk::MemoryKind kind) {
    deviceBytes_ += bytes;
    return vk::Buffer(ctx, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, kind);
  };
  header_ = storage(sizeof(gpu::EarsHeader), vk::MemoryKind::HostVisible);
  std::memset(header_.mapped(), 0, sizeof(gpu::EarsHeader));
  auto texels = [&](VkDeviceSize bytes) {
    deviceBytes_ += bytes;
    vk::Buffer b(ctx, bytes, VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT,
                 vk::MemoryKind::DeviceLocal);
    b.createView(sceneTexelFormat(BINDING_EARS_SAMPLING));
    return b;
  };
  if (!enabled) {
    sampling_ = texels(16);
    cellBuffer_ = storage(16, vk::MemoryKind::DeviceLocal);
    records_ = storage(16, vk::MemoryKind::DeviceLocal);
    slots_ = storage(16, vk::MemoryKind::DeviceLocal);
    deviceBytes_ = 0;  // placeholders
    return;
  }
  cells_ = kMaxCells;
  const uint64_t texelLimit = ctx.properties().limits.maxTexelBufferElements / gpu::kEarsSamplingTexels;
  while (uint64_t(cells_) * sizeof(gpu::EarsCell) > range || cells_ > texelLimit) cells_ /= 2;
  cellBuffer_ = storage(uint64_t(cells_) * sizeof(gpu::EarsCell), vk::MemoryKind::DeviceLocal);
  sampling_ = texels(uint64_t(cells_) * gpu::kEarsSamplingTexels * sizeof(glm::vec4));
  sampling_.zero();
  records_ = storage(uint64_t(pathSlots) * gpu::kEarsDepths * sizeof(gpu::EarsRecord), vk::MemoryKind::DeviceLocal);
  slots_ = storage(uint64_t(pathSlots) * sizeof(gpu::EarsSlot), vk::MemoryKind::DeviceLocal);
  cellBuffer_.zero();
  records_.zero();
  slots_.zero();
  gpu::EarsHeader& h = header();
  const glm::vec3 extent = glm::max(scene.boundsMax - scene.boundsMin, glm::vec3(0.0f));
  const float side = std::max({extent.x, extent.y, extent.z});
  // A margin of one cell: points on the box's faces stay inside.
  const float cellsPerUnit = side > 0.0f ? float(gpu::kEarsGridResolution) / side : 1.0f;
  h.grid = glm::vec4(scene.boundsMin - glm::vec3(1.0f / cellsPerUnit), cellsPerUnit);
  h.cellMask = cells_ - 1;
  h.imageFactor = 0.0f;
  h.epsilon = gpu::kEarsEpsilon;
}

void EarsCache::bindTo(vk::KernelLayout& layout) const {
  layout.bindStorage(BINDING_EARS_HEADER, header_);
  layout.bindStorage(BINDING_EARS_CELLS, cellBuffer_);
  layout.bindTexel(BINDING_EARS_SAMPLING, sampling_);
  layout.bindStorage(BINDING_EARS_RECORDS, records_);
  layout.bindStorage(BINDING_EARS_SLOTS, slots_);
}

void EarsCache::setImageStatistics(double raysPerSample, double relativeVariance) {
  if (!enabled_) return;
  const double factor = relativeVariance > 0.0 && raysPerSample > 0.0 ? std::sqrt(raysPerSample / relativeVariance) : 0.0;
  header().imageFactor = std::isfinite(factor) ? static_cast<float>(factor) : 0.0f;
}

void EarsCache::beginPass() {
  if (enabled_ && header().imageFactor > 0.0f) ++learningPasses_;
}

std::vector<gpu::EarsCell> EarsCache::downloadCells() {
  std::vector<gpu::EarsCell> cells(cells_);
  if (cells_ > 0) cellBuffer_.download(cells.data(), cells.size() * sizeof(gpu::EarsCell));
  return cells;
}

std::vector<glm::vec4> EarsCache::downloadSampling() {
  std::vector<glm::vec4> texels(size_t(cells_) * gpu::kEarsSamplingTexels);
  if (cells_ > 0) sampling_.download(texels.data(), texels.size() * sizeof(glm::vec4));
  return texels;
}

EarsSummary EarsCache::summary() {
  EarsSummary s;
  if (!enabled_) return s;
  s.cells = cells_;
  s.deviceBytes = deviceBytes_;
  s.learningPasses = learningPasses_;
  s.trainingSamples = trainingSamples_;
  s.imageFactor = header().imageFactor;
  glm::dvec4 sum(0.0), squares(0.0);
  for (const gpu::EarsCell& c : downloadCells()) {
    s.occupiedCells += c.sum.w > 0.0f;
    sum += glm::dvec4(c.sum);
    squares += glm::dvec4(c.sumSquares);
  }
  const std::vector<glm::vec4> sampling = downloadSampling();
  for (size_t i = 0; i < cells_; ++i) s.trustedCells += sampling[gpu::kEarsSamplingTexels * i].w >= gpu::kEarsMinCellCopies;
  s.copies = sum.w;
  if (sum.w > 0.0) {
    s.meanLr = glm::dvec3(sum) / sum.w;
    s.meanLrSquared = glm::dvec3(squares) / sum.w;
    s.meanRays = squares.w / sum.w;
  }
  for (uint32_t d = 0; d < gpu::kEarsHistogramDepths; ++d)
    for (uint32_t b = 0; b < gpu::kEarsBins; ++b) s.factors[d][b] = header().factors[d * gpu::kEarsBins + b];
  return s;
}

}  // namespace vkmc
