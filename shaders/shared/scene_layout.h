// The scene texels: the host writes them (host/render/gpu_scene.cpp), the kernels read them (common.glsl,
// shading.glsl). Encode and decode side by side; both languages compile this file.
//   triangles (BINDING_TRIANGLES, RGBA32F): kTriangleTexels per triangle, the vertices in xyz; texel
//       kTriangleLightPmfTexel's w holds the triangle's light-selection pmf (0 unless it emits), texel
//       kTriangleSidesTexel's w is 1 when the triangle is single-sided (culled from the back), else 0; texel
//       kTrianglePartnerTexel's w names the other half of an emitter quad (render/emitter_pairs.h) on the
//       pair's first triangle, as the float 4 (partner + 1) + apex (exact: partners below 2^22), else 0
//   triangle info (BINDING_TRIANGLE_INFO, RGBA32UI): one texel per triangle, the three vertex normals
//       (octahedral, 2 x 16-bit snorm each) and the material id, whose top bit says the material is alpha-tested
//   lights (BINDING_LIGHTS, RGBA32UI): one alias-table entry per light (Walker/Vose), emissive triangles,
//       punctual lights and the environment chosen together in proportion to power:
//       (keep probability as float bits, alias slot, kind << kLightKindShift | index, selection pmf as float bits)
#ifndef VKMC_SCENE_LAYOUT_H
#define VKMC_SCENE_LAYOUT_H
#include "glsl_cpp.h"
VKMC_BEGIN_NAMESPACE

VKMC_CONST uint kTriangleTexels = 3u;
VKMC_CONST uint kTriangleLightPmfTexel = 1u;
// glTF's doubleSided false: only the front face is there (spec 3.9.5, back-face culling), so a ray that meets
// the back passes. Kept beside the vertices, which the walk loads anyway.
VKMC_CONST uint kTriangleSidesTexel = 0u;
VKMC_FN float encodeTriangleSingleSided(bool singleSided) { return singleSided ? 1.0f : 0.0f; }
// An emitter quad's first triangle names its second and its own corner opposite the shared edge; the light
// table's entry for the pair names the first (with the pair's pmf, twice each triangle's).
VKMC_CONST uint kTrianglePartnerTexel = 2u;
VKMC_CONST uint kMaxEmitterPartner = (1u << 22u) - 2u;
VKMC_FN float encodeEmitterPartner(uint partner, uint apex) { return float(((partner + 1u) << 2u) | apex); }
VKMC_FN bool hasEmitterPartner(float code) { return code >= 4.0f; }
VKMC_FN uint emitterPartner(float code) { return (uint(code) >> 2u) - 1u; }
VKMC_FN uint emitterApex(float code) { return uint(code) & 3u; }
VKMC_FN bool triangleSingleSided(vec4 sidesTexel) { return sidesTexel.w != 0.0f; }

// Octahedral unit vectors (Cigolle et al. 2014) in 2 x 16-bit snorm.
VKMC_FN uint encodeOctahedral(vec3 n) {
  n /= (abs(n.x) + abs(n.y) + abs(n.z));
  vec2 e = vec2(n.x, n.y);
  if (n.z < 0.0f) {
    vec2 s = vec2(n.x >= 0.0f ? 1.0f : -1.0f, n.y >= 0.0f ? 1.0f : -1.0f);
    e = (1.0f - abs(vec2(n.y, n.x))) * s;
  }
  return packSnorm2x16(e);
}
VKMC_FN vec3 decodeOctahedral(uint bits) {
  vec2 e = unpackSnorm2x16(bits);
  vec3 v = vec3(e.x, e.y, 1.0f - abs(e.x) - abs(e.y));
  if (v.z < 0.0f) {
    vec2 s = vec2(v.x >= 0.0f ? 1.0f : -1.0f, v.y >= 0.0f ? 1.0f : -1.0f);
    v = vec3((1.0f - abs(vec2(v.y, v.x))) * s, v.z);
  }
  return normalize(v);
}

VKMC_CONST uint kTriangleAlphaTested = 0x80000000u;  // MASK or BLEND: the walks test the triangle's alpha

VKMC_FN uvec4 encodeTriangleInfo(vec3 n0, vec3 n1, vec3 n2, uint material, bool alphaTested) {
  return uvec4(encodeOctahedral(n0), encodeOctahedral(n1), encodeOctahedral(n2),
               material | (alphaTested ? kTriangleAlphaTested : 0u));
}
VKMC_FN uint triangleInfoMaterial(uvec4 info) { return info.w & ~kTriangleAlphaTested; }
VKMC_FN bool triangleInfoAlphaTested(uvec4 info) { return (info.w & kTriangleAlphaTested) != 0u; }
// The shading normal at barycentrics b, unnormalized (the interpolation of the decoded vertex normals).
VKMC_FN vec3 triangleInfoNormal(uvec4 info, vec3 b) {
  return b.x * decodeOctahedral(info.x) + b.y * decodeOctahedral(info.y) + b.z * decodeOctahedral(info.z);
}

// What a light entry's index names: a triangle (BVH order), a PunctualLight, or the environment (index 0).
VKMC_CONST uint kLightKindTriangle = 0u, kLightKindPunctual = 1u, kLightKindEnvironment = 2u;
VKMC_CONST uint kLightKindShift = 30u;
VKMC_CONST uint kLightIndexMask = (1u << kLightKindShift) - 1u;  // triangles and punctual lights below 2^30

VKMC_FN uvec4 encodeLightEntry(float keepProbability, uint alias, uint kind, uint index, float pmf) {
  return uvec4(floatBitsToUint(keepProbability), alias, (kind << kLightKindShift) | (index & kLightIndexMask),
               floatBitsToUint(pmf));
}
VKMC_FN uint lightEntryKind(uvec4 entry) { return entry.z >> kLightKindShift; }
VKMC_FN uint lightEntryIndex(uvec4 entry) { return entry.z & kLightIndexMask; }
VKMC_FN float lightEntryPmf(uvec4 entry) { return uintBitsToFloat(entry.w); }
// The alias pick of u in [0, 1) among n entries: scaled = u n selects the slot, whose entry keeps it when the
// fraction is below its keep probability and sends it to its alias otherwise.
VKMC_FN uint aliasSlot(float scaled, uint n) { return min(uint(scaled), n - 1u); }
VKMC_FN uint aliasChoice(float scaled, uint slot, uvec4 slotEntry) {
  return (scaled - float(slot)) < uintBitsToFloat(slotEntry.x) ? slot : slotEntry.y;
}

VKMC_END_NAMESPACE
#endif
