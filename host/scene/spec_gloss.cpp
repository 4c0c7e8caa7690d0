// Specular-glossiness into metallic-roughness.
#include "scene/spec_gloss.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>

#include "error.h"
#include "scene/gltf_textures.h"
#include "scene/texture_sampler.h"

namespace vkmc {
namespace {

constexpr float kDielectricF0 = 0.04f;

float perceivedBrightness(glm::vec3 c) { return std::sqrt(0.299f * c.r * c.r + 0.587f * c.g * c.g + 0.114f * c.b * c.b); }
float maxComponent(glm::vec3 c) { return std::max(c.r, std::max(c.g, c.b)); }

// Metallic m from the brightness of the diffuse d and specular s: the metal-rough model's specular is
// 0.04 (1 - m) + base m and its diffuse base (1 - 0.04)(1 - m), the spec-gloss diffuse is scaled by
// 1 - max(specular); eliminating base gives 0.04 m^2 + b m + (0.04 - s) = 0.
float solveMetallic(float d, float s, float oneMinusSpecular) {
  if (s < kDielectricF0) return 0.0f;
  float b = d * oneMinusSpecular / (1.0f - kDielectricF0) + s - 2.0f * kDielectricF0;
  float c = kDielectricF0 - s;
  float disc = std::max(b * b - 4.0f * kDielectricF0 * c, 0.0f);
  return std::clamp((-b + std::sqrt(disc)) / (2.0f * kDielectricF0), 0.0f, 1.0f);
}

uint8_t toByte(float x) { return uint8_t(std::lround(std::clamp(x, 0.0f, 1.0f) * 255.0f)); }
float linearToSrgb(float x) { return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f; }
uint32_t packRgba(uint8_t r, uint8_t g, uint8_t b, uint8_t a) {
  return uint32_t(r) | uint32_t(g) << 8 | uint32_t(b) << 16 | uint32_t(a) << 24;
}

std::vector<double> numbers(const tinygltf::Value& v, const char* key, std::vector<double> fallback) {
  if (!v.Has(key) || !v.Get(key).IsArray()) return fallback;
  const tinygltf::Value& a = v.Get(key);
  if (a.ArrayLen() != fallback.size())
    throw Error(std::string(key) + " must have " + std::to_string(fallback.size()) + " numbers");
  for (size_t i = 0; i < fallback.size(); ++i) {
    if (!a.Get(int(i)).IsNumber()) throw Error(std::string(key) + " must hold numbers");
    fallback[i] = a.Get(int(i)).GetNumberAsDouble();
  }
  return fallback;
}

// A textureInfo inside the extension's JSON, as the core slots' are read (texCoord, KHR_texture_transform).
TextureRef textureRef(const tinygltf::Value& ext, const char* key, const std::vector<Texture>& textures, const std::string& what,
                      std::vector<std::string>& warnings) {
  if (!ext.Has(key) || !ext.Get(key).IsObject()) return {};
  const tinygltf::Value& v = ext.Get(key);
  tinygltf::TextureInfo info;
  info.index = v.Has("index") && v.Get("index").IsInt() ? v.Get("index").GetNumberAsInt() : -1;
  info.texCoord = v.Has("texCoord") && v.Get("texCoord").IsInt() ? v.Get("texCoord").GetNumberAsInt() : 0;
  if (v.Has("extensions") && v.Get("extensions").IsObject() && v.Get("extensions").Has("KHR_texture_transform"))
    info.extensions["KHR_texture_transform"] = v.Get("extensions").Get("KHR_texture_transform");
  TextureRef ref = convertTextureRef(info, textures, what, warnings);
  if (ref.present() && textures[ref.texture].width == 0) return {};  // undecodable: warned about already
  return ref;
}

bool sameMapping(const TextureRef& a, const TextureRef& b) {
  return a.texCoord == b.texCoord && a.uvRow0 == b.uvRow0 && a.uvRow1 == b.uvRow1;
}

}  // namespace

MetalRoughSample metalRoughFromSpecGloss(glm::vec3 diffuse, glm::vec3 specular, float glossiness) {
  const float eps = 1e-6f;
  float oneMinusSpecular = 1.0f - maxComponent(specular);
  float m = solveMetallic(perceivedBrightness(diffuse), perceivedBrightness(specular), oneMinusSpecular);
  glm::vec3 fromDiffuse = diffuse * (oneMinusSpecular / (1.0f - kDielectricF0) / std::max(1.0f - m, eps));
  glm::vec3 fromSpecular = (specular - glm::vec3(kDielectricF0 * (1.0f - m))) / std::max(m, eps);
  glm::vec3 base = glm::clamp(glm::mix(fromDiffuse, fromSpecular, m * m), 0.0f, 1.0f);
  return {base, m, std::clamp(1.0f - glossiness, 0.0f, 1.0f)};
}

void applySpecularGlossiness(const tinygltf::Value& ext, Material& out, const std::vector<Texture>& textures,
                             std::vector<Texture>& baked, const std::string& name, std::vector<std::string>& warnings) {
  const std::string what = name + " KHR_materials_pbrSpecularGlossiness";
  std::vector<double> d = numbers(ext, "diffuseFactor", {1, 1, 1, 1}), s = numbers(ext, "specularFactor", {1, 1, 1});
  double g = ext.Has("glossinessFactor") && ext.Get("glossinessFactor").IsNumber()
                 ? ext.Get("glossinessFactor").GetNumberAsDouble()
                 : 1.0;
  glm::vec4 diffuseFactor(d[0], d[1], d[2], d[3]);
  glm::vec3 specularFactor(s[0], s[1], s[2]);
  float glossinessFactor = float(g);
  if (!std::isfinite(diffuseFactor.x + diffuseFactor.y + diffuseFactor.z + diffuseFactor.w) ||
      !std::isfinite(specularFactor.x + specularFactor.y + specularFactor.z) || !std::isfinite(glossinessFactor))
    throw Error(what + ": a factor is NaN or infinite");
  // The extension's ranges: every factor in [0, 1] (a factor of 1e30 made most samples NaN).
  auto inUnit = [](auto v) {
    return glm::all(glm::greaterThanEqual(v, decltype(v)(0.0f))) && glm::all(glm::lessThanEqual(v, decltype(v)(1.0f)));
  };
  if (!inUnit(diffuseFactor)) throw Error(what + ": diffuseFactor must lie in [0, 1]");
  if (!inUnit(specularFactor)) throw Error(what + ": specularFactor must lie in [0, 1]");
  if (!(glossinessFactor >= 0.0f && glossinessFactor <= 1.0f)) throw Error(what + ": glossinessFactor must lie in [0, 1]");
  TextureRef diffuse = textureRef(ext, "diffuseTexture", textures, what + " diffuseTexture", warnings);
  TextureRef specGloss = textureRef(ext, "specularGlossinessTexture", textures, what + " specularGlossinessTexture", warnings);
  if (diffuse.present() && specGloss.present() && !sameMapping(diffuse, specGloss)) {
    warnings.push_back(what + ": specularGlossinessTexture has another uv set or transform than diffuseTexture; it is ignored");
    specGloss = {};
  }
  out.specular = 1.0f;
  out.metallicRoughnessTexture = {};
  if (!diffuse.present() && !specGloss.present()) {
    MetalRoughSample m = metalRoughFromSpecGloss(glm::vec3(diffuseFactor), specularFactor, glossinessFactor);
    out.baseColor = m.baseColor, out.alpha = diffuseFactor.w, out.metallic = m.metallic, out.roughness = m.roughness;
    out.baseColorTexture = {};
    return;
  }
  // Bake: every texel of the finer source grid, both textures looked up at its centre.
  auto texels = [&](const TextureRef& r) {
    return r.present() ? uint64_t(textures[r.texture].width) * textures[r.texture].height : 0u;
  };
  const TextureRef& source = texels(diffuse) >= texels(specGloss) ? diffuse : specGloss;
  const Texture& grid = textures[source.texture];
  Texture base, metalRough;
  for (Texture* t : {&base, &metalRough}) {
    t->width = grid.width, t->height = grid.height, t->wrapS = grid.wrapS, t->wrapT = grid.wrapT, t->nearest = grid.nearest;
    t->texels.resize(size_t(grid.width) * grid.height);
  }
  base.name = grid.name + " (baseColor from specular-glossiness)";
  metalRough.name = grid.name + " (metallicRoughness from specular-glossiness)";
  for (uint32_t y = 0; y < grid.height; ++y)
    for (uint32_t x = 0; x < grid.width; ++x) {
      glm::vec2 uv((x + 0.5f) / grid.width, (y + 0.5f) / grid.height);
      glm::vec4 dif = diffuseFactor * (diffuse.present() ? sampleTexture(textures[diffuse.texture], uv, true) : glm::vec4(1.0f));
      glm::vec4 sg = specGloss.present() ? sampleTexture(textures[specGloss.texture], uv, true) : glm::vec4(1.0f);
      MetalRoughSample m = metalRoughFromSpecGloss(glm::vec3(dif), specularFactor * glm::vec3(sg), glossinessFactor * sg.a);
      size_t i = size_t(y) * grid.width + x;
      base.texels[i] = packRgba(toByte(linearToSrgb(m.baseColor.r)), toByte(linearToSrgb(m.baseColor.g)),
                                toByte(linearToSrgb(m.baseColor.b)), toByte(dif.a));
      metalRough.texels[i] = packRgba(0, toByte(m.roughness), toByte(m.metallic), 255);
    }
  TextureRef baseRef = source, metalRoughRef = source;
  baseRef.texture = int(textures.size() + baked.size());
  metalRoughRef.texture = baseRef.texture + 1;
  baked.push_back(std::move(base));
  baked.push_back(std::move(metalRough));
  out.baseColor = glm::vec3(1.0f), out.alpha = 1.0f, out.metallic = 1.0f, out.roughness = 1.0f;
  out.baseColorTexture = baseRef;
  out.metallicRoughnessTexture = metalRoughRef;
}

}  // namespace vkmc
