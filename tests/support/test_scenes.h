// Small glTF files written on the fly (JSON + external .bin) for loader and bad-input tests.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/gltf_loader.h"

namespace vkmc::test {

struct GltfSpec {
  std::vector<float> positions;    // xyz per vertex
  std::vector<uint32_t> indices;   // empty: non-indexed
  int indexComponentType = 5125;   // 5121 u8, 5123 u16, 5125 u32
  int positionCountOverride = -1;  // claim more vertices than the buffer holds
  bool writeBin = true;            // false: the referenced .bin is missing
  std::string nodeExtra;           // extra JSON inside the node, e.g. "\"translation\":[1,2,3]"
  std::string materialJson = R"({"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.5,0.5,1]},"emissiveFactor":[1,1,1]})";
  int mode = 4;
};

// Writes dir/name.gltf (+ name.bin) and returns the .gltf path.
std::string writeGltf(const std::filesystem::path& dir, const std::string& name, const GltfSpec& spec);
std::filesystem::path makeTempDir(const std::string& tag);

// A unit quad in the z = 0 plane facing +z, as two triangles.
GltfSpec quadSpec();

// The one-line error loading `path` gives ("" when it loads); a message of more than one line fails the test.
std::string loadError(const std::string& path, const LoadLimits& limits = {});

}  // namespace vkmc::test
