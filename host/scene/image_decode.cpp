// PNG, JPEG, WebP and KTX2 decoding (see the header).
#include "scene/image_decode.h"

#include <png.h>
#include <webp/decode.h>
// clang-format off
#include <cstdio>  // jpeglib.h needs FILE and size_t first
#include <jpeglib.h>
// clang-format on
#include <algorithm>
#include <climits>
#include <csetjmp>
#include <cstring>
#include <string>

#include "error.h"
#include "scene/ktx2_decode.h"

namespace vkmc {

void checkImageSize(uint32_t width, uint32_t height, uint32_t maxSide, uint64_t maxTexels) {
  if (width == 0 || height == 0) throw Error("it has no pixels");
  if (width > maxSide || height > maxSide)
    throw Error(std::to_string(width) + "x" + std::to_string(height) + " exceeds " + std::to_string(maxSide) + " texels a side");
  if (uint64_t(width) * height > maxTexels)
    throw Error(std::to_string(width) + "x" + std::to_string(height) + " exceeds the " + std::to_string(maxTexels) +
                " texels left to the scene's images");
}

namespace {

DecodedImage decodePng(const unsigned char* bytes, size_t size, uint32_t maxSide, uint64_t maxTexels) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, bytes, size)) throw Error(std::string("not a valid PNG: ") + image.message);
  try {
    checkImageSize(image.width, image.height, maxSide, maxTexels);
  } catch (...) {
    png_image_free(&image);
    throw;
  }
  image.format = PNG_FORMAT_RGBA;
  DecodedImage out;
  out.width = image.width, out.height = image.height;
  try {
    out.rgba.resize(PNG_IMAGE_SIZE(image));
  } catch (...) {
    png_image_free(&image);  // finish_read frees it on every path; an allocation that fails before it must too
    throw;
  }
  if (!png_image_finish_read(&image, nullptr, out.rgba.data(), 0, nullptr))
    throw Error(std::string("a corrupt or truncated PNG: ") + image.message);
  return out;
}

struct JpegErrors {
  jpeg_error_mgr manager;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

extern "C" void jpegFailed(j_common_ptr info) {
  auto* errors = reinterpret_cast<JpegErrors*>(info->err);
  (*info->err->format_message)(info, errors->message);
  std::longjmp(errors->jump, 1);
}
extern "C" void jpegQuiet(j_common_ptr, int) {}  // warnings are counted (num_warnings), not printed

// Only plain C objects live in this frame, so libjpeg's longjmp back to it skips no destructor.
bool decodeJpegInto(const unsigned char* bytes, size_t size, uint32_t maxSide, uint64_t maxTexels, DecodedImage* out,
                    std::string* why) {
  jpeg_decompress_struct info;
  JpegErrors errors;
  info.err = jpeg_std_error(&errors.manager);
  errors.manager.error_exit = jpegFailed;
  errors.manager.emit_message = jpegQuiet;
  errors.message[0] = '\0';
  if (setjmp(errors.jump)) {
    jpeg_destroy_decompress(&info);
    *why = std::string("a corrupt JPEG: ") + errors.message;
    return false;
  }
  jpeg_create_decompress(&info);
  jpeg_mem_src(&info, bytes, (unsigned long)size);
  jpeg_read_header(&info, TRUE);
  if (info.image_width == 0 || info.image_height == 0 || info.image_width > maxSide || info.image_height > maxSide ||
      uint64_t(info.image_width) * info.image_height > maxTexels) {
    out->width = info.image_width, out->height = info.image_height;  // the caller names the size
    jpeg_destroy_decompress(&info);
    return false;
  }
  // libjpeg's own working memory (a progressive image's coefficients: 2 bytes a sample of each component, blocks
  // padded to 16) bounded by what an image of this size needs: past it the decode fails (jmemnobs has no backing
  // store) instead of allocating what a forged header asks.
  const uint64_t working =
      2 * uint64_t(info.num_components) * (uint64_t(info.image_width) + 16) * (uint64_t(info.image_height) + 16) +
      (uint64_t(64) << 20);
  info.mem->max_memory_to_use = long(std::min<uint64_t>(working, uint64_t(LONG_MAX)));
  info.out_color_space = JCS_EXT_RGBA;
  jpeg_start_decompress(&info);
  out->width = info.output_width, out->height = info.output_height;
  out->rgba.resize(size_t(out->width) * out->height * 4);
  while (info.output_scanline < info.output_height) {
    JSAMPROW row = out->rgba.data() + size_t(info.output_scanline) * out->width * 4;
    jpeg_read_scanlines(&info, &row, 1);
  }
  jpeg_finish_decompress(&info);
  const long warnings = errors.manager.num_warnings;
  jpeg_destroy_decompress(&info);
  if (warnings > 0) *why = "a corrupt or truncated JPEG (libjpeg warned of its data)";
  return warnings == 0;
}

DecodedImage decodeWebp(const unsigned char* bytes, size_t size, uint32_t maxSide, uint64_t maxTexels) {
  WebPBitstreamFeatures features;
  if (WebPGetFeatures(bytes, size, &features) != VP8_STATUS_OK) throw Error("not a valid WebP (its header is malformed)");
  if (features.has_animation) throw Error("an animated WebP (a texture is one still image)");
  checkImageSize(uint32_t(features.width), uint32_t(features.height), maxSide, maxTexels);
  DecodedImage out;
  out.width = uint32_t(features.width), out.height = uint32_t(features.height);
  out.rgba.resize(size_t(out.width) * out.height * 4);
  if (!WebPDecodeRGBAInto(bytes, size, out.rgba.data(), out.rgba.size(), int(out.width) * 4))
    throw Error("a corrupt or truncated WebP");
  return out;
}

}  // namespace

ImageFormat imageFormatOf(const unsigned char* bytes, size_t size) {
  if (size >= 8 && std::memcmp(bytes, "\x89PNG\r\n\x1a\n", 8) == 0) return ImageFormat::Png;
  if (size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF) return ImageFormat::Jpeg;
  if (size >= 12 && std::memcmp(bytes, "RIFF", 4) == 0 && std::memcmp(bytes + 8, "WEBP", 4) == 0) return ImageFormat::WebP;
  if (isKtx2(bytes, size)) return ImageFormat::Ktx2;
  return ImageFormat::Other;
}

DecodedImage decodeImage(const unsigned char* bytes, size_t size, uint32_t maxSide, uint64_t maxTexels) {
  switch (imageFormatOf(bytes, size)) {
    case ImageFormat::Png: return decodePng(bytes, size, maxSide, maxTexels);
    case ImageFormat::Jpeg: {
      DecodedImage out;
      std::string why;
      if (decodeJpegInto(bytes, size, maxSide, maxTexels, &out, &why)) return out;
      if (why.empty()) checkImageSize(out.width, out.height, maxSide, maxTexels);  // refused by its size: say which
      throw Error(why);
    }
    case ImageFormat::WebP: return decodeWebp(bytes, size, maxSide, maxTexels);
    case ImageFormat::Ktx2: return decodeKtx2(bytes, size, maxSide, maxTexels);
    case ImageFormat::Other: break;
  }
  throw Error("not PNG, JPEG, WebP or KTX2 (the image formats vkmc reads)");
}

}  // namespace vkmc
