// Textures and per-triangle shading attributes on the device: the host writes them (host/render/gpu_textures.cpp,
// host/render/texture_atlas.cpp), the kernels read them (shaders/include/textures.glsl). Encode and decode side by
// side; both languages compile it.
//   texture pages (BINDING_TEXTURE_PAGES): every texture in the square pages (layers; a lone page trimmed to
//       what it uses) of one RGBA8 2D array image, each inside a one-texel gutter holding the texels its wrap
//       modes reach beyond its edges; a UNORM and an SRGB view (kTexturePage*), sampled bilinearly, clamped to
//       the page. The kernel folds a uv into one period of its wrap modes (wrapUnit), so a filter reading at most
//       one texel past an edge finds what the wrap modes give. Sampled so, DamagedHelmet renders 1.05x the
//       samples/s of filtering in the kernel on llvmpipe (docs/journal/performance.md, "Textures on the device")
//   textures (BINDING_TEXTURES, RGBA32UI): one texel per glTF texture: x: its texel (0, 0) in the page,
//       px | py << 16; y: width | height << 16; z: page | wrapS << 16 | wrapT << 18 | nearest flag; w: the
//       pages' width | height << 16
//   texture texels (BINDING_TEXTURE_TEXELS, R32UI): the pages' texels (packUnorm4x8) page by page, row-major
//       from the top row: the form `vkmc bench-textures` compares with (filtered by textureTexelBuffer* below)
//   triangle attributes (BINDING_TRIANGLE_ATTRIBUTES, RGBA32UI): kAttributeTexels per triangle (BVH order):
//       uv0 of the 3 corners, uv1 of the 3 corners (float bits, 6 + 6 words), 3 octahedral tangents with
//       their bitangent signs, 3 RGBA8 vertex colours
#ifndef VKMC_TEXTURE_LAYOUT_H
#define VKMC_TEXTURE_LAYOUT_H
#include "glsl_cpp.h"
#include "scene_layout.h"
VKMC_BEGIN_NAMESPACE

VKMC_CONST uint kWrapRepeat = 0u, kWrapClampToEdge = 1u, kWrapMirroredRepeat = 2u;
VKMC_CONST uint kTextureNearest = 1u << 20u;  // info.z bit: magFilter NEAREST (else bilinear)
VKMC_CONST uint kAttributeTexels = 5u;
// The views of the texture pages in BINDING_TEXTURE_PAGES's array, both sampled bilinearly.
VKMC_CONST uint kTexturePageUnorm = 0u, kTexturePageSrgb = 1u, kTexturePageViews = 2u;

VKMC_FN uvec4 encodeTextureInfo(uint pageX, uint pageY, uint page, uint width, uint height, uint pageWidth, uint pageHeight,
                                uint wrapS, uint wrapT, bool nearest) {
  return uvec4(pageX | (pageY << 16u), width | (height << 16u),
               page | (wrapS << 16u) | (wrapT << 18u) | (nearest ? kTextureNearest : 0u), pageWidth | (pageHeight << 16u));
}
VKMC_FN uvec2 textureOrigin(uvec4 info) { return uvec2(info.x & 0xffffu, info.x >> 16u); }
VKMC_FN uvec2 textureExtent(uvec4 info) { return uvec2(info.y & 0xffffu, info.y >> 16u); }
VKMC_FN uint texturePage(uvec4 info) { return info.z & 0xffffu; }
VKMC_FN uint textureWrapS(uvec4 info) { return (info.z >> 16u) & 3u; }
VKMC_FN uint textureWrapT(uvec4 info) { return (info.z >> 18u) & 3u; }
VKMC_FN bool textureNearest(uvec4 info) { return (info.z & kTextureNearest) != 0u; }
VKMC_FN uvec2 texturePageSize(uvec4 info) { return uvec2(info.w & 0xffffu, info.w >> 16u); }

// Wrapping without integer division (llvmpipe has no vector divide: a % per tap was most of the shade stage's
// time): u is first folded into one period of its wrap mode, [0, 1) for REPEAT and [0, 1] for MIRRORED_REPEAT
// (reflected) and CLAMP_TO_EDGE (clamped); the texels a filter then reads lie in [-1, n], which wrapNearTexel
// maps into [0, n) with compares: REPEAT wraps them round, MIRRORED_REPEAT reflects -1 to 0 and n to n - 1, and
// CLAMP_TO_EDGE clamps.
VKMC_FN float wrapUnit(float u, uint mode) {
  if (!(abs(u) < 1.0e9f)) u = 0.0f;  // NaN, infinities and uvs past float's integer precision
  if (mode == kWrapClampToEdge) return clamp(u, 0.0f, 1.0f);
  if (mode == kWrapMirroredRepeat) {
    float m = u - 2.0f * floor(0.5f * u);
    return m > 1.0f ? 2.0f - m : m;
  }
  return u - floor(u);
}
VKMC_FN int wrapNearTexel(int i, int n, uint mode) {
  if (mode == kWrapRepeat) return i < 0 ? i + n : (i >= n ? i - n : i);
  return clamp(i, 0, n - 1);
}

