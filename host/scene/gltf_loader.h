// glTF 2.0 (.gltf with external or embedded buffers, .glb) into a flat world-space Scene.
#pragma once
#include <string>

#include "scene/scene.h"

namespace vkmc {

// Throws vkmc::Error with a one-line reason on malformed input (bad JSON, missing buffers, out-of-range
// accessors or indices, non-finite positions or factors, no triangles, cyclic node graphs).
Scene loadGltf(const std::string& path);

}  // namespace vkmc
