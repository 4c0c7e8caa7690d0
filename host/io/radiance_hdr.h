// Radiance RGBE (.hdr) decoding, strict and bounded: the header and the size are checked before anything is
// allocated, and every run of the run-length encoding against what is left of its scanline and of the file, so a
// truncated or corrupt file is refused with one line instead of looping or decoding to black (stb_image 2.27, as
// Debian 12 ships it, does both). Reads the format every Radiance writer emits: "#?RADIANCE" or "#?RGBE",
// FORMAT=32-bit_rle_rgbe, the standard orientation "-Y H +X W", and scanlines flat or in the new run-length encoding.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vkmc {

struct RadianceImage {
  uint32_t width = 0, height = 0;
  std::vector<float> rgb;  // width * height * 3, top row first
};

// Throws vkmc::Error naming `name` when the bytes are not a whole, valid Radiance file or hold more than maxTexels.
RadianceImage decodeRadianceHdr(std::string_view bytes, const std::string& name, uint64_t maxTexels);

}  // namespace vkmc
