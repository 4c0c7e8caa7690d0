#include "scene/gltf_material_extensions.h"

#include <tiny_gltf.h>

#include <cmath>
#include <limits>

#include "error.h"
#include "scene/gltf_textures.h"

namespace vkmc {
namespace {

// One extension object's fields, with errors that name the material, the extension and the key.
class ExtensionReader {
 public:
  ExtensionReader(const tinygltf::Value& v, std::string what, const std::vector<Texture>& textures,
                  std::vector<std::string>& warnings)
      : v_(v), what_(std::move(what)), textures_(textures), warnings_(warnings) {}

  float number(const char* key, double fallback, double lo, double hi) const {
    if (!v_.Has(key)) return float(fallback);
    const tinygltf::Value& x = v_.Get(key);
    if (!x.IsNumber() || !std::isfinite(x.GetNumberAsDouble())) throw Error(what_ + "." + key + " is not a finite number");
    double d = x.GetNumberAsDouble();
    if (d < lo || d > hi)
      throw Error(what_ + "." + key + " = " + std::to_string(d) + " is outside [" + std::to_string(lo) + ", " +
                  std::to_string(hi) + "]");
    return float(d);
  }

  glm::vec3 color(const char* key, glm::vec3 fallback) const {
    if (!v_.Has(key)) return fallback;
    const tinygltf::Value& x = v_.Get(key);
    if (!x.IsArray() || x.ArrayLen() != 3) throw Error(what_ + "." + key + " is not an array of 3 numbers");
    glm::vec3 c;
    for (int i = 0; i < 3; ++i) {
      const tinygltf::Value& e = x.Get(i);
      if (!e.IsNumber() || !std::isfinite(e.GetNumberAsDouble()) || e.GetNumberAsDouble() < 0.0 || e.GetNumberAsDouble() > 1.0)
        throw Error(what_ + "." + key + " has a component that is not a number in [0, 1]");
      c[i] = float(e.GetNumberAsDouble());
    }
    return c;
  }

  TextureRef texture(const char* key) const {
    if (!v_.Has(key)) return {};
    return convertTextureRef(v_.Get(key), textures_, what_ + "." + key, warnings_);
  }

