// Texture loading: images decoded into Scene::textures with their samplers, material slots with
// KHR_texture_transform and texCoord, undecodable or oversized images ignored with a warning naming them, and
// textured emitters weighted by their mean emission.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>  // jpeglib.h needs FILE first
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <jpeglib.h>

#include "scene/gltf_loader.h"
#include "scene/texture_sampler.h"
#include "support/test_scenes.h"

using namespace vkmc;

namespace {
bool anyWarningHas(const Scene& s, const std::string& text) {
  for (const std::string& w : s.warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}
}  // namespace

TEST(GltfTextures, ImagesSamplersAndTransformsReachTheScene) {
  auto dir = test::makeTempDir("textures");
  std::string png = test::writePng(dir, "img", 2, 2, {10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120, 130, 140, 150, 160});
  std::string material = R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0,"texCoord":1},
    "metallicRoughnessTexture":{"index":1,"extensions":{"KHR_texture_transform":{"offset":[0.5,-1],"rotation":1.5707963,
    "scale":[2,3],"texCoord":1}}}},"normalTexture":{"index":1,"scale":0.25},"emissiveTexture":{"index":0},
    "emissiveFactor":[1,1,1],"alphaMode":"MASK","alphaCutoff":0.3})";
  std::string extra = R"("extensionsUsed":["KHR_texture_transform"],"images":[{"uri":")" + png +
                      R"("}],"samplers":[{"wrapS":33071,"wrapT":33648,"magFilter":9728}],
    "textures":[{"source":0,"sampler":0},{"source":0}])";
  Scene s = loadGltf(test::writeQuadsGltf(dir, "tex", {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0}}, material, extra));
  ASSERT_EQ(s.textures.size(), 2u);
  const Texture& t = s.textures[0];
  EXPECT_EQ(t.width, 2u);
  EXPECT_EQ(t.height, 2u);
  EXPECT_EQ(t.texels[0], 10u | 20u << 8 | 30u << 16 | 40u << 24);
  EXPECT_EQ(t.texels[3], 130u | 140u << 8 | 150u << 16 | 160u << 24);
  EXPECT_EQ(t.wrapS, TextureWrap::ClampToEdge);
  EXPECT_EQ(t.wrapT, TextureWrap::MirroredRepeat);
  EXPECT_TRUE(t.nearest);
  EXPECT_EQ(s.textures[1].wrapS, TextureWrap::Repeat);
  EXPECT_FALSE(s.textures[1].nearest);
  const Material& m = s.materials[0];
  EXPECT_EQ(m.baseColorTexture.texture, 0);
  EXPECT_EQ(m.baseColorTexture.texCoord, 1);
  EXPECT_EQ(m.alphaMode, AlphaMode::Mask);
  EXPECT_FLOAT_EQ(m.alphaCutoff, 0.3f);
  EXPECT_FLOAT_EQ(m.normalTexture.scale, 0.25f);
  // KHR_texture_transform: uv' = T R S uv with R = [cos sin; -sin cos]; rotation pi/2, scale (2, 3), offset (0.5, -1).
  const TextureRef& mr = m.metallicRoughnessTexture;
  EXPECT_EQ(mr.texCoord, 1);
  glm::vec2 uv = slotUv(mr, glm::vec2(9.0f), glm::vec2(0.1f, 0.2f));
  EXPECT_NEAR(uv.x, 0.5 + 3 * 0.2, 1e-5);   // cos * 2 * u + sin * 3 * v + 0.5
  EXPECT_NEAR(uv.y, -1.0 - 2 * 0.1, 1e-5);  // -sin * 2 * u + cos * 3 * v - 1
  ASSERT_EQ(s.uv0.size(), s.positions.size());
  EXPECT_TRUE(s.uv1.empty());
  ASSERT_EQ(s.tangents.size(), s.positions.size());  // normal-mapped: tangents along +u (+x here)
  EXPECT_NEAR(s.tangents[0].x, 1.0, 1e-5);
}

