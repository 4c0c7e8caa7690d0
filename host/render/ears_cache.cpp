// EARS's cache: buffers sized to the device, the grid laid over the scene, the image factor between passes.
#include "render/ears_cache.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <tuple>

#include "../shaders/shared/sampling.h"

namespace vkmc {

namespace {
constexpr uint32_t kMaxCells = 1u << 19;  // of each kind (32 MiB of sums and learned texels a kind): far more cells
                                          // than a scene's surfaces fill at 64 per side
}

EarsCache::EarsCache(vk::Context& ctx, const GpuSceneInfo& scene, uint32_t pathSlots, bool enabled, bool learnsLight,
                     uint64_t extraShadowSlots)
    : enabled_(enabled), learnsLight_(enabled && learnsLight) {
  const VkDeviceSize range = ctx.properties().limits.maxStorageBufferRange;
  auto storage = [&](VkDeviceSize bytes, vk::MemoryKind kind) {
    deviceBytes_ += bytes;
    return vk::Buffer(ctx, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, kind);
  };
  header_ = storage(sizeof(gpu::EarsHeader), vk::MemoryKind::HostVisible);
  std::memset(header_.mapped(), 0, sizeof(gpu::EarsHeader));
  auto texels = [&](VkDeviceSize bytes) {
    deviceBytes_ += bytes;
    vk::Buffer b(ctx, notPowerOfTwoTexelBytes(ctx, bytes), VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT, vk::MemoryKind::DeviceLocal);
    b.createView(sceneTexelFormat(BINDING_EARS_SAMPLING));
    return b;
  };
  if (!enabled) {
    sampling_ = texels(16);
    cellBuffer_ = storage(16, vk::MemoryKind::DeviceLocal);
    records_ = storage(16, vk::MemoryKind::DeviceLocal);
    slots_ = storage(16, vk::MemoryKind::DeviceLocal);
    training_ = storage(16, vk::MemoryKind::DeviceLocal);
    deviceBytes_ = 0;  // placeholders
    return;
  }
  cells_ = kMaxCells;
  const uint64_t texelLimit = ctx.properties().limits.maxTexelBufferElements / gpu::kEarsSamplingTexels;
  // The cells, then a key word per copies' cell (ears.h earsKeyWord).
  auto cellBytes = [&] { return uint64_t(tableCells()) * sizeof(gpu::EarsCell) + uint64_t(cells_) * sizeof(uint32_t); };
  while (cellBytes() > range || tableCells() > texelLimit) cells_ /= 2;
  cellBuffer_ = storage(cellBytes(), vk::MemoryKind::DeviceLocal);
  sampling_ = texels(uint64_t(tableCells()) * gpu::kEarsSamplingTexels * sizeof(glm::vec4));
  sampling_.zero();
  const uint64_t recordBytes = sizeof(gpu::EarsRecord) + (learnsLight_ ? gpu::kEarsLightRecordBytes : 0);
  records_ = storage(uint64_t(pathSlots) * gpu::kEarsDepths * recordBytes, vk::MemoryKind::DeviceLocal);
  slots_ = storage(uint64_t(pathSlots) * sizeof(gpu::EarsSlot), vk::MemoryKind::DeviceLocal);
  training_ = storage(uint64_t(pathSlots) * (gpu::kEarsDepths + 1) * sizeof(uint32_t), vk::MemoryKind::DeviceLocal);
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
  h.extraShadowSlots = static_cast<uint32_t>(std::min<uint64_t>(extraShadowSlots, UINT32_MAX));
}

void EarsCache::bindTo(vk::KernelLayout& layout) const {
  layout.bindStorage(BINDING_EARS_HEADER, header_);
  layout.bindStorage(BINDING_EARS_CELLS, cellBuffer_);
  layout.bindTexel(BINDING_EARS_SAMPLING, sampling_);
  layout.bindStorage(BINDING_EARS_RECORDS, records_);
  layout.bindStorage(BINDING_EARS_SLOTS, slots_);
  layout.bindStorage(BINDING_EARS_TRAINING, training_);
}

void EarsCache::setImageStatistics(double raysPerSample, double relativeVariance) {
  if (!enabled_) return;
  const double factor = relativeVariance > 0.0 && raysPerSample > 0.0 ? std::sqrt(raysPerSample / relativeVariance) : 0.0;
  header().imageFactor = std::isfinite(factor) ? static_cast<float>(factor) : 0.0f;
}

void EarsCache::beginPass() {
  if (!enabled_) return;
  clearTrainingLists();  // normally empty already: a pass that threw left its entries behind
  if (header().imageFactor > 0.0f) ++learningPasses_;
}

std::vector<gpu::EarsCell> EarsCache::downloadCells() {
  std::vector<gpu::EarsCell> cells(tableCells());
  if (cells_ > 0) cellBuffer_.download(cells.data(), cells.size() * sizeof(gpu::EarsCell));
  return cells;
}

std::vector<glm::vec4> EarsCache::downloadSampling() {
  std::vector<glm::vec4> texels(size_t(tableCells()) * gpu::kEarsSamplingTexels);
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
  const std::vector<gpu::EarsCell> cells = downloadCells();
  const std::vector<glm::vec4> sampling = downloadSampling();
  // Each kind's occupied and trusted cells and the pooled sums: copies' cells first, then the light cells.
  auto pool = [&](size_t first, uint32_t& occupied, uint32_t& trusted) {
    glm::dvec4 sum(0.0), squares(0.0);
    for (size_t i = first; i < first + cells_; ++i) {
      occupied += cells[i].sum.w > 0.0f;
      trusted += sampling[gpu::kEarsSamplingTexels * i].w >= gpu::kEarsMinCellCopies;
      sum += glm::dvec4(cells[i].sum);
      squares += glm::dvec4(cells[i].sumSquares);
    }
    return std::make_pair(sum, squares);
  };
  auto [sum, squares] = pool(0, s.occupiedCells, s.trustedCells);
  s.copies = sum.w;
  if (sum.w > 0.0) {
    s.meanLr = glm::dvec3(sum) / sum.w;
    s.meanLrSquared = glm::dvec3(squares) / sum.w;
    s.meanRays = squares.w / sum.w;
  }
  s.learnsLight = learnsLight_;
  glm::dvec4 lightSum(0.0), lightSquares(0.0);
  if (learnsLight_) std::tie(lightSum, lightSquares) = pool(cells_, s.occupiedLightCells, s.trustedLightCells);
  s.lightSamples = lightSum.w;
  if (lightSum.w > 0.0) {
    s.meanV = glm::dvec3(lightSum) / lightSum.w;
    s.meanVSquared = glm::dvec3(lightSquares) / lightSum.w;
    s.meanLightRays = lightSquares.w / lightSum.w;
  }
  for (uint32_t d = 0; d < gpu::kEarsHistogramDepths; ++d)
    for (uint32_t b = 0; b < gpu::kEarsBins; ++b) {
      auto count = [&](uint32_t h) { return header().histograms[(h * gpu::kEarsHistogramDepths + d) * gpu::kEarsBins + b]; };
      s.factors[d][b] = count(gpu::kEarsFactorHistogram);
      s.lightFactors[d][b] = count(gpu::kEarsLightHistogram);
    }
  return s;
}

}  // namespace vkmc
