// Feature scan.
#include "scene/scene_features.h"

#include "microfacet.h"

namespace vkmc {

const char* SceneFeatures::sizeClass() const { return triangles < 1000 ? "small" : triangles < 100000 ? "medium" : "large"; }

std::vector<std::string> SceneFeatures::unsupported() const {
  std::vector<std::string> out;
  return out;
}

SceneFeatures scanFeatures(const Scene& scene) {
  SceneFeatures f;
  f.triangles = static_cast<uint32_t>(scene.triangleCount());
  f.materials = static_cast<uint32_t>(scene.materials.size());
  std::vector<bool> used(scene.materials.size(), false);
  for (uint32_t m : scene.materialIds) used[m] = true;
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    if (!used[i]) continue;
    const Material& m = scene.materials[i];
    f.glossy |= m.metallic > 0.0f || m.specular > 0.0f || m.transmission > 0.0f || m.clearcoat > 0.0f || m.hasSheen() ||
                m.hasIridescence();
    f.metallic |= m.metallic > 0.0f;
    f.nonDefaultSpecular |= m.specular != 1.0f;
    f.doubleSided |= m.doubleSided;
    f.singleSided |= m.culledFromBehind();
    f.textures |= m.textured();
    f.normalMaps |= m.normalTexture.present();
    f.alpha |= m.alphaMode != AlphaMode::Opaque;
    f.transmission |= m.transmission > 0.0f;
    f.volumes |= m.transmission > 0.0f && m.volumetric;
    f.clearcoat |= m.clearcoat > 0.0f;
    f.sheen |= m.hasSheen();
    f.iridescence |= m.hasIridescence();
    bool baseSpecular = m.metallic > 0.0f || m.specular > 0.0f || m.transmission > 0.0f;
    f.anisotropy |= m.hasAnisotropy() && baseSpecular;
    f.dispersion |= m.hasDispersion();
    f.textures |= m.hasAnisotropy() && baseSpecular;  // the tangent frame is read with the texture coordinates
    // Textures only scale roughness down: a roughness texture can make any lobe smooth.
    auto canBeSmooth = [](float roughness, const TextureRef& texture) {
      return roughness * roughness < gpu::kDeltaAlpha || texture.present();
    };
    f.delta |= baseSpecular && canBeSmooth(m.roughness, m.metallicRoughnessTexture);
    f.delta |= m.clearcoat > 0.0f && canBeSmooth(m.clearcoatRoughness, m.clearcoatRoughnessTexture);
  }
  f.textures |= !scene.colors.empty();
  for (uint32_t m : scene.materialIds) f.emissiveTriangles += scene.materials[m].isEmissive() ? 1 : 0;
  f.punctualLights = static_cast<uint32_t>(scene.punctualLights.size());
  f.environment = scene.environment.has_value();
  return f;
}

SceneFeatures allFeatures(const SceneFeatures& scene) {
  SceneFeatures f = scene;
  f.glossy = true;
  f.metallic = true;
  f.emissiveTriangles = std::max(f.emissiveTriangles, 1u);
  f.textures = true;
  f.normalMaps = true;
  f.alpha = true;
  f.singleSided = true;
  f.transmission = true;
  f.volumes = true;
  f.clearcoat = true;
  f.sheen = true;
  f.iridescence = true;
  f.anisotropy = true;
  f.dispersion = true;
  f.delta = true;
  f.punctualLights = std::max(f.punctualLights, 1u);
  f.environment = true;
  f.deepWalks = true;
  f.registerStackEntries = 12;
  return f;
}

}  // namespace vkmc
