// KTX2 decoding through the Basis Universal transcoder (see the header).
#include "scene/ktx2_decode.h"

#include <basisu_transcoder.h>

#include <algorithm>
#include <cstring>
#include <mutex>
#include <string>

#include "error.h"

namespace vkmc {
namespace {

constexpr unsigned char kKtx2Identifier[12] = {0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n'};

uint64_t readLittleEndian(const unsigned char* at, int bytes) {
  uint64_t value = 0;
  for (int i = bytes - 1; i >= 0; --i) value = value << 8 | at[i];
  return value;
}

// The transcoder reads the header's 64-bit offsets and lengths through a uint32_t conversion, so its own bounds
// checks can pass a forged offset past 4 GiB that wraps (image_fuzzer found one: the supercompression data read
// from 4 GiB before the file). Every region the header and level index name is checked here first, in 64 bits; a
// file under 1 GiB then leaves no sum for the transcoder's 32 bits to wrap.
void checkRegions(const unsigned char* bytes, size_t size) {
  constexpr size_t kHeaderBytes = 80, kLevelEntryBytes = 24;
  if (size < kHeaderBytes) throw Error("a truncated KTX2 (" + std::to_string(size) + " bytes, shorter than its header)");
  if (size > (size_t(1) << 30)) throw Error("a KTX2 over 1 GiB");
  const auto inside = [size](uint64_t offset, uint64_t length) { return offset <= size && length <= size - offset; };
  if (readLittleEndian(bytes + 28, 4) > 0) throw Error("a KTX2 volume (a texture is one 2D image)");
  const uint64_t levels = std::max<uint64_t>(1, readLittleEndian(bytes + 40, 4));
  if (levels > 32) throw Error("a corrupt KTX2 (" + std::to_string(levels) + " mip levels; a 2D image has at most 32)");
  if (!inside(kHeaderBytes, levels * kLevelEntryBytes))
    throw Error("a corrupt KTX2 (its level index lies past the end of the file)");
  const struct {
    const char* name;
    uint64_t offset, length;
  } regions[] = {{"data format descriptor", readLittleEndian(bytes + 48, 4), readLittleEndian(bytes + 52, 4)},
                 {"key/value data", readLittleEndian(bytes + 56, 4), readLittleEndian(bytes + 60, 4)},
                 {"supercompression data", readLittleEndian(bytes + 64, 8), readLittleEndian(bytes + 72, 8)}};
  for (const auto& region : regions)
    if (!inside(region.offset, region.length))
      throw Error(std::string("a corrupt KTX2 (its ") + region.name + " lies past the end of the file)");
  for (uint64_t level = 0; level < levels; ++level) {
    const unsigned char* entry = bytes + kHeaderBytes + level * kLevelEntryBytes;
    if (!inside(readLittleEndian(entry, 8), readLittleEndian(entry + 8, 8)) || readLittleEndian(entry + 16, 8) > UINT32_MAX)
      throw Error("a corrupt KTX2 (mip level " + std::to_string(level) + " lies past the end of the file)");
  }
}

void initialiseTranscoderOnce() {
  static std::once_flag once;
  std::call_once(once, [] { basist::basisu_transcoder_init(); });
}

void checkShape(const basist::ktx2_transcoder& file, uint32_t maxSide, uint64_t maxTexels) {
  const uint32_t width = file.get_width(), height = file.get_height();
  if (file.get_layers() > 1) throw Error("a KTX2 array of " + std::to_string(file.get_layers()) + " images (a texture is one)");
  if (file.get_faces() != 1) throw Error("a KTX2 cube map (a texture is one 2D image)");
  checkImageSize(width, height, maxSide, maxTexels);
  // ETC1S data comes in BasisLZ and nothing else; UASTC raw or in Zstandard. Zstandard's output is allocated at the
  // size the level index declares (the transcoder allows up to 2 GiB, and inflates a level before it reads its
  // format): one that is not the UASTC blocks of an image this size is refused before a forged length allocates it.
  const uint32_t scheme = file.get_header().m_supercompression_scheme;
  if (file.is_etc1s() != (scheme == basist::KTX2_SS_BASISLZ))
    throw Error(std::string("a corrupt KTX2 (") + (file.is_etc1s() ? "ETC1S" : "UASTC") + " data in supercompression scheme " +
                std::to_string(scheme) + ")");
  if (scheme == basist::KTX2_SS_ZSTANDARD) {
    const uint64_t blocks = uint64_t((width + 3) / 4) * ((height + 3) / 4);
    const uint64_t declared = file.get_level_index()[0].m_uncompressed_byte_length;
    if (declared != blocks * 16)
      throw Error("a corrupt KTX2: its first level declares " + std::to_string(declared) + " bytes, where a " +
                  std::to_string(width) + "x" + std::to_string(height) + " UASTC image has " + std::to_string(blocks * 16));
  }
}

}  // namespace

bool isKtx2(const unsigned char* bytes, size_t size) {
  return size >= sizeof(kKtx2Identifier) && std::memcmp(bytes, kKtx2Identifier, sizeof(kKtx2Identifier)) == 0;
}

DecodedImage decodeKtx2(const unsigned char* bytes, size_t size, uint32_t maxSide, uint64_t maxTexels) {
  initialiseTranscoderOnce();
  checkRegions(bytes, size);
  basist::ktx2_transcoder file;
  if (!file.init(bytes, uint32_t(size)))
    throw Error(
        "not a KTX2 of Basis Universal data vkmc can read (its header, level index or data format is invalid, or "
        "it holds uncompressed texels)");
  checkShape(file, maxSide, maxTexels);
  if (!file.start_transcoding()) throw Error("a corrupt KTX2 (its supercompression data does not decode)");
  DecodedImage out;
  out.width = file.get_width(), out.height = file.get_height();
  out.rgba.resize(size_t(out.width) * out.height * 4);
  if (!file.transcode_image_level(0, 0, 0, out.rgba.data(), out.width * out.height, basist::transcoder_texture_format::cTFRGBA32))
    throw Error(std::string("a corrupt or truncated KTX2 (its ") + (file.is_uastc() ? "UASTC" : "ETC1S") +
                " data does not transcode)");
  return out;
}

}  // namespace vkmc
