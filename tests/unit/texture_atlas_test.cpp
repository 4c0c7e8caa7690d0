// Texture pages (host/render/texture_atlas.h): every texture lands whole in one page without overlapping
// another's texels or gutter, each gutter texel is what the texture's wrap modes give one texel past the edge,
// the page side is the cheapest candidate, and what does not fit is refused with the texture named.
#include <gtest/gtest.h>

#include <random>

#include "error.h"
#include "render/texture_atlas.h"

using namespace vkmc;

namespace {

Texture texture(uint32_t w, uint32_t h, TextureWrap s, TextureWrap t, std::mt19937& rng) {
  Texture x;
  x.width = w, x.height = h, x.wrapS = s, x.wrapT = t;
  for (uint32_t i = 0; i < w * h; ++i) x.texels.push_back(rng());
  return x;
}

// The reference wrap, written from the glTF/OpenGL definitions with integer modulo.
int wrapped(int i, int n, TextureWrap w) {
  if (w == TextureWrap::ClampToEdge) return std::clamp(i, 0, n - 1);
  if (w == TextureWrap::Repeat) return ((i % n) + n) % n;
  int period = 2 * n, m = ((i % period) + period) % period;
  return m < n ? m : period - 1 - m;
}

}  // namespace

TEST(TextureAtlas, TexturesAndGuttersLandWholeWithoutOverlap) {
  std::mt19937 rng(3);
  const TextureWrap modes[] = {TextureWrap::Repeat, TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat};
  std::vector<Texture> textures;
  for (int i = 0; i < 40; ++i)
    textures.push_back(texture(1 + rng() % 37, 1 + rng() % 23, modes[rng() % 3], modes[rng() % 3], rng));
  TextureAtlas atlas = packTextureAtlas(textures, 64, 100);
  ASSERT_EQ(atlas.placements.size(), textures.size());
  ASSERT_EQ(atlas.texels.size(), size_t(atlas.layers) * atlas.pageWidth * atlas.pageHeight);
  std::vector<int> owner(atlas.texels.size(), -1);
  for (size_t k = 0; k < textures.size(); ++k) {
    const Texture& t = textures[k];
    const AtlasPlacement& p = atlas.placements[k];
    ASSERT_LT(p.layer, atlas.layers);
    ASSERT_GE(p.x, 1u);
    ASSERT_GE(p.y, 1u);
    ASSERT_LE(p.x + t.width + 1, atlas.pageWidth);
    ASSERT_LE(p.y + t.height + 1, atlas.pageHeight);
    for (int y = -1; y <= int(t.height); ++y)
      for (int x = -1; x <= int(t.width); ++x) {
        size_t at = (size_t(p.layer) * atlas.pageHeight + size_t(int(p.y) + y)) * atlas.pageWidth + size_t(int(p.x) + x);
        EXPECT_EQ(owner[at], -1) << "texture " << k << " overlaps texture " << owner[at];
        owner[at] = int(k);
        uint32_t want =
            t.texels[size_t(wrapped(y, int(t.height), t.wrapT)) * t.width + size_t(wrapped(x, int(t.width), t.wrapS))];
        EXPECT_EQ(atlas.texels[at], want) << "texture " << k << " texel (" << x << ", " << y << ")";
      }
  }
}

TEST(TextureAtlas, EqualTexturesTakeOnePageEach) {
  // Five 2048^2 textures (DamagedHelmet): pages of 2050, no texel wasted beyond the gutters.
  std::mt19937 rng(1);
  std::vector<Texture> textures(5, texture(2048, 2048, TextureWrap::Repeat, TextureWrap::Repeat, rng));
  TextureAtlas atlas = packTextureAtlas(textures, 16384, 2048);
  EXPECT_EQ(atlas.pageWidth, 2050u);
  EXPECT_EQ(atlas.layers, 5u);
}

TEST(TextureAtlas, WhatDoesNotFitIsRefusedByName) {
  std::mt19937 rng(1);
  std::vector<Texture> textures = {texture(8, 8, TextureWrap::Repeat, TextureWrap::Repeat, rng)};
  textures.push_back(texture(63, 4, TextureWrap::Repeat, TextureWrap::Repeat, rng));
  textures.back().name = "wide";
  try {
    packTextureAtlas(textures, 64, 8);
    FAIL() << "a 63-texel texture does not fit a 64-texel page with its gutter";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'wide'"), std::string::npos) << e.what();
  }
  std::vector<Texture> many(9, texture(30, 30, TextureWrap::Repeat, TextureWrap::Repeat, rng));
  EXPECT_THROW(packTextureAtlas(many, 32, 8), Error);  // 9 pages needed, 8 allowed
  EXPECT_NO_THROW(packTextureAtlas(many, 32, 9));
}

TEST(TextureAtlas, TooManyPagesChooseALargerSide) {
  // Nine 30^2 textures: pages of 32 need 9 layers; with 8 allowed, pages of 64 hold four each.
  std::mt19937 rng(2);
  std::vector<Texture> many(9, texture(30, 30, TextureWrap::Repeat, TextureWrap::Repeat, rng));
  TextureAtlas atlas = packTextureAtlas(many, 64, 8);
  EXPECT_EQ(atlas.pageWidth, 64u);
  EXPECT_EQ(atlas.layers, 3u);
}

TEST(TextureAtlas, OnePageIsTrimmedAndUnusableImagesAreLeftOut) {
  std::mt19937 rng(4);
  std::vector<Texture> textures = {texture(1000, 2, TextureWrap::Repeat, TextureWrap::Repeat, rng), Texture{}};
  textures[1].name = "a KTX2 image the loader could not decode";
  TextureAtlas atlas = packTextureAtlas(textures, 16384, 2048);
  EXPECT_EQ(atlas.layers, 1u);
  EXPECT_EQ(atlas.pageWidth, 1002u);  // not a 1002^2 square for a 1000x2 texture
  EXPECT_EQ(atlas.pageHeight, 4u);
  EXPECT_EQ(atlas.texels.size(), size_t(1002) * 4);
  EXPECT_EQ(atlas.texels[size_t(1002) + 1], textures[0].texels[0]);
}

TEST(TextureAtlas, NoTexturesGiveOneTexel) {
  TextureAtlas atlas = packTextureAtlas({}, 64, 8);
  EXPECT_EQ(atlas.layers, 1u);
  EXPECT_EQ(atlas.texels.size(), 1u);
}
