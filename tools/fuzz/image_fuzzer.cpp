// libFuzzer entry: any bytes as a glTF image (scene/gltf_textures decodeGltfImage: the PNG and JPEG signatures,
// the size checks, then libpng or libjpeg-turbo). It never throws: an image it cannot read is named in its failures.
#include <tiny_gltf.h>

#include <cstdint>

#include "cpu_timeout.h"
#include "scene/gltf_textures.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vkmc::fuzz::CpuTimeout timeout;
  vkmc::ImageDecoder decoder;
  // Small limits: an image past them is refused from its header (the check under test), and the ones decoded stay
  // fast enough for a million inputs.
  decoder.limits.maxDimension = 1024;
  decoder.limits.maxTotalTexels = 1u << 18;
  tinygltf::Image image;
  std::string err, warn;
  vkmc::decodeGltfImage(&image, 0, &err, &warn, 0, 0, data, int(size), &decoder);
  return 0;
}
