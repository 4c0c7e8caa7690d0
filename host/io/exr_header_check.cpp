#include "io/exr_header_check.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string_view>

#include "error.h"

namespace vkmc {
namespace {

// The attribute types OpenEXR 3.1 reads by their own length, whatever size the file declares.
struct FixedType {
  std::string_view name;
  size_t bytes;
};
constexpr FixedType kFixedTypes[] = {
    {"box2i", 16},   {"box2f", 16},   {"chromaticities", 32}, {"compression", 1}, {"double", 8}, {"envmap", 1}, {"float", 4},
    {"int", 4},      {"keycode", 28}, {"lineOrder", 1},       {"m33f", 36},       {"m33d", 72},  {"m44f", 64},  {"m44d", 128},
    {"rational", 8}, {"tiledesc", 9}, {"timecode", 8},        {"v2i", 8},         {"v2f", 8},    {"v2d", 16},   {"v3i", 12},
    {"v3f", 12},     {"v3d", 24},     {"deepImageState", 1}};

class HeaderWalk {
 public:
  HeaderWalk(const std::string& bytes, const std::string& name, uint64_t maxValues)
      : b_(bytes), name_(name), maxValues_(maxValues) {}

  void run() {
    if (b_.size() < 8 || b_.compare(0, 4, "\x76\x2f\x31\x01") != 0) return;
    const uint32_t version = uint32At(4);
    longestName_ = (version & 0x400) ? 256 : 32;  // the long-names flag
    at_ = 8;
    header(true);
    if (version & 0x1000)  // multipart: headers follow one another; an empty header ends the list
      while (at_ < b_.size() && b_[at_] != '\0') header(false);
  }

 private:
  Error fail(const std::string& why) const { return Error("cannot read EXR '" + name_ + "': " + why); }
  uint32_t uint32At(size_t at) const {
    if (at > b_.size() || b_.size() - at < 4) throw fail("its header is truncated");
    uint32_t v;
    std::memcpy(&v, b_.data() + at, 4);
    return v;
  }
  // A NUL-terminated name of fewer than `longest` bytes (attribute and type names: 32, or 256 with the long-names
  // flag; channel names: 256).
  std::string text(size_t longest) {
    const size_t nul = b_.find('\0', at_);
    if (nul == std::string::npos || nul - at_ >= longest) throw fail("its header has a malformed name");
    std::string s = b_.substr(at_, nul - at_);
    at_ = nul + 1;
    return s;
  }

  // One header's attributes, up to an empty name. The first part's data window and tiles (what vkmc reads), each
  // times its channels, are checked against the limit; the other parts' attributes are walked.
  void header(bool first) {
    std::optional<std::array<int32_t, 4>> window;
    std::optional<std::array<uint32_t, 2>> tile;
    channels_ = 0;
    for (std::string attribute = text(longestName_); !attribute.empty(); attribute = text(longestName_)) {
      const std::string type = text(longestName_);
      const uint32_t declared = uint32At(at_);
      at_ += 4;
      const uint64_t bytes = valueBytes(type, declared);
      if (bytes > b_.size() - at_)
        throw fail("its header's attribute '" + attribute + "' declares " + std::to_string(bytes) +
                   " bytes, past the file's end");
      if (type == "box2i" && attribute == "dataWindow")
        window = std::array<int32_t, 4>{int32_t(uint32At(at_)), int32_t(uint32At(at_ + 4)), int32_t(uint32At(at_ + 8)),
                                        int32_t(uint32At(at_ + 12))};
      if (type == "tiledesc") tile = std::array<uint32_t, 2>{uint32At(at_), uint32At(at_ + 4)};
      at_ += bytes;
    }
    if (!first) return;
    if (window)
      checkExrDeclaredSize(int64_t((*window)[2]) - (*window)[0] + 1, int64_t((*window)[3]) - (*window)[1] + 1, channels_,
                           maxValues_, name_);
    if (tile) checkExrDeclaredSize((*tile)[0], (*tile)[1], channels_, maxValues_, name_);  // a tile buffer a channel
  }

  // The bytes OpenEXR reads for a value of `type` at at_ (counting a channel list's channels).
  uint64_t valueBytes(const std::string& type, uint32_t declared) {
    for (const FixedType& f : kFixedTypes)
      if (type == f.name) return f.bytes;
    if (type == "chlist") {  // channel names, each followed by 16 bytes, up to an empty name
      const size_t start = at_;
      for (std::string channel = text(256); !channel.empty(); channel = text(256), ++channels_) at_ += 16;
      const size_t end = at_;
      at_ = start;
      return end - start;
    }
    if (type == "preview") {  // width, height, then 4 bytes a pixel (saturated: past the file's end either way)
      const uint64_t pixels = uint64_t(uint32At(at_)) * uint32At(at_ + 4);
      return pixels > (UINT64_MAX - 8) / 4 ? UINT64_MAX : 8 + 4 * pixels;
    }
    if (int32_t(declared) < 0) throw fail("its header declares a negative size for a " + type);
    return declared;  // strings, vectors, opaque types: their declared size
  }

  const std::string& b_;
  const std::string& name_;
  const uint64_t maxValues_;
  size_t longestName_ = 32, at_ = 0;
  uint64_t channels_ = 0;
};

}  // namespace

void checkExrDeclaredSize(int64_t width, int64_t height, uint64_t channels, uint64_t maxValues, const std::string& name) {
  if (width <= 0 || height <= 0 || uint64_t(width) * uint64_t(height) * std::max<uint64_t>(channels, 1) > maxValues)
    throw Error("cannot read EXR '" + name + "': it declares " + std::to_string(width) + "x" + std::to_string(height) +
                " pixels of " + std::to_string(channels) + " channels, more than the " + std::to_string(maxValues) +
                " values vkmc reads");
}

void checkExrHeaders(const std::string& bytes, const std::string& name, uint64_t maxValues) {
  HeaderWalk(bytes, name, maxValues).run();
}

}  // namespace vkmc
