// Texture lookups and the per-corner attributes they need (texture_layout.h). Only kernels of scenes with
// textures or vertex colours (SPEC_HAS_TEXTURES) run this code; the host twin is host/scene/texture_sampler.cpp.
#ifndef VKMC_TEXTURES_GLSL
#define VKMC_TEXTURES_GLSL

// RGBA of texel (x, y), each in [-1, n] (wrapUnit's folded range), under the texture's wrap modes; rgb decoded
// from sRGB when asked.
vec4 textureTexel(uvec4 info, int x, int y, bool srgb) {
  int w = int(info.y), h = int(info.z);
  x = wrapNearTexel(x, w, textureWrapS(info));
  y = wrapNearTexel(y, h, textureWrapT(info));
  vec4 c = unpackUnorm4x8(imageLoad(textureTexels, int(info.x) + y * w + x).x);
  if (srgb) c.rgb = vec3(srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b));
  return c;
}

// The filtered texture at uv: bilinear over decoded texels (filtering happens in linear space), or nearest.
vec4 sampleTexture(uint texture, vec2 uv, bool srgb) {
  uvec4 info = imageLoad(textureInfos, int(texture));
  uv = vec2(wrapUnit(uv.x, textureWrapS(info)), wrapUnit(uv.y, textureWrapT(info)));
  if (textureNearest(info)) return textureTexel(info, nearestTexel(uv.x, int(info.y)), nearestTexel(uv.y, int(info.z)), srgb);
  float fx, fy;
  int x = bilinearLow(uv.x, int(info.y), fx), y = bilinearLow(uv.y, int(info.z), fy);
  vec4 top = mix(textureTexel(info, x, y, srgb), textureTexel(info, x + 1, y, srgb), fx);
  vec4 bottom = mix(textureTexel(info, x, y + 1, srgb), textureTexel(info, x + 1, y + 1, srgb), fx);
  return mix(top, bottom, fy);
}

// Interpolated attributes of a triangle at barycentrics b.
struct SurfaceAttributes {
  vec2 uv0, uv1;
  vec4 color;    // COLOR_0 (1 where absent)
  vec4 tangent;  // world-space tangent (unnormalized interpolation), w: bitangent sign
};

SurfaceAttributes attributesAt(uint tri, vec3 b) {
  int base = int(kAttributeTexels * tri);
  SurfaceAttributes a;
  a.uv0 = vec2(0.0);
  a.uv1 = vec2(0.0);
  a.color = vec4(1.0);
  a.tangent = vec4(0.0, 0.0, 0.0, 1.0);
  // General pipelines (all features on) also run on scenes whose attributes were never uploaded.
  if (base + int(kAttributeTexels) > imageSize(triangleAttributes)) return a;
  uvec4 t0 = imageLoad(triangleAttributes, base), t1 = imageLoad(triangleAttributes, base + 1);
  uvec4 t2 = imageLoad(triangleAttributes, base + 2);
  a.uv0 = b.x * decodeUv(t0, 0u) + b.y * decodeUv(t0, 1u) + b.z * decodeUv(t1, 2u);
  a.uv1 = b.x * decodeUv(t1, 3u) + b.y * decodeUv(t2, 4u) + b.z * decodeUv(t2, 5u);
  uvec4 colors = imageLoad(triangleAttributes, base + 4);
  a.color = b.x * decodeColor(colors, 0u) + b.y * decodeColor(colors, 1u) + b.z * decodeColor(colors, 2u);
  if (kHasNormalMaps != 0u) {
    uvec4 tangents = imageLoad(triangleAttributes, base + 3);
    vec4 k0 = decodeTangent(tangents, 0u), k1 = decodeTangent(tangents, 1u), k2 = decodeTangent(tangents, 2u);
    a.tangent = vec4(b.x * k0.xyz + b.y * k1.xyz + b.z * k2.xyz, k0.w);
  }
  return a;
}

// A slot's texture coordinate: its set, then its KHR_texture_transform.
vec2 slotUv(TextureSlot slot, SurfaceAttributes a) {
  vec3 uv = vec3(slot.texCoord == 0u ? a.uv0 : a.uv1, 1.0);
  return vec2(dot(slot.uvRow0.xyz, uv), dot(slot.uvRow1.xyz, uv));
}

bool hasTexture(TextureSlot slot) { return kHasTextures != 0u && slot.texture != kNoTexture; }

// baseColor (rgb) and alpha: factor x texture x COLOR_0.
vec4 baseColorAt(Material m, SurfaceAttributes a) {
  vec4 c = m.baseColor;
  if (kHasTextures == 0u) return c;
  if (hasTexture(m.baseColorTexture)) c *= sampleTexture(m.baseColorTexture.texture, slotUv(m.baseColorTexture, a), true);
  return c * a.color;
}

// Whether a ray meets the surface of an alpha-tested triangle at barycentrics b12: MASK compares alpha with the
// cutoff; BLEND keeps the surface with probability alpha (stochastic transparency, unbiased for the blend),
// deciding by a hash of the ray's key and the triangle so the answer is the same whenever the walk asks again.
bool surfacePresent(uint tri, vec2 b12, uint rayKey) {
  uvec4 info = imageLoad(triangleInfo, int(tri));
  if (!triangleInfoAlphaTested(info)) return true;
  Material m = materials[triangleInfoMaterial(info)];
  float alpha = kHasTextures != 0u ? baseColorAt(m, attributesAt(tri, vec3(1.0 - b12.x - b12.y, b12))).a : m.baseColor.a;
  if ((m.flags & kMaterialAlphaMask) != 0u) return alpha >= m.alphaCutoff;
  return randomUnit(rayKey, tri) < alpha;
}
#endif
