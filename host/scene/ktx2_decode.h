// KTX2 textures (KHR_texture_basisu): Basis Universal's ETC1S or UASTC payloads, supercompressed with BasisLZ or
// Zstandard, transcoded on load to 8-bit RGBA through the vendored Basis Universal transcoder
// (third_party/basisu: Debian packages none). Only the first mip level is read: vkmc filters its own textures.
#pragma once
#include <cstddef>
#include <cstdint>

#include "scene/image_decode.h"

namespace vkmc {

bool isKtx2(const unsigned char* bytes, size_t size);  // by the KTX 2.0 file identifier

// Throws vkmc::Error with the reason (not naming the image: the caller does) when the bytes are not a whole KTX2
// of Basis Universal data, hold more than one 2D image (an array, a cube map, a volume), or exceed maxSide a side or
// maxTexels in all.
DecodedImage decodeKtx2(const unsigned char* bytes, size_t size, uint32_t maxSide, uint64_t maxTexels);

}  // namespace vkmc
