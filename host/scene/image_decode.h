// PNG, JPEG and WebP decoding through Debian's maintained libraries (libpng's simplified API, libjpeg-turbo,
// libwebp), and KTX2 through the vendored Basis Universal transcoder (scene/ktx2_decode.h), for glTF textures. The header is read
// first, so a size past the caller's limit is refused before the pixels are allocated; a truncated or corrupt file is refused (a
// libjpeg warning counts: it would fill the rest with grey). stb_image is not used: Debian's 2.27 writes past a Huffman table on
// a crafted JPEG (found by image_fuzzer).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace vkmc {

enum class ImageFormat { Png, Jpeg, WebP, Ktx2, Other };
ImageFormat imageFormatOf(const unsigned char* bytes, size_t size);  // by the file's signature

struct DecodedImage {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> rgba;  // width * height * 4, top row first
};

// Throws vkmc::Error when an image of this size has no pixels, a side past maxSide or more than maxTexels texels.
void checkImageSize(uint32_t width, uint32_t height, uint32_t maxSide, uint64_t maxTexels);

// Throws vkmc::Error with the reason (not naming the image: the caller does) when the bytes are not a whole PNG,
// JPEG, still WebP or single-image KTX2, or when a side exceeds maxSide or the texels exceed maxTexels.
DecodedImage decodeImage(const unsigned char* bytes, size_t size, uint32_t maxSide, uint64_t maxTexels);

}  // namespace vkmc
