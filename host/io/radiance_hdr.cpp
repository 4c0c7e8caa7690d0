// Radiance RGBE decoding (see the header).
#include "io/radiance_hdr.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "error.h"

namespace vkmc {
namespace {

constexpr size_t kMaxHeaderBytes = 1 << 16;

struct Reader {
  std::string_view bytes;
  size_t at = 0;
  const std::string& name;
  [[noreturn]] void fail(const std::string& why) const { throw Error("cannot read '" + name + "' as a Radiance .hdr: " + why); }
  size_t left() const { return bytes.size() - at; }
  uint8_t byte(const char* where) {
    if (at >= bytes.size()) fail(std::string("it ends inside ") + where + " (truncated)");
    return uint8_t(bytes[at++]);
  }
  std::string_view line() {  // up to and without the newline
    const size_t end = bytes.find('\n', at);
    if (end == std::string_view::npos || end > kMaxHeaderBytes) fail("its header has no end");
    std::string_view l = bytes.substr(at, end - at);
    at = end + 1;
    return l;
  }
};

void readHeader(Reader& r) {
  std::string_view magic = r.line();
  if (magic.substr(0, 10) != "#?RADIANCE" && magic.substr(0, 6) != "#?RGBE") r.fail("it does not start with #?RADIANCE");
  for (std::string_view l = r.line(); !l.empty(); l = r.line())
    if (l.substr(0, 7) == "FORMAT=" && l != "FORMAT=32-bit_rle_rgbe")
      r.fail("its format is " + std::string(l.substr(7)) + " (vkmc reads 32-bit_rle_rgbe)");
}

void readSize(Reader& r, uint64_t maxTexels, uint32_t& width, uint32_t& height) {
  const std::string l(r.line());
  long long h = 0, w = 0;
  char extra = 0;
  if (std::sscanf(l.c_str(), "-Y %lld +X %lld%c", &h, &w, &extra) != 2)
    r.fail("its resolution line '" + l.substr(0, 40) + "' is not the standard orientation -Y H +X W");
  if (h <= 0 || w <= 0 || h > (1 << 20) || w > (1 << 20))
    r.fail("its size " + std::to_string(w) + "x" + std::to_string(h) + " is impossible");
  if (uint64_t(w) * uint64_t(h) > maxTexels)
    throw Error("'" + r.name + "' is " + std::to_string(w) + "x" + std::to_string(h) + ", more than the " +
                std::to_string(maxTexels) + " texels the device's buffers hold");
  // Even at its best a row takes 4 bytes a texel flat, or its 4-byte header and 2 bytes a 127-texel run of each of
  // its 4 channels run-length encoded.
  const uint64_t leastRowBytes = std::min<uint64_t>(4 * uint64_t(w), 4 + 8 * ((uint64_t(w) + 126) / 127));
  if (uint64_t(h) * leastRowBytes > r.left()) r.fail("it is too short for its size (truncated)");
  width = uint32_t(w), height = uint32_t(h);
}

// One scanline of RGBE texels into `row` (4 bytes a texel).
void readScanline(Reader& r, uint32_t width, uint8_t* row) {
  const bool mayBeRle = width >= 8 && width < 32768 && r.left() >= 4 && uint8_t(r.bytes[r.at]) == 2 &&
                        uint8_t(r.bytes[r.at + 1]) == 2 && (uint8_t(r.bytes[r.at + 2]) & 0x80) == 0;
  if (!mayBeRle) {
    for (uint32_t x = 0; x < 4 * width; ++x) row[x] = r.byte("a flat scanline");
    return;
  }
  r.at += 2;
  const uint32_t declared = uint32_t(r.byte("a scanline header")) << 8 | r.byte("a scanline header");
  if (declared != width)
    r.fail("a scanline declares " + std::to_string(declared) + " texels, the image is " + std::to_string(width) + " wide");
  for (int c = 0; c < 4; ++c)
    for (uint32_t x = 0; x < width;) {
      const uint8_t code = r.byte("a run");
      const uint32_t run = code > 128 ? code - 128u : code;
      if (run == 0 || run > width - x) r.fail("a run of " + std::to_string(run) + " texels overruns its scanline (corrupt)");
      if (code > 128) {
        const uint8_t value = r.byte("a run");
        for (uint32_t k = 0; k < run; ++k) row[4 * (x + k) + c] = value;
      } else {
        for (uint32_t k = 0; k < run; ++k) row[4 * (x + k) + c] = r.byte("a run");
      }
      x += run;
    }
}

}  // namespace

RadianceImage decodeRadianceHdr(std::string_view bytes, const std::string& name, uint64_t maxTexels) {
  Reader r{bytes, 0, name};
  readHeader(r);
  RadianceImage image;
  readSize(r, maxTexels, image.width, image.height);
  image.rgb.resize(size_t(image.width) * image.height * 3);
  std::vector<uint8_t> row(size_t(image.width) * 4);
  for (uint32_t y = 0; y < image.height; ++y) {
    readScanline(r, image.width, row.data());
    float* out = &image.rgb[size_t(y) * image.width * 3];
    for (uint32_t x = 0; x < image.width; ++x) {
      const uint8_t* t = &row[4 * x];
      // The exponent as stb_image and Radiance read it: value = mantissa * 2^(e - 136); e = 0 is black.
      const float f = t[3] == 0 ? 0.0f : std::ldexp(1.0f, int(t[3]) - 136);
      out[3 * x] = t[0] * f, out[3 * x + 1] = t[1] * f, out[3 * x + 2] = t[2] * f;
    }
  }
  return image;
}

}  // namespace vkmc