TEST(GltfTextures, UndecodableAndOversizedImagesAreIgnoredWithAWarningNamingThem) {
  auto dir = test::makeTempDir("textures");
  std::ofstream(dir / "junk.png") << "not a png";
  std::string wide = test::writePng(dir, "wide", 20000, 1, std::vector<uint8_t>(20000 * 4, 7));
  std::string material = R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0}},"emissiveTexture":{"index":1}})";
  std::string extra =
      R"("images":[{"uri":"junk.png","name":"junk"},{"uri":")" + wide + R"("}],"textures":[{"source":0},{"source":1}])";
  Scene s = loadGltf(test::writeQuadsGltf(dir, "bad", {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0}}, material, extra));
  EXPECT_TRUE(anyWarningHas(s, "image 0 (junk)"));
  EXPECT_TRUE(anyWarningHas(s, "20000x1 exceeds 16384"));
  EXPECT_FALSE(s.materials[0].baseColorTexture.present());
  EXPECT_FALSE(s.materials[0].emissiveTexture.present());
}

// A texture whose image file is missing is named with the file (it was "texture 0 has no image vkmc can decode").
TEST(GltfTextures, AMissingImageFileIsNamed) {
  auto dir = test::makeTempDir("textures_missing");
  std::string material = R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}})";
  std::string extra = R"("images":[{"uri":"gone/wood.png"}],"textures":[{"source":0}])";
  Scene s = loadGltf(test::writeQuadsGltf(dir, "missing", {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0}}, material, extra));
  EXPECT_TRUE(anyWarningHas(s, "gone/wood.png")) << (s.warnings.empty() ? "" : s.warnings.back());
  EXPECT_FALSE(s.materials[0].baseColorTexture.present());
}

// Only PNG, JPEG, WebP and KTX2, by their signatures: a Radiance .hdr, a GIF or a BMP as a texture is ignored with a
// warning, never handed to another decoder (stb_image's HDR decoder, which the loader once reached, looped forever
// on a cut file).
TEST(GltfTextures, ImagesOtherThanPngJpegAndWebpAreIgnoredWithAWarning) {
  auto dir = test::makeTempDir("textures_formats");
  std::ofstream(dir / "sky.hdr", std::ios::binary) << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 64 +X 64\n" << char(2) << char(2);
  std::ofstream(dir / "anim.gif", std::ios::binary) << "GIF89a" << std::string(32, '\0');
  std::string material = R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0}},"emissiveTexture":{"index":1}})";
  std::string extra = R"("images":[{"uri":"sky.hdr"},{"uri":"anim.gif"}],"textures":[{"source":0},{"source":1}])";
  Scene s = loadGltf(test::writeQuadsGltf(dir, "formats", {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0}}, material, extra));
  EXPECT_TRUE(anyWarningHas(s, "image 0: not PNG, JPEG, WebP or KTX2"));
  EXPECT_TRUE(anyWarningHas(s, "image 1: not PNG, JPEG, WebP or KTX2"));
  EXPECT_FALSE(s.materials[0].baseColorTexture.present());
}

// A JPEG whose Huffman table overruns stb_image's (Debian's 2.27 wrote past it: found by image_fuzzer, kept in
// tests/fuzz/regressions/images/) is refused by libjpeg-turbo with a warning naming the image.
TEST(GltfTextures, ACorruptJpegIsIgnoredWithAWarning) {
  auto dir = test::makeTempDir("textures_corrupt");
  std::filesystem::copy_file(std::string(VKMC_SOURCE_DIR) + "/tests/fuzz/regressions/images/stb_huffman_overflow.jpg",
                             dir / "bad.jpg");
  std::string material = R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}})";
  std::string extra = R"("images":[{"uri":"bad.jpg"}],"textures":[{"source":0}])";
  Scene s = loadGltf(test::writeQuadsGltf(dir, "corrupt", {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0}}, material, extra));
  EXPECT_TRUE(anyWarningHas(s, "image 0: a corrupt")) << (s.warnings.empty() ? "" : s.warnings.back());
  EXPECT_FALSE(s.materials[0].baseColorTexture.present());
}

