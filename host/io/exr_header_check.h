// A walk over an OpenEXR file's headers before OpenEXR reads it. OpenEXR allocates from what a header declares
// before it reads the pixels (an opaque or string attribute's size, a preview's pixels, line or tile buffers for
// the data window), so a few forged bytes could claim gigabytes. The walk reads each attribute as OpenEXR 3.1
// does (known types by their own length, others by their declared size) and refuses, with one line naming the
// file: an attribute or preview that runs past the file's end, a data window or tile of more than maxValues
// values. Bytes without the EXR magic are left to OpenEXR to refuse.
#pragma once
#include <cstdint>
#include <string>

namespace vkmc {

void checkExrHeaders(const std::string& bytes, const std::string& name, uint64_t maxValues);

// Refuses an image of more than maxValues values (pixels times channels), or of no pixels, from its declared size.
void checkExrDeclaredSize(int64_t width, int64_t height, uint64_t channels, uint64_t maxValues, const std::string& name);

}  // namespace vkmc
