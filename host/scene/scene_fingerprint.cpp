// Every field a render reads, hashed field by field (structs have padding; vectors of glm types do not).
#include "scene/scene_fingerprint.h"

#include "scene/content_hash.h"

namespace vkmc {
namespace {

void addTextureRef(ContentHash& h, const TextureRef& t) {
  h.addValue(uint64_t(int64_t(t.texture))), h.addValue(uint64_t(t.texCoord));
  const float v[7] = {t.uvRow0.x, t.uvRow0.y, t.uvRow0.z, t.uvRow1.x, t.uvRow1.y, t.uvRow1.z, t.scale};
  h.add(v, sizeof(v));
}

}  // namespace

uint64_t sceneFingerprint(const Scene& s) {
  ContentHash h;
  h.add(s.positions), h.add(s.normals), h.add(s.uv0), h.add(s.uv1), h.add(s.tangents), h.add(s.colors);
  h.add(s.materialIds);
  for (const Material& m : s.materials) {
    const float v[11] = {m.baseColor.x, m.baseColor.y, m.baseColor.z, m.alpha,    m.emission.x, m.emission.y,
                         m.emission.z,  m.metallic,    m.roughness,   m.specular, m.alphaCutoff};
    h.add(v, sizeof(v));
    h.addValue(uint64_t(m.doubleSided) | uint64_t(m.alphaMode) << 8);
    const float ext[16] = {m.specularColor.x, m.specularColor.y,    m.specularColor.z,   m.ior,
                           m.transmission,    m.attenuation.x,      m.attenuation.y,     m.attenuation.z,
                           m.clearcoat,       m.clearcoatRoughness, m.sheenColor.x,      m.sheenColor.y,
                           m.sheenColor.z,    m.sheenRoughness,     float(m.volumetric), 0.0f};
    h.add(ext, sizeof(ext));
    // The film and the anisotropy only where they are, so a scene without them keeps the fingerprint older
    // checkpoints recorded.
    for (const TextureRef* t : m.textureRefs())
      if (t != &m.iridescenceTexture && t != &m.iridescenceThicknessTexture && t != &m.anisotropyTexture) addTextureRef(h, *t);
    if (m.iridescence > 0.0f) {
      const float film[4] = {m.iridescence, m.iridescenceIor, m.iridescenceThicknessMin, m.iridescenceThicknessMax};
      h.add(film, sizeof(film));
      addTextureRef(h, m.iridescenceTexture), addTextureRef(h, m.iridescenceThicknessTexture);
    }
    if (m.dispersion > 0.0f) h.add(&m.dispersion, sizeof(m.dispersion));
    if (m.hasAnisotropy()) {
      const float stretch[2] = {m.anisotropyStrength, m.anisotropyRotation};
      h.add(stretch, sizeof(stretch));
      addTextureRef(h, m.anisotropyTexture);
    }
  }
  for (const Texture& t : s.textures) {
    h.addValue(uint64_t(t.width) << 32 | t.height);
    h.addValue(uint64_t(t.wrapS) | uint64_t(t.wrapT) << 8 | uint64_t(t.nearest) << 16);
    h.add(t.texels);
  }
  for (const Camera& c : s.cameras) {
    const float v[14] = {c.position.x,
                         c.position.y,
                         c.position.z,
                         c.forward.x,
                         c.forward.y,
                         c.forward.z,
                         c.up.x,
                         c.up.y,
                         c.up.z,
                         c.yfov,
                         c.aspectRatio.value_or(0.0f),
                         c.xmag,
                         c.ymag,
                         float(c.kind)};
    h.add(v, sizeof(v));
  }
  for (const PunctualLight& l : s.punctualLights) {
    const float v[12] = {l.position.x,  l.position.y,  l.position.z,  l.direction.x,    l.direction.y,    l.direction.z,
                         l.intensity.x, l.intensity.y, l.intensity.z, l.innerConeAngle, l.outerConeAngle, float(l.kind)};
    h.add(v, sizeof(v));
  }
  if (s.environment) {
    h.addValue(uint64_t(s.environment->width) << 32 | s.environment->height);
    h.add(s.environment->radiance);
    h.add(&s.environment->rotationDegrees, sizeof(float));
  }
  return h.value();
}

}  // namespace vkmc
