// Environment map reading: .hdr through stb_image's float loader, .exr through io/exr.
#include "io/environment_image.h"

#include <cmath>
#include <filesystem>
#include <memory>

#include "error.h"
#include "io/exr.h"

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_HDR
#include <stb/stb_image.h>

namespace vkmc {

EnvironmentMap readEnvironmentMap(const std::string& path, float rotationDegrees, float strength) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (!std::filesystem::is_regular_file(path)) throw Error("--environment: cannot open '" + path + "'");
  EnvironmentMap map;
  map.source = path;
  map.rotationDegrees = rotationDegrees;
  if (ext == ".hdr") {
    int w = 0, h = 0, channels = 0;
    std::unique_ptr<float, void (*)(void*)> pixels(stbi_loadf(path.c_str(), &w, &h, &channels, 3), stbi_image_free);
    if (!pixels) throw Error("--environment: cannot read '" + path + "': " + stbi_failure_reason());
    map.width = uint32_t(w), map.height = uint32_t(h);
    map.radiance.resize(size_t(w) * size_t(h));
    for (size_t i = 0; i < map.radiance.size(); ++i)
      map.radiance[i] = glm::vec3(pixels.get()[3 * i], pixels.get()[3 * i + 1], pixels.get()[3 * i + 2]);
  } else if (ext == ".exr") {
    ExrImage image;
    try {
      image = readExr(path);
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