TEST(GltfTextures, ATexturedEmitterIsWeightedByItsMeanEmission) {
  // Left half of the texture black, right half white (sRGB 255 = 1): the quad's mean emission is half its factor.
  auto dir = test::makeTempDir("textures");
  std::string png = test::writePng(dir, "half", 2, 1, {0, 0, 0, 255, 255, 255, 255, 255});
  std::string material =
      R"({"emissiveFactor":[1,1,1],"emissiveTexture":{"index":0},"extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":4}}})";
  std::string extra = R"("images":[{"uri":")" + png + R"("}],"samplers":[{"magFilter":9728}],
    "textures":[{"source":0,"sampler":0}])";
  Scene s = loadGltf(test::writeQuadsGltf(dir, "glow", {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0}}, material, extra));
  double mean = 0.0;
  for (size_t t = 0; t < s.triangleCount(); ++t) mean += averageEmission(s, t).x / double(s.triangleCount());
  EXPECT_NEAR(mean, 2.0, 0.26);  // the 64-point pattern per triangle: within its quadrature error of 4 x 1/2
  EXPECT_GT(mean, 0.0);
}

// EXT_texture_webp: the WebP source is preferred, the core source is its fallback, and a WebP as the core source is
// read too (glTF-Transform, gltfjsx and Godot write WebP). Lossless WebP decodes to the exact texels.
TEST(GltfTextures, WebpTexturesAreReadWithTheirFallback) {
  auto dir = test::makeTempDir("textures_webp");
  const std::vector<uint8_t> texels = {10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120, 130, 140, 150, 160};
  std::string webp = test::writeWebp(dir, "img", 2, 2, texels);
  std::string png = test::writePng(dir, "fallback", 1, 1, {1, 2, 3, 255});
  const char broken[] = "RIFF\x10\0\0\0WEBPVP8 junk";  // a WebP's signature, then no valid chunk
  std::ofstream(dir / "broken.webp", std::ios::binary).write(broken, sizeof(broken) - 1);
  std::string material = R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0}},"emissiveTexture":{"index":1},
      "normalTexture":{"index":2}})";
  std::string extra = R"("extensionsUsed":["EXT_texture_webp"],"images":[{"uri":")" + webp + R"("},{"uri":")" + png +
                      R"("},{"uri":"broken.webp"}],"textures":[{"source":1,"extensions":{"EXT_texture_webp":{"source":0}}},
      {"source":1,"extensions":{"EXT_texture_webp":{"source":2}}},{"source":0}])";
  Scene s = loadGltf(test::writeQuadsGltf(dir, "webp", {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0}}, material, extra));
  ASSERT_EQ(s.textures.size(), 3u);
  ASSERT_EQ(s.textures[0].width, 2u);
  EXPECT_EQ(std::memcmp(s.textures[0].texels.data(), texels.data(), texels.size()), 0) << "the WebP, not the fallback";
  ASSERT_EQ(s.textures[1].width, 1u) << "an undecodable WebP falls back to the core source";
  const uint8_t fallback[4] = {1, 2, 3, 255};
  EXPECT_EQ(std::memcmp(s.textures[1].texels.data(), fallback, 4), 0);
  EXPECT_TRUE(anyWarningHas(s, "image 2: not a valid WebP"));
  EXPECT_EQ(s.textures[2].width, 2u) << "a WebP as the core source";
  EXPECT_TRUE(s.warnings.end() ==
              std::find_if(s.warnings.begin(), s.warnings.end(),
                           [](const std::string& w) { return w.find("EXT_texture_webp") != std::string::npos; }))
      << "EXT_texture_webp is implemented: no warning";
}

