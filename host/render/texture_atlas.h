// Every texture of a scene in the pages (layers) of one 2D array image, each surrounded by a one-texel gutter
// holding what its wrap modes put there, so that a sampler clamping to the page filters as the texture's own wrap
// modes would (texture_layout.h). One array image because lavapipe cannot index image arrays per lane.
#pragma once
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace vkmc {

struct AtlasPlacement {
  uint32_t layer = 0, x = 0, y = 0;  // the page and position of the texture's texel (0, 0); its gutter is around it
};

struct TextureAtlas {
  uint32_t pageWidth = 1, pageHeight = 1, layers = 1;
  std::vector<AtlasPlacement> placements;  // one per Scene::textures entry
  std::vector<uint32_t> texels;            // layers x pageHeight x pageWidth RGBA8 texels, page by page, row-major
};

// Shelf-packs the textures (tallest first) into square pages, choosing the page side (at most maxSide) that needs
// the fewest texels in all with at most maxLayers pages; a single page is trimmed to what it uses. Throws
// vkmc::Error naming the texture when one does not fit a page, or when no side needs few enough pages. Textures
// without texels (images the loader ignored) are left out. No textures: one 1x1 page (the kernels' descriptors
// must point at an image).
TextureAtlas packTextureAtlas(const std::vector<Texture>& textures, uint32_t maxSide, uint32_t maxLayers);

}  // namespace vkmc
