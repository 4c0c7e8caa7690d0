// PNG preview through libpng's simplified API, written atomically.
#include "io/png.h"

#include <png.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "error.h"
#include "io/exr.h"
#include "io/output_files.h"
#include "io/tone_map.h"

#include <stb/stb_easy_font.h>

namespace vkmc {
namespace {
std::string encodeRgbPng(const std::vector<uint8_t>& rgb, uint32_t width, uint32_t height) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = width;
  image.height = height;
  image.format = PNG_FORMAT_RGB;
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&image, nullptr, &size, 0, rgb.data(), 0, nullptr))
    throw Error(std::string("cannot encode PNG: ") + image.message);
  std::string bytes(size, '\0');
  if (!png_image_write_to_memory(&image, bytes.data(), &size, 0, rgb.data(), 0, nullptr))
    throw Error(std::string("cannot encode PNG: ") + image.message);
  bytes.resize(size);
  return bytes;
}

// Draws text with stb_easy_font (axis-aligned quads) in black, scaled by `scale`, at (x, y).
void drawText(std::vector<uint8_t>& rgb, uint32_t width, uint32_t height, int x, int y, const std::string& text, int scale) {
  static char buffer[99999];
  int quads = stb_easy_font_print(0, 0, const_cast<char*>(text.c_str()), nullptr, buffer, sizeof(buffer));
  const float* v = reinterpret_cast<const float*>(buffer);
  for (int q = 0; q < quads; ++q) {
    const float* quad = v + q * 16;  // 4 vertices of (x, y, z, color)
    int x0 = int(quad[0]), y0 = int(quad[1]), x1 = int(quad[8]), y1 = int(quad[9]);
    for (int yy = y0 * scale; yy < y1 * scale; ++yy)
      for (int xx = x0 * scale; xx < x1 * scale; ++xx) {
        int px = x + xx, py = y + yy;
        if (px < 0 || py < 0 || px >= int(width) || py >= int(height)) continue;
        for (int c = 0; c < 3; ++c) rgb[3 * (size_t(py) * width + px) + c] = 0;
      }
  }
}
}  // namespace

void writeContactSheet(const std::string& path, const std::vector<ExrImage>& images, const std::vector<std::string>& labels,
                       float exposureStops) {
  writeFileAtomically(path, encodeContactSheet(images, labels, exposureStops));
}

std::string encodeContactSheet(const std::vector<ExrImage>& images, const std::vector<std::string>& labels, float exposureStops) {
  if (images.empty()) throw Error("no images for the contact sheet");
  // Small renders are enlarged (nearest neighbour) so that a label fits above each.
  const uint32_t zoom = std::max(1u, (160u + images[0].width - 1) / images[0].width);
  const uint32_t srcW = images[0].width;
  const uint32_t w = srcW * zoom, h = images[0].height * zoom, labelHeight = 24, gap = 4;
  const uint32_t width = uint32_t(images.size()) * (w + gap) - gap, height = h + labelHeight;
  std::vector<uint8_t> rgb(size_t(width) * height * 3, 255);
  const char* names[] = {"R", "G", "B"};
  for (size_t k = 0; k < images.size(); ++k) {
    uint32_t x0 = uint32_t(k) * (w + gap);
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x) {
        std::array<double, 3> v{};
        for (int c = 0; c < 3; ++c) {
          auto it = images[k].channels.find(names[c]);
          v[c] = it == images[k].channels.end() ? 0.0 : it->second[size_t(y / zoom) * srcW + x / zoom];
        }
        const std::array<uint8_t, 3> out = previewPixel(v, exposureStops, ToneMap::Neutral);
        std::copy(out.begin(), out.end(), rgb.begin() + 3 * (size_t(y + labelHeight) * width + x0 + x));
      }
    drawText(rgb, width, height, int(x0) + 2, 4, k < labels.size() ? labels[k] : "", w >= 320 ? 2 : 1);
  }
  return encodeRgbPng(rgb, width, height);
}

