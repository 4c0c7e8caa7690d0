#version 460
#extension GL_GOOGLE_include_directive : require
// Texture lookups in the forms `vkmc bench-textures` compares (host/bench/texture_forms.cpp). Invocation i reads
// TestRay i: origin.xy the uv, direction.xyzw up to four texture indices as shading reads them (a material's
// base colour, metallic-roughness, normal and emissive slots; kNoTexture where absent), sRGB for the first and
// the last. It writes the sum of its lookups to hit i.
//   default: the renderer's form (textures.glsl): the texture pages sampled as images, filtered and
//            sRGB-decoded by the sampler
//   VKMC_TEXEL_BUFFER: the same pages' texels in a storage texel buffer, bilinear filtering in the kernel and
//            sRGB decoded per tap by pow (the renderer's form until 2026-11-28)
#include "common.glsl"
#include "textures.glsl"

layout(binding = BINDING_TEST_RAYS, std430) readonly buffer Lookups { TestRay lookups[]; };
layout(binding = BINDING_TEST_HITS, std430) writeonly buffer Results { vec4 results[]; };

#ifdef VKMC_TEXEL_BUFFER
layout(binding = BINDING_TEXTURE_TEXELS, TEXEL_FORMAT_TEXTURE_TEXELS) uniform readonly uimageBuffer textureTexels;

vec4 pageTexel(uvec4 info, int x, int y, bool srgb) {
  ivec2 size = ivec2(texturePageSize(info));
  vec4 c = unpackUnorm4x8(imageLoad(textureTexels, (int(texturePage(info)) * size.y + y) * size.x + x).x);
  return srgb ? vec4(srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b), c.a) : c;
}

// The texel a filter reads lies within one texel of the texture's rectangle: in its gutter at worst.
vec4 texelBufferLookup(uint texture, vec2 uv, bool srgb) {
  uvec4 info = imageLoad(textureInfos, int(texture));
  uv = vec2(wrapUnit(uv.x, textureWrapS(info)), wrapUnit(uv.y, textureWrapT(info)));
  ivec2 o = ivec2(textureOrigin(info)), n = ivec2(textureExtent(info));
  if (textureNearest(info)) return pageTexel(info, o.x + nearestTexel(uv.x, n.x), o.y + nearestTexel(uv.y, n.y), srgb);
  float fx, fy;
  int x = o.x + bilinearLow(uv.x, n.x, fx), y = o.y + bilinearLow(uv.y, n.y, fy);
  vec4 top = mix(pageTexel(info, x, y, srgb), pageTexel(info, x + 1, y, srgb), fx);
  vec4 bottom = mix(pageTexel(info, x, y + 1, srgb), pageTexel(info, x + 1, y + 1, srgb), fx);
  return mix(top, bottom, fy);
}
#endif

vec4 lookup(uint texture, vec2 uv, bool srgb) {
  if (texture == kNoTexture) return vec4(0.0);
#ifdef VKMC_TEXEL_BUFFER
  return texelBufferLookup(texture, uv, srgb);
#else
  return sampleTexture(texture, uv, srgb);
#endif
}

void main() {
  uint i = invocationIndex();
  if (i >= pc.pathCount) return;
  TestRay r = lookups[i];
  uvec4 slots = floatBitsToUint(r.direction);
  results[i] = lookup(slots.x, r.origin.xy, true) + lookup(slots.y, r.origin.xy, false) +
               lookup(slots.z, r.origin.xy, false) + lookup(slots.w, r.origin.xy, true);
}
