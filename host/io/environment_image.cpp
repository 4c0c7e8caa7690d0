// Environment map reading: .hdr through io/radiance_hdr, .exr through io/exr, each size-checked before it allocates.
#include "io/environment_image.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>

#include "error.h"
#include "io/exr.h"
#include "io/radiance_hdr.h"

namespace vkmc {

namespace {

std::string readBytes(const std::string& path, uint64_t maxBytes) {
  std::error_code ec;
  const uint64_t size = std::filesystem::file_size(path, ec);
  if (ec) throw Error("--environment: cannot open '" + path + "'");
  if (size > maxBytes) throw Error("--environment: '" + path + "' is larger than any map vkmc can hold");
  std::ifstream in(path, std::ios::binary);
  std::string bytes(size, '\0');
  if (!in.read(bytes.data(), std::streamsize(size))) throw Error("--environment: cannot read '" + path + "'");
  return bytes;
}

}  // namespace

EnvironmentMap readEnvironmentMap(const std::string& path, float rotationDegrees, float strength, uint64_t maxTexels) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (!std::filesystem::is_regular_file(path)) throw Error("--environment: cannot open '" + path + "'");
  EnvironmentMap map;
  map.source = path;
  map.rotationDegrees = rotationDegrees;
  if (ext == ".hdr") {
    RadianceImage image;
    try {
      // A flat file holds 4 bytes a texel; a header is under 64 KiB.
      image = decodeRadianceHdr(readBytes(path, 4 * maxTexels + (1 << 16)), path, maxTexels);
    } catch (const Error& e) {
      throw Error(std::string("--environment: ") + e.what());
    }
    map.width = image.width, map.height = image.height;
    map.radiance.resize(size_t(image.width) * image.height);
    for (size_t i = 0; i < map.radiance.size(); ++i)
      map.radiance[i] = glm::vec3(image.rgb[3 * i], image.rgb[3 * i + 1], image.rgb[3 * i + 2]);
  } else if (ext == ".exr") {
    ExrImage image;
    try {
      image = readExr(path, 3 * maxTexels);  // R, G, B; a file with more channels must be smaller
    } catch (const Error& e) {
      throw Error(std::string("--environment: ") + e.what());
    }
    for (const char* c : {"R", "G", "B"})
      if (!image.channels.count(c)) throw Error("--environment: '" + path + "' has no " + c + " channel");
    map.width = uint32_t(image.width), map.height = uint32_t(image.height);
    map.radiance.resize(size_t(image.width) * size_t(image.height));
    for (size_t i = 0; i < map.radiance.size(); ++i)
      map.radiance[i] = glm::vec3(image.channels["R"][i], image.channels["G"][i], image.channels["B"][i]);
  } else {
    throw Error("--environment: '" + path + "' is neither .hdr nor .exr");
  }
  if (map.width == 0 || map.height == 0) throw Error("--environment: '" + path + "' is empty");
  for (size_t i = 0; i < map.radiance.size(); ++i) {
    glm::vec3 L = map.radiance[i] * strength;
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(L[c]) || L[c] < 0.0f)
        throw Error("--environment: '" + path + "' pixel (" + std::to_string(i % map.width) + ", " +
                    std::to_string(i / map.width) + ") is negative or not finite (times the strength)");
    map.radiance[i] = L;
  }
  return map;
}

}  // namespace vkmc