namespace {
// A pixel every sample of which escaped to the backdrop: the backdrop's grey in every channel, with no variance but
// the device's float sums' rounding (a batch adds up to 64 samples in float: a relative 1e-6 or so in the mean,
// and a variance of the mean near 1e-8 b^2 from the sum of squares' cancellation). The tolerances are far above
// that and far below a shaded pixel's noise. With a pixel filter whose weights are not all 1 the mean is the grey
// times their mean, and no pixel is taken for backdrop.
bool showsOnlyBackdrop(const Film& film, size_t p, float backdrop) {
  for (int c = 0; c < 3; ++c)
    if (!(std::abs(film.mean(p, c) - backdrop) <= 1e-4 * backdrop) ||
        film.varianceOfMean(p, c) > 1e-6 * double(backdrop) * backdrop)
      return false;
  return true;
}
}  // namespace

FilmPreview encodeFilmPng(const Film& film, const PreviewLook& look, float backdrop) {
  // The key is the whole image's (the backdrop's grey is a grey card for the studio's light); the highlights the
  // automatic exposure keeps are the scene's, the pixels that show more than the backdrop. Without a backdrop (a
  // lights-only world, a map, --background) there are none to keep: the key alone, as a visible sky needs.
  std::vector<double> luminances, scene;
  for (size_t p = 0; p < film.pixels(); ++p) {
    luminances.push_back(luminance(film.mean(p, 0), film.mean(p, 1), film.mean(p, 2)));
    if (backdrop > 0.0f && !showsOnlyBackdrop(film, p, backdrop)) scene.push_back(luminances.back());
  }
  FilmPreview preview;
  preview.stops = exposureFor(look, luminances, scene);
  preview.backdropShare = backdrop > 0.0f ? 1.0 - double(scene.size()) / double(std::max<size_t>(1, film.pixels())) : 0.0;
  std::vector<uint8_t> rgb(film.pixels() * 3);
  for (size_t p = 0; p < film.pixels(); ++p) {
    const std::array<uint8_t, 3> out =
        previewPixel({film.mean(p, 0), film.mean(p, 1), film.mean(p, 2)}, preview.stops, look.toneMap);
    std::copy(out.begin(), out.end(), rgb.begin() + 3 * p);
    preview.clippedShare += (out[0] == 255 || out[1] == 255 || out[2] == 255) ? 1.0 / double(film.pixels()) : 0.0;
  }
  preview.png = encodeRgbPng(rgb, film.width, film.height);
  return preview;
}

namespace {
// Viridis at five stops, linearly interpolated: perceptually ordered and readable to most colour-blind eyes.
std::array<uint8_t, 3> viridis(double t) {
  static const double stops[5][3] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
  const double x = std::clamp(t, 0.0, 1.0) * 4.0;
  const int i = std::min(3, int(x));
  const double f = x - i;
  std::array<uint8_t, 3> rgb;
  for (int c = 0; c < 3; ++c) rgb[c] = uint8_t(std::lround(stops[i][c] + f * (stops[i + 1][c] - stops[i][c])));
  return rgb;
}
}  // namespace

std::string encodeEfficiencyPng(const std::vector<double>& efficiency, uint32_t width, uint32_t height) {
  std::vector<double> logs;
  for (double e : efficiency)
    if (e > 0.0 && std::isfinite(e)) logs.push_back(std::log10(e));
  std::sort(logs.begin(), logs.end());
  const double lo = logs.empty() ? 0.0 : logs[logs.size() / 100], hi = logs.empty() ? 1.0 : logs[logs.size() * 99 / 100];
  std::vector<uint8_t> rgb(efficiency.size() * 3, 0);
  for (size_t p = 0; p < efficiency.size(); ++p) {
    const double e = efficiency[p];
    const std::array<uint8_t, 3> c = e > 0.0 && std::isfinite(e) ? viridis((std::log10(e) - lo) / std::max(hi - lo, 1e-9))
                                                                 : std::array<uint8_t, 3>{128, 128, 128};
    std::copy(c.begin(), c.end(), rgb.begin() + 3 * p);
  }
  return encodeRgbPng(rgb, width, height);
}

std::string encodeEfficiencyPng(const Film& film) {
  if (!film.estimatesVariance()) return encodeRgbPng(std::vector<uint8_t>(film.pixels() * 3, 0), film.width, film.height);
  std::vector<double> efficiency(film.pixels());
  // As the EXR holds them (float), so that `vkmc compare --efficiency-png` draws the same map from the EXR.
  for (size_t p = 0; p < film.pixels(); ++p) efficiency[p] = double(float(std::min(film.efficiency(p), 3.0e38)));
  return encodeEfficiencyPng(efficiency, film.width, film.height);
}

}  // namespace vkmc
