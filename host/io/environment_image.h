// Environment maps from files: Radiance .hdr (io/radiance_hdr) or OpenEXR (R, G, B channels), validated.
#pragma once
#include <string>

#include "scene/scene.h"

namespace vkmc {

// Reads an equirectangular map, times `strength`, rotated by `rotationDegrees` about +Y. Throws Error with one
// line on a missing, unreadable, truncated or corrupt file, an unknown extension, a map of more than maxTexels
// texels (checked before its pixels are allocated), or a pixel that is negative or not finite.
EnvironmentMap readEnvironmentMap(const std::string& path, float rotationDegrees = 0.0f, float strength = 1.0f,
                                  uint64_t maxTexels = uint64_t(1) << 24);

}  // namespace vkmc
