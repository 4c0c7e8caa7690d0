// KHR_draco_mesh_compression and EXT_meshopt_compression: a pass between tinygltf's parse and flattening that
// rewrites the model in place so the rest of the loader sees plain buffers, views and accessors.
#pragma once
#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vkmc {

struct DecompressLimits {
  uint64_t maxDecodedBytes = uint64_t(1) << 31;  // all decoded data together
  uint64_t maxTriangles = uint64_t(1) << 25;     // per Draco primitive
};

// Decodes every meshopt-compressed buffer view into a new buffer the view then points to, and every Draco
// primitive into new buffers, views and accessors that replace its attributes and indices. Throws vkmc::Error
// naming the extension, e.g. "KHR_draco_mesh_compression: primitive 0 of mesh 2: ...". Limits: meshopt output is
// sized from the file's count x byteStride and refused before allocation past maxDecodedBytes; libdraco allocates
// what its bitstream declares while decoding, so Draco's limits apply to what it returns.
void decompressModel(tinygltf::Model& model, const DecompressLimits& limits);

// What tinygltf 2.7 would refuse in compressed files, rewritten before it parses them: EXT_meshopt_compression's
// fallback buffers without uri (no data; a .gltf buffer needs a uri and a GLB's uri-less buffer is its BIN chunk)
// get a 1-byte data URI, and Draco primitives lose their `indices` (an accessor without a buffer view, which
// tinygltf refuses; decoding replaces them). Returns the rewritten JSON, or "" when nothing needed it. `json` has
// passed scanGltfJson.
std::string prepareCompressedJson(std::string_view json);

}  // namespace vkmc
