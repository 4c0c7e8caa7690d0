// EARS's learned cache on the device (shaders/shared/ears.h): its cells, each path slot's training records, the
// header the kernels read, and, between passes, the image factor every factor is scaled by
// (ears_image_statistics.h). Without EARS the bindings get 16-byte placeholders.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "../shaders/shared/layout.h"
#include "render/gpu_scene.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/kernel.h"

namespace vkmc {

// What a render's cache learned, for the report.
struct EarsSummary {
  uint32_t cells = 0;            // in the hash table
  uint32_t occupiedCells = 0;    // with any training sample
  uint32_t trustedCells = 0;     // finest cells whose levels have enough to decide (kEarsMinCellCopies)
  uint64_t deviceBytes = 0;      // cells, records, slots and header
  uint32_t learningPasses = 0;   // passes whose factors came from the cache
  uint32_t trainingSamples = 0;  // per pixel, in the training passes (not in the image)
  double imageFactor = 0.0;      // sqrt(C_img / V_img) of the last pass
  // Over every cell: the training copies, and their mean Lr, Lr^2 (per channel) and rays.
  double copies = 0.0, meanRays = 0.0;
  glm::dvec3 meanLr{0.0}, meanLrSquared{0.0};
  std::array<std::array<uint64_t, gpu::kEarsBins>, gpu::kEarsHistogramDepths> factors{};  // vertices by depth and bin
  // The light cells alike (ears_light_max > 0): the copies' first light samples, their mean v, v^2 and rays.
  bool learnsLight = false;
  uint32_t occupiedLightCells = 0, trustedLightCells = 0;
  double lightSamples = 0.0, meanLightRays = 0.0;
  glm::dvec3 meanV{0.0}, meanVSquared{0.0};
  std::array<std::array<uint64_t, gpu::kEarsBins>, gpu::kEarsHistogramDepths> lightFactors{};  // copies by depth, bin
};

class EarsCache {
 public:
  // enabled false: placeholders only. pathSlots: the path pool (kEarsDepths records each); learnsLight: light cells
  // too (ears_light_max > 0); extraShadowSlots: the shadow queue's room for split light samples (PathPoolSize).
  EarsCache(vk::Context& ctx, const GpuSceneInfo& scene, uint32_t pathSlots, bool enabled, bool learnsLight,
            uint64_t extraShadowSlots);
  bool enabled() const { return enabled_; }
  void bindTo(vk::KernelLayout& layout) const;
  // Between passes: the factors' image statistics (C_img: rays per sample of the pass just done).
  void setImageStatistics(double raysPerSample, double relativeVariance);
  // At a pass's start: counts the passes whose factors come from the cache.
  void beginPass();
  void noteTrainingSamples(uint32_t samplesPerPixel) { trainingSamples_ += samplesPerPixel; }
  EarsSummary summary();
  uint64_t deviceBytes() const { return deviceBytes_; }
  // The pass's training lists (ears.h EarsHeader): records written and slots split off; emptied after training.
  uint32_t trainingRecords() const { return header().trainingRecords; }
  uint32_t trainingChildren() const { return header().trainingChildren; }
  void clearTrainingLists() const { header().trainingRecords = header().trainingChildren = 0; }
  uint32_t cellCount() const { return cells_; }                            // copies' cells (as many light cells follow)
  uint32_t tableCells() const { return (learnsLight_ ? 2 : 1) * cells_; }  // both kinds
  std::vector<gpu::EarsCell> downloadCells();                              // tableCells()
  std::vector<glm::vec4> downloadSampling();                               // kEarsSamplingTexels per cell of tableCells()

 private:
  gpu::EarsHeader& header() const { return *static_cast<gpu::EarsHeader*>(header_.mapped()); }
  bool enabled_, learnsLight_;
  uint32_t cells_ = 0;
  uint32_t learningPasses_ = 0;
  uint32_t trainingSamples_ = 0;
  uint64_t deviceBytes_ = 0;
  vk::Buffer header_, cellBuffer_, sampling_, records_, slots_, training_;
};

}  // namespace vkmc
