// The texture-form benchmark (host/bench/texture_forms.h) compares like with like: every form returns the same
// lookups as the renderer's, within what the form's own arithmetic allows, on textures that wrap.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <random>

#include "bench/texture_forms.h"
#include "support/render_helpers.h"

using namespace vkmc;

namespace {

Texture randomTexture(uint32_t w, uint32_t h, std::mt19937& rng) {
  Texture t;
  t.width = w, t.height = h;
  for (uint32_t i = 0; i < w * h; ++i) t.texels.push_back(rng());
  return t;
}

// Two materials on two quads whose uvs run over [-1.5, 2.5]: lookups wrap in both directions.
Scene twoTextureScene(uint32_t secondWidth) {
  std::mt19937 rng(5);
  Scene s;
  s.textures.push_back(randomTexture(8, 8, rng));
  s.textures.push_back(randomTexture(secondWidth, 8, rng));
  for (int m = 0; m < 2; ++m) {
    Material mat;
    mat.baseColorTexture.texture = m;
    mat.metallicRoughnessTexture.texture = 1 - m;
    mat.emissiveTexture.texture = m;
    s.materials.push_back(mat);
    test::addQuad(s, glm::vec3(float(2 * m), 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), uint32_t(m));
    for (glm::vec2 uv : {glm::vec2(-1.5f, -1.5f), glm::vec2(2.5f, -1.5f), glm::vec2(2.5f, 2.5f), glm::vec2(-1.5f, -1.5f),
                         glm::vec2(2.5f, 2.5f), glm::vec2(-1.5f, 2.5f)})
      s.uv0.push_back(uv);
  }
  return s;
}

}  // namespace

TEST(TextureForms, LookupsAreShadingsAndOrderIsAPermutation) {
  Scene scene = twoTextureScene(8);
  std::vector<gpu::TestRay> coherent = makeTextureLookups(scene, 4096, true, 3),
                            random = makeTextureLookups(scene, 4096, false, 3);
  // Three slots per point (base colour, metallic-roughness, emissive), the normal slot empty.
  EXPECT_EQ(countTextureLookups(coherent), 3u * 4096u);
  for (const gpu::TestRay& r : random) EXPECT_EQ(std::bit_cast<uint32_t>(r.direction.z), gpu::kNoTexture);
  auto key = [](const gpu::TestRay& r) {
    return std::make_tuple(r.origin.x, r.origin.y, std::bit_cast<uint32_t>(r.direction.x),
                           std::bit_cast<uint32_t>(r.direction.y));
  };
  std::vector<std::tuple<float, float, uint32_t, uint32_t>> a, b;
  for (const gpu::TestRay& r : coherent) a.push_back(key(r));
  for (const gpu::TestRay& r : random) b.push_back(key(r));
  EXPECT_NE(a, b);  // reordered
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  EXPECT_EQ(a, b);  // the same lookups
}

TEST(TextureForms, BothFormsReadTheSamePages) {
  // Two sizes and three wrap modes: the pages' gutters must give the kernel's filter what the sampler's gets.
  Scene scene = twoTextureScene(5);
  scene.textures[0].wrapS = TextureWrap::MirroredRepeat;
  scene.textures[1].wrapT = TextureWrap::ClampToEdge;
  std::vector<gpu::TestRay> lookups = makeTextureLookups(scene, 4096, false, 7);
  vk::Context& ctx = test::sharedContext();
  std::vector<TextureFormTiming> forms = timeTextureForms(ctx, scene, lookups, 2);
  ASSERT_EQ(forms.size(), 2u);
  for (const TextureFormTiming& f : forms) {
    EXPECT_EQ(f.skipped, "") << f.form;
    EXPECT_EQ(f.nsPerLookup.size(), 2u) << f.form;
  }
  // The sampler quantizes bilinear weights to subTexelPrecisionBits, so each of the 3 lookups in a sum may be off
  // by 2^(1 - bits) of a texel difference (<= 1), and returns 8-bit texels' filtered values at 8 bits. A wrong
  // texel, page or wrap is off by ~0.3 on these random textures.
  double bits = ctx.properties().limits.subTexelPrecisionBits;
  EXPECT_LT(forms[1].maxDifference, 3.0 * (std::ldexp(1.0, 1 - int(bits)) + 1.0 / 255.0)) << "subTexelPrecisionBits " << bits;
}

TEST(TextureForms, ALonePageIsTrimmedToARectangle) {
  // One 16x3 texture: its page is 18x5, not 18x18; both forms must address the rectangle.
  Scene scene = twoTextureScene(8);
  std::mt19937 rng(9);
  scene.textures = {randomTexture(16, 3, rng)};
  scene.textures[0].wrapT = TextureWrap::MirroredRepeat;
  for (Material& m : scene.materials)
    m.baseColorTexture.texture = m.metallicRoughnessTexture.texture = m.emissiveTexture.texture = 0;
  std::vector<gpu::TestRay> lookups = makeTextureLookups(scene, 2048, false, 5);
  vk::Context& ctx = test::sharedContext();
  std::vector<TextureFormTiming> forms = timeTextureForms(ctx, scene, lookups, 1);
  ASSERT_EQ(forms.size(), 2u);
  ASSERT_EQ(forms[1].skipped, "");
  double bits = ctx.properties().limits.subTexelPrecisionBits;
  EXPECT_LT(forms[1].maxDifference, 3.0 * (std::ldexp(1.0, 1 - int(bits)) + 1.0 / 255.0));
}
