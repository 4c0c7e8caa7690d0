// glTF 2.0 (.gltf with external or embedded buffers, .glb) into a flat world-space Scene.
#pragma once
#include <string>
#include <vector>

#include "scene/gltf_input_guard.h"
#include "scene/scene.h"

namespace vkmc {

// Throws vkmc::Error with a one-line reason on malformed input (bad JSON, missing buffers, out-of-range
// accessors or indices, non-finite positions or factors, no triangles, cyclic node graphs).
struct LoadLimits {
  // Instancing can multiply a small file into an enormous scene: stop long before memory runs out. The
  // renderer lowers this to what the device's buffers hold (maxSceneTriangles).
  uint64_t maxTriangles = uint64_t(1) << 25;
  // Decoded texels of all images together (4 bytes each on the device); images past it are ignored with a warning.
  uint64_t maxTextureTexels = uint64_t(1) << 28;
  // An image's side; larger ones are ignored with a warning. The renderer lowers it to what a texture page holds.
  uint32_t maxTextureSide = 16384;
  InputLimits input;
};

Scene loadGltf(const std::string& path, const LoadLimits& limits = {});
// The files a scene reads: the file itself, then its buffers' and images' files (never an output's place). Only the
// file where it cannot be read: the load names why.
std::vector<std::string> gltfInputFiles(const std::string& path, const LoadLimits& limits = {});
// The same from a file's bytes (binary: GLB); URIs resolve against baseDir. `name` labels the scene.
Scene loadGltfFromMemory(const std::vector<unsigned char>& bytes, bool binary, const std::string& baseDir,
                         const std::string& name, const LoadLimits& limits = {});

}  // namespace vkmc
