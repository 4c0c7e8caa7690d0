// PNG preview through libpng's simplified API, written atomically.
#include "io/png.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "error.h"
#include "io/exr.h"

namespace vkmc {
namespace {
uint8_t toSrgb8(double linear) {
  double v = std::clamp(std::isfinite(linear) ? linear : 0.0, 0.0, 1.0);
  v = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  return static_cast<uint8_t>(std::lround(v * 255.0));
}
}  // namespace

void writeFilmPng(const std::string& path, const Film& film, float exposureStops) {
  double scale = std::exp2(static_cast<double>(exposureStops));
  std::vector<uint8_t> rgb(film.pixels() * 3);
  for (size_t p = 0; p < film.pixels(); ++p)
    for (int c = 0; c < 3; ++c) rgb[3 * p + c] = toSrgb8(film.mean(p, c) * scale);
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = film.width;
  image.height = film.height;
  image.format = PNG_FORMAT_RGB;
  std::string tmp = temporaryPathFor(path);
  if (!png_image_write_to_file(&image, tmp.c_str(), 0, rgb.data(), 0, nullptr)) {
    std::remove(tmp.c_str());
    throw Error("cannot write PNG '" + path + "': " + image.message);
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw Error("cannot write '" + path + "': " + ec.message());
  }
}

}  // namespace vkmc
