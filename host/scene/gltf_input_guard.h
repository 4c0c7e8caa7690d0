// Checks on untrusted glTF input before tinygltf sees it: files are opened without blocking and read only when
// they are regular and of plausible size, GLB containers are validated chunk by chunk, and JSON is scanned for
// nesting depth and value count (tinygltf's JSON-to-Value conversion recurses, and a few MB of numbers cost GBs).
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vkmc {

struct InputLimits {
  uint64_t maxSceneFileBytes = uint64_t(1) << 31;     // a .gltf or .glb
  uint64_t maxExternalFileBytes = uint64_t(1) << 31;  // a buffer or image URI
  uint32_t maxJsonDepth = 64;                         // glTF itself needs about 8
  uint64_t maxJsonValues = uint64_t(1) << 23;         // ~1 GB of parsed values at most
};

// The bytes of a regular file no larger than maxBytes; `what` names it in the one-line error otherwise (a FIFO,
// a folder or a device is refused without blocking).
std::vector<unsigned char> readRegularFile(const std::string& path, uint64_t maxBytes, const std::string& what);

// The JSON chunk of a GLB container whose header, chunk lengths and alignment are consistent with its size.
std::string_view glbJsonChunk(const std::vector<unsigned char>& glb);

// The same GLB container with its JSON chunk replaced by `json` (padded with spaces) and its BIN chunk kept.
// `glb` has passed glbJsonChunk.
std::vector<unsigned char> replaceGlbJson(const std::vector<unsigned char>& glb, std::string json);

// What the loader needs to know before tinygltf parses the file.
struct GltfJsonFacts {
  uint64_t largestBuffer = 0;  // the largest declared buffers[].byteLength
  std::vector<std::string> extensionsUsed, extensionsRequired;
  std::vector<std::string> externalUris;  // buffers' and images' uris that name files (not data: uris), as written
};

// Throws vkmc::Error when JSON text is malformed, nested deeper than limits.maxJsonDepth or holds more than
// limits.maxJsonValues values: checked by a scan that keeps nothing, before anything parses it (a parsed value's
// copies and dumps recurse as deep as it nests).
void checkJsonBounds(std::string_view json, const InputLimits& limits);

// Throws vkmc::Error when the JSON is malformed, nested deeper than limits.maxJsonDepth or holds more than
// limits.maxJsonValues values, or when a bufferView lies outside its buffer's declared length (before anything
// reads one: tinygltf decodes images from bufferViews unchecked).
GltfJsonFacts scanGltfJson(std::string_view json, const InputLimits& limits);

}  // namespace vkmc