// Texel coordinate x (texel centres at i + 0.5) bounded so that int conversion stays defined; NaN becomes 0.
VKMC_FN float boundedTexelCoordinate(float x) { return x > -1.0e9f ? min(x, 1.0e9f) : (x <= -1.0e9f ? -1.0e9f : 0.0f); }

// The 2x2 bilinear footprint of coordinate u on an axis of n texels: the lower texel (unwrapped) and the
// weight of the upper one.
VKMC_FN int bilinearLow(float u, int n, INOUT(float) upperWeight) {
  float x = boundedTexelCoordinate(u * float(n) - 0.5f);
  float lo = floor(x);
  upperWeight = x - lo;
  return int(lo);
}
VKMC_FN int nearestTexel(float u, int n) { return int(floor(boundedTexelCoordinate(u * float(n)))); }

// The sRGB transfer function's inverse (IEC 61966-2-1), per channel.
VKMC_FN float srgbToLinear(float c) { return c <= 0.04045f ? c * (1.0f / 12.92f) : pow((c + 0.055f) * (1.0f / 1.055f), 2.4f); }

VKMC_FN uvec4 encodeUvTexel(vec2 a, vec2 b) {
  return uvec4(floatBitsToUint(a.x), floatBitsToUint(a.y), floatBitsToUint(b.x), floatBitsToUint(b.y));
}
// Texels 0-2 hold six uvs, two per texel: uv0 of corners 0-2, then uv1 of corners 0-2. Slot s = 3 set + corner
// lives in texel s / 2, in its upper half when s is odd.
VKMC_FN uint uvSlot(uint set, uint corner) { return set * 3u + corner; }
VKMC_FN vec2 decodeUv(uvec4 texel, uint slot) {
  return (slot & 1u) == 0u ? vec2(uintBitsToFloat(texel.x), uintBitsToFloat(texel.y))
                           : vec2(uintBitsToFloat(texel.z), uintBitsToFloat(texel.w));
}

VKMC_FN uvec4 encodeTangents(vec4 t0, vec4 t1, vec4 t2) {
  uint signs = (t0.w < 0.0f ? 1u : 0u) | (t1.w < 0.0f ? 2u : 0u) | (t2.w < 0.0f ? 4u : 0u);
  return uvec4(encodeOctahedral(vec3(t0)), encodeOctahedral(vec3(t1)), encodeOctahedral(vec3(t2)), signs);
}
VKMC_FN vec4 decodeTangent(uvec4 texel, uint corner) {
  uint bits = corner == 0u ? texel.x : (corner == 1u ? texel.y : texel.z);
  return vec4(decodeOctahedral(bits), ((texel.w >> corner) & 1u) != 0u ? -1.0f : 1.0f);
}

VKMC_FN uvec4 encodeColors(vec4 c0, vec4 c1, vec4 c2) { return uvec4(packUnorm4x8(c0), packUnorm4x8(c1), packUnorm4x8(c2), 0u); }
VKMC_FN vec4 decodeColor(uvec4 texel, uint corner) {
  return unpackUnorm4x8(corner == 0u ? texel.x : (corner == 1u ? texel.y : texel.z));
}

// Barycentrics (b1, b2) of a point p in the plane of triangle (v0, v1, v2): for light samples, whose
// emission may be textured.
VKMC_FN vec2 barycentricsOf(vec3 p, vec3 v0, vec3 v1, vec3 v2) {
  vec3 e1 = v1 - v0, e2 = v2 - v0, d = p - v0;
  float d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2), dp1 = dot(d, e1), dp2 = dot(d, e2);
  float den = d11 * d22 - d12 * d12;
  if (!(den > 0.0f)) return vec2(0.0f);
  return clamp(vec2(d22 * dp1 - d12 * dp2, d11 * dp2 - d12 * dp1) / den, vec2(0.0f), vec2(1.0f));
}

VKMC_END_NAMESPACE
#endif
