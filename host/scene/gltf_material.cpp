#include "scene/gltf_material.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "error.h"
#include "scene/gltf_material_extensions.h"
#include "scene/gltf_textures.h"
#include "scene/spec_gloss.h"

namespace vkmc {
namespace {

// Exporters write 1 as 1.0000001 now and then: within this of a bound, a factor is taken as the bound.
constexpr double kRoundingSlack = 1e-5;

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%g", x);
  return buf;
}

// A factor the schema bounds to [0, 1] (or [0, inf) where `hi` is infinite), checked and rounded into range.
float factor(double x, double hi, const std::string& what) {
  if (!std::isfinite(x)) throw Error(what + " is not a finite number");
  if (x < -kRoundingSlack || x > hi + kRoundingSlack)
    throw Error(what + " = " + number(x) + " is outside [0, " + (std::isinf(hi) ? "inf" : number(hi)) + "]");
  return float(std::min(std::max(x, 0.0), hi));
}

double extensionNumber(const tinygltf::ExtensionMap& ext, const char* extension, const char* key, double fallback) {
  auto it = ext.find(extension);
  if (it == ext.end() || !it->second.Has(key)) return fallback;
  const tinygltf::Value& v = it->second.Get(key);
  return v.IsNumber() ? v.GetNumberAsDouble() : NAN;
}

// The core factors: baseColorFactor, metallicFactor, roughnessFactor in [0, 1], emissiveStrength and alphaCutoff
// in [0, inf). emissiveFactor above the schema's 1 is used as given with a warning: Blender's exporter wrote a
// strength into it before KHR_materials_emissive_strength existed, and viewers render such files.
void readCoreFactors(const tinygltf::Material& m, const std::string& name, Material& out, std::vector<std::string>& warnings) {
  constexpr double kUnbounded = INFINITY;
  const auto& pbr = m.pbrMetallicRoughness;
  if (pbr.baseColorFactor.size() != 4) throw Error(name + ": baseColorFactor must have 4 components");
  for (int c = 0; c < 3; ++c) out.baseColor[c] = factor(pbr.baseColorFactor[c], 1.0, name + ": baseColorFactor");
  out.alpha = factor(pbr.baseColorFactor[3], 1.0, name + ": baseColorFactor's alpha");
  out.metallic = factor(pbr.metallicFactor, 1.0, name + ": metallicFactor");
  out.roughness = factor(pbr.roughnessFactor, 1.0, name + ": roughnessFactor");
  if (m.emissiveFactor.size() != 3) throw Error(name + ": emissiveFactor must have 3 components");
  for (int c = 0; c < 3; ++c) out.emission[c] = factor(m.emissiveFactor[c], kUnbounded, name + ": emissiveFactor");
  if (const float most = std::max({out.emission.x, out.emission.y, out.emission.z}); most > 1.0 + kRoundingSlack)
    warnings.push_back(name + ": emissiveFactor = " + number(most) +
                       " is above the schema's 1 (an exporter's strength); used as given, as viewers do");
  double strength = extensionNumber(m.extensions, "KHR_materials_emissive_strength", "emissiveStrength", 1.0);
  out.emission *= factor(strength, kUnbounded, name + ": KHR_materials_emissive_strength.emissiveStrength");
  if (!std::isfinite(out.emission.x) || !std::isfinite(out.emission.y) || !std::isfinite(out.emission.z))
    throw Error(name + ": emissiveFactor x emissiveStrength overflows float");
  out.alphaCutoff = factor(m.alphaCutoff, kUnbounded, name + ": alphaCutoff");
}

// KHR_materials_unlit as an emission shader (what Blender's importer makes of it): the surface shows its base
// colour, baseColorFactor x baseColorTexture, as emitted radiance, reflects nothing, and like any emitter lights
// its surroundings. Its alpha (factor and texture) still applies.
void makeUnlit(Material& m) {
  m.emission = m.baseColor;
  m.emissiveTexture = m.baseColorTexture;
  m.baseColor = glm::vec3(0.0f);
  m.metallic = 0.0f;
  m.specular = 0.0f;
  m.normalTexture = TextureRef{};
  m.metallicRoughnessTexture = TextureRef{};
  m.transmission = 0.0f;
  m.clearcoat = 0.0f;
  m.sheenColor = glm::vec3(0.0f);
}

// A volume's interface of ior 1 with no metal neither reflects nor bends light: its microfacets are invisible, so
// it is rendered straight through, whatever its roughness (the rough btdf is degenerate at eta 1: it lost 2% of the
// light at roughness 0.3 and 29% at 1 in the glass furnace), and without Schlick's grazing reflection (its F90 is
// specularFactor, which an index-matched interface does not have). A metal's reflection keeps its roughness, so
// only metallicFactor 0 (any texture times 0) qualifies; thin-walled transmission (no volume) does not depend on
// the ior and keeps its roughness.
void matchIndex(Material& m) {
  constexpr float kMatched = 1e-3f;
  if (m.transmission > 0.0f && m.volumetric && std::abs(m.ior - 1.0f) < kMatched && m.metallic == 0.0f)
    m.roughness = 0.0f, m.specular = 0.0f;
}

}  // namespace

Material convertMaterial(const tinygltf::Material& m, int index, const std::vector<Texture>& textures,
                         std::vector<Texture>& baked, std::vector<std::string>& warnings) {
  Material out;
  const auto& pbr = m.pbrMetallicRoughness;
  std::string name = "material " + std::to_string(index);
  readCoreFactors(m, name, out, warnings);
  out.doubleSided = m.doubleSided;
  out.baseColorTexture = convertTextureRef(pbr.baseColorTexture, textures, name + " baseColorTexture", warnings);
  out.metallicRoughnessTexture =
      convertTextureRef(pbr.metallicRoughnessTexture, textures, name + " metallicRoughnessTexture", warnings);
  out.normalTexture = convertTextureRef(m.normalTexture, textures, name + " normalTexture", warnings);
  out.emissiveTexture = convertTextureRef(m.emissiveTexture, textures, name + " emissiveTexture", warnings);
  // occlusionTexture is for rasterizers' ambient-occlusion approximations; a path tracer computes occlusion.
  if (m.alphaMode == "MASK")
    out.alphaMode = AlphaMode::Mask;
  else if (m.alphaMode == "BLEND")
    out.alphaMode = AlphaMode::Blend;
  else if (m.alphaMode != "OPAQUE")
    throw Error(name + ": alphaMode '" + m.alphaMode + "' is not OPAQUE, MASK or BLEND");
  applyMaterialExtensions(m, out, textures, name, warnings);
  if (auto sg = m.extensions.find("KHR_materials_pbrSpecularGlossiness"); sg != m.extensions.end() && sg->second.IsObject())
    applySpecularGlossiness(sg->second, out, textures, baked, name, warnings);
  if (m.extensions.count("KHR_materials_unlit")) makeUnlit(out);
  matchIndex(out);
  return out;
}

}  // namespace vkmc
