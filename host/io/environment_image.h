// Environment maps from files: Radiance .hdr (stb_image) or OpenEXR (R, G, B channels), validated.
#pragma once
#include <string>

#include "scene/scene.h"

namespace vkmc {

// Reads an equirectangular map, times `strength`, rotated by `rotationDegrees` about +Y. Throws Error with one
// line on a missing or unreadable file, an unknown extension, or a pixel that is negative or not finite.
EnvironmentMap readEnvironmentMap(const std::string& path, float rotationDegrees = 0.0f, float strength = 1.0f);

}  // namespace vkmc
