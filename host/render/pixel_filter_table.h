// What the device reads of a pixel filter (BINDING_PIXEL_FILTER): its header and the piecewise-linear sampling
// table through |f| (layout in shaders/shared/pixel_filter.h), built on the host.
#pragma once
#include <vector>

#include "../shaders/shared/layout.h"
#include "render/pixel_filter.h"

namespace vkmc {

struct PixelFilterTable {
  gpu::PixelFilterHeader header{};
  std::vector<float> table;  // cdf at the nodes, then the density at the nodes (pixelFilterTableSize())
};

// The header's kind, radius and parameters, with invIntegral still 1.
gpu::PixelFilterHeader pixelFilterHeader(const PixelFilter& filter);
// Integrals over [-radius, radius] of f1 and of |f1| (composite Simpson on 8192 intervals: the Mitchell pieces'
// knots are nodes, and Simpson is exact on cubics).
double pixelFilterIntegral(const gpu::PixelFilterHeader& header, bool absolute = false);
PixelFilterTable buildPixelFilterTable(const PixelFilter& filter);
// The header followed by the table, as BINDING_PIXEL_FILTER holds them.
std::vector<float> pixelFilterBufferData(const PixelFilterTable& t);

}  // namespace vkmc
