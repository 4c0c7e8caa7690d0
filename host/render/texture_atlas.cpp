// Shelf packing of textures into array-image pages, gutters filled by the kernels' own wrap rule.
#include "render/texture_atlas.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "../shaders/shared/texture_layout.h"
#include "error.h"
#include "scene/texture_sampler.h"

namespace vkmc {

namespace {

struct Padded {
  uint32_t w, h;
  size_t texture;
};

// Shelf packing at page side `side`: placements (of the padded boxes' corners) and the pages used.
uint32_t shelfPack(const std::vector<Padded>& boxes, uint32_t side, std::vector<AtlasPlacement>* placements) {
  uint32_t layer = 0, x = 0, y = 0, shelf = 0;
  for (const Padded& b : boxes) {
    if (x + b.w > side) y += shelf, x = 0, shelf = 0;
    if (y + b.h > side) ++layer, x = 0, y = 0, shelf = 0;
    if (placements) (*placements)[b.texture] = {layer, x + 1, y + 1};
    x += b.w;
    shelf = std::max(shelf, b.h);
  }
  return layer + 1;
}

std::string textureName(const Texture& t, size_t i) {
  return "texture " + std::to_string(i) + (t.name.empty() ? "" : " ('" + t.name + "')");
}

}  // namespace

TextureAtlas packTextureAtlas(const std::vector<Texture>& textures, uint32_t maxSide, uint32_t maxLayers) {
  TextureAtlas atlas;
  atlas.placements.resize(textures.size());  // images the loader could not use (no texels) keep (0, 0, 0)
  std::vector<Padded> boxes;
  uint32_t largest = 0;
  double area = 0.0;
  for (size_t i = 0; i < textures.size(); ++i) {
    const Texture& t = textures[i];
    if (t.width == 0 || t.height == 0 || t.texels.size() != size_t(t.width) * t.height) continue;
    if (uint64_t(t.width) + 2 > maxSide || uint64_t(t.height) + 2 > maxSide)
      throw Error(textureName(t, i) + " is " + std::to_string(t.width) + "x" + std::to_string(t.height) +
                  ": larger than the device's largest image side (" + std::to_string(maxSide) + ") less a 1-texel border");
    boxes.push_back({t.width + 2, t.height + 2, i});
    largest = std::max({largest, t.width + 2, t.height + 2});
    area += double(t.width + 2) * double(t.height + 2);
  }
  if (boxes.empty()) {
    atlas.texels.assign(1, 0xffffffffu);
    return atlas;
  }
  std::stable_sort(boxes.begin(), boxes.end(),
                   [](const Padded& a, const Padded& b) { return a.h != b.h ? a.h > b.h : a.w > b.w; });
  // Candidate sides: the largest texture's, its doublings, and the square of the total area. Among those whose
  // pages the device allows, the fewest texels win, then the fewest pages.
  std::vector<uint32_t> sides;
  for (uint64_t s = largest; s <= maxSide; s *= 2) sides.push_back(uint32_t(s));
  uint64_t root = uint64_t(std::ceil(std::sqrt(area)));
  if (root > largest && root <= maxSide) sides.push_back(uint32_t(root));
  uint32_t bestSide = 0, bestPages = 0, fewestPages = ~0u;
  double bestTexels = 0.0;
  for (uint32_t s : sides) {
    uint32_t pages = shelfPack(boxes, s, nullptr);
    fewestPages = std::min(fewestPages, pages);
    double texels = double(pages) * double(s) * double(s);
    if (pages <= maxLayers && (bestSide == 0 || texels < bestTexels || (texels == bestTexels && pages < bestPages)))
      bestSide = s, bestPages = pages, bestTexels = texels;
  }
  if (bestSide == 0)
    throw Error("textures too big for the device: they need at least " + std::to_string(fewestPages) +
                " image layers, the device allows " + std::to_string(maxLayers));
  atlas.layers = shelfPack(boxes, bestSide, &atlas.placements);
  // One page is trimmed to what its shelves use (a long, thin texture must not cost a square of its length).
  atlas.pageWidth = atlas.pageHeight = bestSide;
  if (atlas.layers == 1) {
    atlas.pageWidth = atlas.pageHeight = 0;
    for (const Padded& b : boxes) {
      const AtlasPlacement& p = atlas.placements[b.texture];
      atlas.pageWidth = std::max(atlas.pageWidth, p.x - 1 + b.w);
      atlas.pageHeight = std::max(atlas.pageHeight, p.y - 1 + b.h);
    }
  }

  const size_t W = atlas.pageWidth, page = W * atlas.pageHeight;
  atlas.texels.assign(page * atlas.layers, 0u);
  for (const Padded& b : boxes) {
    const Texture& t = textures[b.texture];
    const AtlasPlacement& p = atlas.placements[b.texture];
    const int w = int(t.width), h = int(t.height);
    const uint32_t wrapS = wrapCode(t.wrapS), wrapT = wrapCode(t.wrapT);
    uint32_t* origin = &atlas.texels[page * p.layer + size_t(p.y) * W + p.x];
    for (int y = -1; y <= h; ++y) {
      const int sy = gpu::wrapNearTexel(y, h, wrapT);
      for (int x = -1; x <= w; ++x)
        origin[std::ptrdiff_t(y) * std::ptrdiff_t(W) + x] =
            t.texels[size_t(sy) * t.width + size_t(gpu::wrapNearTexel(x, w, wrapS))];
    }
  }
  return atlas;
}

}  // namespace vkmc
