// Texture lookups and the per-corner attributes they need (texture_layout.h). Only kernels of scenes with
// textures or vertex colours (SPEC_HAS_TEXTURES) run this code; the host twin is host/scene/texture_sampler.cpp.
#ifndef VKMC_TEXTURES_GLSL
#define VKMC_TEXTURES_GLSL

layout(binding = BINDING_TEXTURE_PAGES) uniform sampler2DArray texturePages[kTexturePageViews];

// Where uv lands in the texture pages: folded into one period of the texture's wrap modes (texture_layout.h),
// then into the texture's rectangle of its page; the page's gutters give what the wrap modes put past the edges.
// NEAREST textures land on the centre of their texel, where the bilinear sampler returns that texel alone (one
// sampler for both filters: a second, nearest one behind a branch cost llvmpipe most of the images' gain).
vec3 texturePageCoordinate(uvec4 info, vec2 uv) {
  uv = vec2(wrapUnit(uv.x, textureWrapS(info)), wrapUnit(uv.y, textureWrapT(info)));
  vec2 texel = vec2(textureOrigin(info)) + uv * vec2(textureExtent(info));
  if (textureNearest(info)) texel = floor(texel) + 0.5;
  return vec3(texel / vec2(texturePageSize(info)), float(texturePage(info)));
}

// The filtered texture at uv, bilinear (in linear space: the SRGB view decodes before filtering) or nearest.
vec4 sampleTexture(uint texture, vec2 uv, bool srgb) {
  vec3 at = texturePageCoordinate(imageLoad(textureInfos, int(texture)), uv);
  return srgb ? textureLod(texturePages[kTexturePageSrgb], at, 0.0) : textureLod(texturePages[kTexturePageUnorm], at, 0.0);
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
  if (kHasNormalMaps != 0u || kHasAnisotropy != 0u) {  // the tangent frame: a normal map's, an anisotropy's direction
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
  Material m = loadMaterial(triangleInfoMaterial(info));
  float alpha = kHasTextures != 0u ? baseColorAt(m, attributesAt(tri, vec3(1.0 - b12.x - b12.y, b12))).a : m.baseColor.a;
  if ((m.flags & kMaterialAlphaMask) != 0u) return alpha >= m.alphaCutoff;
  return randomUnit(rayKey, tri) < alpha;
}
#endif
