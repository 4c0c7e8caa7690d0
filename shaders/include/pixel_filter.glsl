// The camera's pixel filter (pixel_filter.h): the sample's point in its pixel and its weight. The default box
// compiles to u itself and never reads the table.
layout(binding = BINDING_PIXEL_FILTER, std430) readonly buffer PixelFilterBuffer {
  PixelFilterHeader pixelFilter;
  float pixelFilterTable[];  // cdf and density at the nodes (pixel_filter.h)
};
#include "pixel_filter.h"

FilterSample samplePixelFilter(vec2 u) {
  if (kPixelFilterSampling == kPixelFilterSamplingUniform) return samplePixelBox(u);
  return samplePixelFilterTable(pixelFilter, u);
}
