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

// Quads, each its own mesh with TEXCOORD_0 (0,0) (1,0) (1,1) (0,1) at o, o + u, o + u + v, o + v (front face
// along u x v), and a material index into materialsJson (a JSON array's elements, without brackets).
struct QuadSpec {
  float o[3], u[3], v[3];
  int material = 0;
};
// rootExtra: more root members, e.g. R"("images":[...],"textures":[...])" (without a leading comma).
std::string writeQuadsGltf(const std::filesystem::path& dir, const std::string& name, const std::vector<QuadSpec>& quads,
                           const std::string& materialsJson, const std::string& rootExtra = "");

// Writes an RGBA8 PNG (w x h, rows from the top) and returns its file name within dir.
std::string writePng(const std::filesystem::path& dir, const std::string& name, int w, int h, const std::vector<uint8_t>& rgba);
// A lossless WebP (libwebp's encoder): texels with non-zero alpha decode exactly.
std::string writeWebp(const std::filesystem::path& dir, const std::string& name, int w, int h, const std::vector<uint8_t>& rgba);

// The one-line error loading `path` gives ("" when it loads); a message of more than one line fails the test.
std::string loadError(const std::string& path, const LoadLimits& limits = {});

}  // namespace vkmc::test