// KHR_texture_basisu: the KTX2 source is preferred over the core source (its fallback), a texture may name only the
// KTX2 (the spec lets a file that requires the extension leave the core source out), and a cut KTX2 falls back.
TEST(GltfTextures, Ktx2TexturesAreTranscodedWithTheirFallback) {
  auto dir = test::makeTempDir("textures_ktx2");
  const std::string data = std::string(VKMC_SOURCE_DIR) + "/tests/unit/data/ktx2/";
  std::filesystem::copy_file(data + "quadrants_uastc_zstd.ktx2", dir / "q.ktx2",
                             std::filesystem::copy_options::overwrite_existing);
  std::ifstream whole(data + "quadrants_etc1s.ktx2", std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(whole), std::istreambuf_iterator<char>()};
  std::ofstream(dir / "cut.ktx2", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  std::string png = test::writePng(dir, "fallback", 1, 1, {1, 2, 3, 255});
  std::string material = R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0}},"emissiveTexture":{"index":1},
      "normalTexture":{"index":2}})";
  std::string extra = R"("extensionsUsed":["KHR_texture_basisu"],"extensionsRequired":["KHR_texture_basisu"],
      "images":[{"uri":"q.ktx2","mimeType":"image/ktx2"},{"uri":")" +
                      png + R"("},{"uri":"cut.ktx2"}],
      "textures":[{"source":1,"extensions":{"KHR_texture_basisu":{"source":0}}},{"extensions":{"KHR_texture_basisu":{"source":0}}},
      {"source":1,"extensions":{"KHR_texture_basisu":{"source":2}}}])";
  Scene s = loadGltf(test::writeQuadsGltf(dir, "ktx2", {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0}}, material, extra));
  ASSERT_EQ(s.textures.size(), 3u);
  EXPECT_EQ(s.textures[0].width, 16u) << "the KTX2, not the fallback";
  EXPECT_EQ(s.textures[1].width, 16u) << "a KTX2 with no core source";
  EXPECT_NEAR(int(s.textures[0].texels[0] & 0xFF), 200, 2) << "the top-left quadrant's red";
  ASSERT_EQ(s.textures[2].width, 1u) << "a cut KTX2 falls back to the core source";
  EXPECT_TRUE(anyWarningHas(s, "image 2:"));
  EXPECT_TRUE(s.warnings.end() ==
              std::find_if(s.warnings.begin(), s.warnings.end(),
                           [](const std::string& w) { return w.find("KHR_texture_basisu") != std::string::npos; }))
      << "KHR_texture_basisu is implemented: no warning";
}

// A progressive JPEG (libjpeg's own encoder) decodes within the working memory vkmc allows libjpeg for its size.
TEST(GltfTextures, AProgressiveJpegIsRead) {
  auto dir = test::makeTempDir("textures_progressive");
  const int w = 96, h = 64;
  std::vector<uint8_t> rgb(size_t(w) * h * 3);
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = uint8_t(i * 7);
  jpeg_compress_struct info;
  jpeg_error_mgr errors;
  info.err = jpeg_std_error(&errors);
  jpeg_create_compress(&info);
  unsigned char* bytes = nullptr;
  unsigned long size = 0;
  jpeg_mem_dest(&info, &bytes, &size);
  info.image_width = w, info.image_height = h, info.input_components = 3, info.in_color_space = JCS_RGB;
  jpeg_set_defaults(&info);
  jpeg_simple_progression(&info);
  jpeg_start_compress(&info, TRUE);
  while (info.next_scanline < info.image_height) {
    JSAMPROW row = rgb.data() + size_t(info.next_scanline) * w * 3;
    jpeg_write_scanlines(&info, &row, 1);
  }
  jpeg_finish_compress(&info);
  jpeg_destroy_compress(&info);
  std::ofstream(dir / "progressive.jpg", std::ios::binary).write(reinterpret_cast<const char*>(bytes), std::streamsize(size));
  std::free(bytes);
  std::string material = R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}})";
  std::string extra = R"("images":[{"uri":"progressive.jpg"}],"textures":[{"source":0}])";
  Scene s = loadGltf(test::writeQuadsGltf(dir, "progressive", {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0}}, material, extra));
  ASSERT_EQ(s.textures.size(), 1u);
  EXPECT_EQ(s.textures[0].width, uint32_t(w));
  EXPECT_EQ(s.textures[0].height, uint32_t(h));
}
