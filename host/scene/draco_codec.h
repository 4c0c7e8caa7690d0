// Draco mesh decoding (and encoding, for tests) behind plain types, built as a shared library of its own
// (vkmc_draco): Debian's libdraco bundles an older tinygltf whose symbols must never meet libtinygltf's, so libdraco
// is linked statically into this library alone and none of its symbols are exported.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace vkmc {

struct DracoAttributeRequest {
  uint32_t uniqueId = 0;  // the id the glTF extension's attribute mapping gives
  int components = 0;     // 1..4, from the glTF accessor's type
};

struct DracoDecoded {
  std::string error;                           // empty on success
  uint32_t points = 0;                         // vertices
  std::vector<uint32_t> indices;               // 3 per triangle, each < points
  std::vector<std::vector<float>> attributes;  // per request, points x components floats (normalized as Draco says)
};

// Refuses meshes of more than maxTriangles triangles or more than maxBytes of decoded attributes and indices.
__attribute__((visibility("default"))) DracoDecoded decodeDracoMesh(const unsigned char* data, size_t size,
                                                                    const std::vector<DracoAttributeRequest>& requests,
                                                                    uint64_t maxTriangles, uint64_t maxBytes);

// For tests: xyz positions, optional uv texture coordinates (empty: none) and triangle indices, quantized to `bits`;
// sequential encoding keeps the face order, edgebreaker does not. Returns the bytes and the attributes' unique ids.
struct DracoEncoded {
  std::vector<char> bytes;
  uint32_t positionId = 0, uvId = 0;
};
__attribute__((visibility("default"))) DracoEncoded encodeDracoMesh(const std::vector<float>& positions,
                                                                    const std::vector<float>& uvs,
                                                                    const std::vector<uint32_t>& indices, int bits,
                                                                    bool sequential);

}  // namespace vkmc