 private:
  const tinygltf::Value& v_;
  std::string what_;
  const std::vector<Texture>& textures_;
  std::vector<std::string>& warnings_;
};

const tinygltf::Value* extension(const tinygltf::Material& gltf, const char* name) {
  auto it = gltf.extensions.find(name);
  return it != gltf.extensions.end() && it->second.IsObject() ? &it->second : nullptr;
}

// KHR_materials_iridescence, _anisotropy and _dispersion: a film on the base's Fresnel terms, its specular lobe
// stretched along a direction in the tangent plane, and its volume's ior by wavelength.
template <class Reader>
void applyFilmAndAnisotropy(const tinygltf::Material& gltf, Material& m, const Reader& reader) {
  constexpr double kHuge = std::numeric_limits<double>::max();
  if (const tinygltf::Value* v = extension(gltf, "KHR_materials_iridescence")) {
    ExtensionReader r = reader(*v, "KHR_materials_iridescence");
    m.iridescence = r.number("iridescenceFactor", 0.0, 0.0, 1.0);
    // The ratified spelling, or the draft's (files written before ratification use it).
    m.iridescenceIor = r.number(v->Has("iridescenceIor") ? "iridescenceIor" : "iridescenceIOR", 1.3, 1.0, kHuge);
    m.iridescenceThicknessMin = r.number("iridescenceThicknessMinimum", 100.0, 0.0, kHuge);
    m.iridescenceThicknessMax = r.number("iridescenceThicknessMaximum", 400.0, 0.0, kHuge);
    m.iridescenceTexture = r.texture("iridescenceTexture");
    m.iridescenceThicknessTexture = r.texture("iridescenceThicknessTexture");
    // Without a thickness texture the film is iridescenceThicknessMaximum thick (the extension's rule).
    if (!m.iridescenceThicknessTexture.present()) m.iridescenceThicknessMin = m.iridescenceThicknessMax;
  }
  if (const tinygltf::Value* v = extension(gltf, "KHR_materials_anisotropy")) {
    ExtensionReader r = reader(*v, "KHR_materials_anisotropy");
    m.anisotropyStrength = r.number("anisotropyStrength", 0.0, 0.0, 1.0);
    m.anisotropyRotation = r.number("anisotropyRotation", 0.0, -kHuge, kHuge);  // radians, from the tangent toward the bitangent
    m.anisotropyTexture = r.texture("anisotropyTexture");
  }
  if (const tinygltf::Value* v = extension(gltf, "KHR_materials_dispersion"))
    m.dispersion = reader(*v, "KHR_materials_dispersion").number("dispersion", 0.0, 0.0, kHuge);
}

}  // namespace

void applyMaterialExtensions(const tinygltf::Material& gltf, Material& m, const std::vector<Texture>& textures,
                             const std::string& name, std::vector<std::string>& warnings) {
  constexpr double kHuge = std::numeric_limits<double>::max();
  auto reader = [&](const tinygltf::Value& v, const char* ext) {
    return ExtensionReader(v, name + " " + ext, textures, warnings);
  };
  if (const tinygltf::Value* v = extension(gltf, "KHR_materials_specular")) {
    ExtensionReader r = reader(*v, "KHR_materials_specular");
    m.specular = r.number("specularFactor", 1.0, 0.0, 1.0);
    m.specularColor = glm::vec3(1.0f);
    if (v->Has("specularColorFactor")) {  // may exceed 1 (the spec's f0 is clamped after scaling by (ior-1)^2/(ior+1)^2)
      const tinygltf::Value& c = v->Get("specularColorFactor");
      if (!c.IsArray() || c.ArrayLen() != 3) throw Error(name + " KHR_materials_specular.specularColorFactor is not 3 numbers");
      for (int i = 0; i < 3; ++i) {
        double x = c.Get(i).IsNumber() ? c.Get(i).GetNumberAsDouble() : -1.0;
        if (!std::isfinite(x) || x < 0.0 || x > 1e6)
          throw Error(name + " KHR_materials_specular.specularColorFactor has a component that is not a number in [0, 1e6]");
        m.specularColor[i] = float(x);
      }
    }
    m.specularTexture = r.texture("specularTexture");
    m.specularColorTexture = r.texture("specularColorTexture");
  }
  if (const tinygltf::Value* v = extension(gltf, "KHR_materials_ior")) {
    // The spec bounds ior below only (1, or 0 for backward compatibility: as 1). Above kLargestIor a dielectric's
    // F0 differs from 1 by under 4e-4, and larger values would overflow (ior + 1)^2 in float: rendered as that.
    constexpr double kLargestIor = 1e4;
    float ior = reader(*v, "KHR_materials_ior").number("ior", 1.5, 0.0, std::numeric_limits<float>::max());
    if (ior != 0.0f && ior < 1.0f) throw Error(name + " KHR_materials_ior.ior = " + std::to_string(ior) + " is below 1");
    m.ior = ior == 0.0f ? 1.0f : float(std::min<double>(ior, kLargestIor));
  }
  if (const tinygltf::Value* v = extension(gltf, "KHR_materials_transmission")) {
    ExtensionReader r = reader(*v, "KHR_materials_transmission");
    m.transmission = r.number("transmissionFactor", 0.0, 0.0, 1.0);
    m.transmissionTexture = r.texture("transmissionTexture");
  }
  if (const tinygltf::Value* v = extension(gltf, "KHR_materials_volume")) {
    // A path tracer has the mesh itself: thickness only says whether the volume is there (thicknessTexture, a
    // rasterizer's estimate of the distance through it, is not needed).
    ExtensionReader r = reader(*v, "KHR_materials_volume");
    m.volumetric = r.number("thicknessFactor", 0.0, 0.0, kHuge) > 0.0f;
    float distance = r.number("attenuationDistance", kHuge, 0.0, kHuge);
    glm::vec3 color = r.color("attenuationColor", glm::vec3(1.0f));
    if (v->Has("attenuationDistance") && !(distance > 0.0f))
      throw Error(name + " KHR_materials_volume.attenuationDistance must be positive");
    // A colour component of 0 absorbs everything: as 1e-6 of the light left after one attenuationDistance.
    for (int i = 0; i < 3; ++i) m.attenuation[i] = float(-std::log(std::max(double(color[i]), 1e-6)) / double(distance));
  }
  if (const tinygltf::Value* v = extension(gltf, "KHR_materials_clearcoat")) {
    ExtensionReader r = reader(*v, "KHR_materials_clearcoat");
    m.clearcoat = r.number("clearcoatFactor", 0.0, 0.0, 1.0);
    m.clearcoatRoughness = r.number("clearcoatRoughnessFactor", 0.0, 0.0, 1.0);
    m.clearcoatTexture = r.texture("clearcoatTexture");
    m.clearcoatRoughnessTexture = r.texture("clearcoatRoughnessTexture");
    m.clearcoatNormalTexture = r.texture("clearcoatNormalTexture");
  }
  if (const tinygltf::Value* v = extension(gltf, "KHR_materials_sheen")) {
    ExtensionReader r = reader(*v, "KHR_materials_sheen");
    m.sheenColor = r.color("sheenColorFactor", glm::vec3(0.0f));
    m.sheenRoughness = r.number("sheenRoughnessFactor", 0.0, 0.0, 1.0);
    m.sheenColorTexture = r.texture("sheenColorTexture");
    m.sheenRoughnessTexture = r.texture("sheenRoughnessTexture");
  }
  applyFilmAndAnisotropy(gltf, m, reader);
  if (m.transmission > 0.0f && !m.volumetric && m.attenuation != glm::vec3(0.0f))
    warnings.push_back(name + ": KHR_materials_volume attenuation without a thickness is ignored (the surface is thin-walled)");
  if (m.dispersion > 0.0f && !m.hasDispersion())
    warnings.push_back(name + ": KHR_materials_dispersion without transmission into a KHR_materials_volume is ignored");
}

}  // namespace vkmc
