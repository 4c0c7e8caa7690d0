// The shading of one path vertex, shared by the wavefront's shade stage (shade.comp) and the megakernel
// (megakernel.comp), so both integrators run the same estimator code: the surface point, emission with its MIS
// weight, light samples as shadow rays, BSDF continuations with roulette. What differs is only where their
// results go: queues between dispatches, or the next iteration of one invocation's loop.
#include "bsdf_gltf.h"
#include "environment_map.h"
#include "light_sampling.h"
#include "punctual_light.h"
#include "mis.h"
#include "roulette.h"
#include "textures.glsl"

struct SurfacePoint {
  vec3 p;
  vec3 pError;
  vec3 ng;  // geometric normal, facing the incoming ray's side
  mat3 frame;  // shading frame; column 2 is the shading normal, on the side of ng
  bool frontFace;
  uint material;
  vec3 b;  // barycentrics
  SurfaceAttributes attributes;  // uvs, colour, tangent (scenes with textures or vertex colours)
  vec3 emission;  // emitted radiance here (factor x emissive texture), set by shadeSurface
};

SurfacePoint surfaceAt(uint tri, vec2 b12, vec3 wo) {
  vec3 v0, v1, v2;
  triangleVertices(tri, v0, v1, v2);
  vec3 b = vec3(1.0 - b12.x - b12.y, b12.x, b12.y);
  SurfacePoint s;
  s.p = b.x * v0 + b.y * v1 + b.z * v2;
  s.pError = barycentricError(b, v0, v1, v2);
  s.ng = normalize(scaledTriangleCross(v0, v1, v2).xyz);
  s.frontFace = dot(s.ng, wo) > 0.0;
  if (!s.frontFace) s.ng = -s.ng;
  uvec4 info = imageLoad(triangleInfo, int(tri));
  s.material = triangleInfoMaterial(info);
  s.b = b;
  vec3 n = triangleInfoNormal(info, b);
  float len = length(n);
  vec3 ns = len > 0.0 ? n / len : s.ng;
  if (dot(ns, s.ng) < 0.0) ns = -ns;
  s.frame = basisFromNormal(ns);
  s.emission = vec3(0.0);
  if (kHasTextures != 0u) s.attributes = attributesAt(tri, b);
  return s;
}

// The normal-mapped shading normal (tangent-space normal texture, glTF 3.9.3), on the side the unmapped one faces;
// the unmapped one where the mapped normal would fall below the geometric surface.
vec3 normalMapped(TextureSlot slot, SurfacePoint s) {
  vec3 n = s.frame[2];
  vec3 t = s.attributes.tangent.xyz - n * dot(n, s.attributes.tangent.xyz);
  float tl = length(t);
  if (!(tl > 0.0)) return n;
  t /= tl;
  vec3 bt = cross(n, t) * s.attributes.tangent.w;
  vec3 c = sampleTexture(slot.texture, slotUv(slot, s.attributes), false).rgb * 2.0 - 1.0;
  c.xy *= slot.uvRow0.w;
  vec3 mapped = normalize(t * c.x + bt * c.y + n * c.z);
  return dot(mapped, s.ng) > 0.0 ? mapped : n;
}

// A texture channel times its factor, or the factor alone without a texture.
float texturedFactor(float factor, TextureSlot slot, SurfacePoint s, uint channel) {
  if (kHasTextures == 0u || !hasTexture(slot)) return factor;
  return factor * sampleTexture(slot.texture, slotUv(slot, s.attributes), false)[channel];
}
vec3 texturedColor(vec3 factor, TextureSlot slot, SurfacePoint s) {
  if (kHasTextures == 0u || !hasTexture(slot)) return factor;
  return factor * sampleTexture(slot.texture, slotUv(slot, s.attributes), true).rgb;
}

// The material extensions at s (bsdf_gltf.h): specular colour and ior, transmission (refracting into a volume
// from a front face, out of it from a back face), clearcoat over the unmapped normal or its own normal map, sheen,
// and a thin film's iridescence.
void shadeExtensions(Material m, SurfacePoint s, vec3 unmappedNormal, inout GltfMaterial gm) {
  vec3 specularColor = texturedColor(m.specularColor.rgb, m.specularColorTexture, s);
  setIor(gm, m.specularColor.w, specularColor);
  if (kHasTransmission != 0u && m.attenuation.w > 0.0) {
    // An index-matched volume (ior 1) refracts as one of ior 1 + 1e-4: at exactly 1 every refraction gives wi = -wo,
    // where Walter's rough btdf has no half vector (NaN samples); 1e-4 bends no ray visibly, and the lobe tends to
    // the straight pass that ior 1 is. The Fresnel term keeps the file's ior (setIor above).
    float ior = max(m.specularColor.w, 1.0001);
    setTransmission(gm, texturedFactor(m.attenuation.w, m.transmissionTexture, s, 0u), s.frontFace ? ior : 1.0 / ior,
                    m.volumetric == 0u);
  }
  if (kHasClearcoat != 0u && m.clearcoat > 0.0) {
    vec3 n = unmappedNormal;
    if (kHasNormalMaps != 0u && hasTexture(m.clearcoatNormalTexture)) {
      SurfacePoint front = s;  // the tangent frame belongs to the front face, as in shadeSurface
      front.frame[2] = s.frontFace ? unmappedNormal : -unmappedNormal;
      n = normalMapped(m.clearcoatNormalTexture, front);
      if (!s.frontFace) n = -n;
    }
    setClearcoat(gm, texturedFactor(m.clearcoat, m.clearcoatTexture, s, 0u),
                 texturedFactor(m.clearcoatRoughness, m.clearcoatRoughnessTexture, s, 1u), normalize(n * s.frame));
  }
  if (kHasSheen != 0u && maxComponent(m.sheen.rgb) > 0.0)
    setSheen(gm, texturedColor(m.sheen.rgb, m.sheenColorTexture, s), texturedFactor(m.sheen.w, m.sheenRoughnessTexture, s, 3u));
  if (kHasIridescence != 0u && m.iridescence.x > 0.0) {
    // The thickness texture's green channel blends the range (without one, the loader made both ends the maximum).
    float thickness = mix(m.iridescence.z, m.iridescence.w, texturedFactor(1.0, m.iridescenceThicknessTexture, s, 1u));
    setIridescence(gm, texturedFactor(m.iridescence.x, m.iridescenceTexture, s, 0u), m.iridescence.y, thickness);
  }
}

// KHR_materials_anisotropy at s: turns s.frame about its normal so that local x is the anisotropy direction (the
// front face's tangent rotated by anisotropyRotation toward the bitangent, after the texture's own direction) and
// returns the strength (the factor times the texture's blue). Without a tangent the frame's own x is the tangent.
float anisotropyAt(Material m, inout SurfacePoint s) {
  vec2 dir = vec2(1.0, 0.0);
  float strength = m.anisotropy.x;
  if (hasTexture(m.anisotropyTexture)) {
    vec3 c = sampleTexture(m.anisotropyTexture.texture, slotUv(m.anisotropyTexture, s.attributes), false).rgb;
    dir = c.rg * 2.0 - 1.0;
    strength *= c.b;
  }
  dir = vec2(m.anisotropy.y * dir.x - m.anisotropy.z * dir.y, m.anisotropy.z * dir.x + m.anisotropy.y * dir.y);
  vec3 n = s.frame[2];
  vec3 t = s.attributes.tangent.xyz - n * dot(n, s.attributes.tangent.xyz);
  float tl = length(t);
  t = tl > 0.0 ? t / tl : s.frame[0];
  vec3 b = cross(s.frontFace ? n : -n, t) * (s.attributes.tangent.w < 0.0 ? -1.0 : 1.0);
  vec3 a = t * dir.x + b * dir.y;
  float al = length(a);
  a = al > 0.0 ? a / al : t;
  s.frame = mat3(a, cross(n, a), n);
  return strength;
}

// KHR_materials_dispersion at a vertex of `path` on material m: a path past a dispersive volume's interface carries
// one colour channel (chosen at the camera, each with probability 1/3) at the ior of that channel's wavelength. The
// first time, its throughput is masked to the channel and scaled by 3, so every channel's expectation is kept; m's
// ior becomes the channel's, for the Fresnel terms and the refraction alike.
void takeSpectralChannel(inout PathState path, inout Material m) {
  if (kHasDispersion == 0u || m.dispersion.w <= 0.0) return;
  uint c = pathChannelOf(path.pixel);
  if ((path.pixel & kPathChannelTaken) == 0u) {
    vec3 mask = vec3(0.0);
    mask[c] = 3.0;
    path.throughput.rgb *= mask;
    path.pixel |= kPathChannelTaken;
  }
  m.specularColor.w = m.dispersion[c];
}

// The material's parameters at s (factors times textures and vertex colours), its emission into s.emission
// and its normal map into s.frame; a material with a specular lobe gets a shading normal whose mirror
// direction of wo stays above the surface (normalForValidReflection).
GltfMaterial shadeSurface(Material m, inout SurfacePoint s, vec3 wo) {
  vec4 base = m.baseColor;
  float metallic = m.metallic, roughness = m.roughness;
  vec3 unmappedNormal = s.frame[2];
  s.emission = m.emission;
  if (kHasTextures != 0u) {
    base = baseColorAt(m, s.attributes);
    if (hasTexture(m.metallicRoughnessTexture)) {
      vec4 mr = sampleTexture(m.metallicRoughnessTexture.texture, slotUv(m.metallicRoughnessTexture, s.attributes), false);
      roughness *= mr.g;
      metallic *= mr.b;
    }
    if (hasTexture(m.emissiveTexture) && maxComponent(m.emission) > 0.0)
      s.emission *= sampleTexture(m.emissiveTexture.texture, slotUv(m.emissiveTexture, s.attributes), true).rgb;
    if (kHasNormalMaps != 0u && hasTexture(m.normalTexture)) {
      // The tangent frame belongs to the front face: a back-face hit maps with the unflipped normal, then flips.
      bool flipped = !s.frontFace;
      if (flipped) s.frame[2] = -s.frame[2];
      vec3 mapped = normalMapped(m.normalTexture, s);
      s.frame = basisFromNormal(flipped ? -mapped : mapped);
    }
  }
  float specular = texturedFactor(m.specular, m.specularTexture, s, 3u);
  if (kHasGlossy != 0u && (metallic > 0.0 || specular > 0.0)) {
    vec3 n = normalForValidReflection(s.ng, wo, s.frame[2]);
    if (n != s.frame[2]) s.frame = basisFromNormal(n);
  }
  float anisotropy = 0.0;
  if (kHasAnisotropy != 0u && kHasTextures != 0u && m.anisotropy.x > 0.0) anisotropy = anisotropyAt(m, s);
  GltfMaterial gm = makeGltfMaterial(base.rgb, metallic, roughness, specular);
  if (anisotropy > 0.0) setAnisotropy(gm, anisotropy);
  if (kHasGlossy != 0u) shadeExtensions(m, s, unmappedNormal, gm);
  return gm;
}

// Beer-Lambert attenuation of a segment of length t that ended on the inside of a volume (a back face of a
// material that refracts into one); 1 elsewhere.
vec3 volumeTransmittance(Material m, SurfacePoint s, float t) {
  if (kHasTransmission == 0u || s.frontFace || m.volumetric == 0u || m.attenuation.w <= 0.0) return vec3(1.0);
  return exp(-m.attenuation.rgb * t);
}

bool emitsToward(Material m, bool frontFace) {
  return (frontFace || (m.flags & kMaterialDoubleSided) != 0u) && maxComponent(m.emission) > 0.0;
}

// Emitted radiance of emitter triangle `tri` (material m) at point p: textured emitters look their texture up.
vec3 emissionAtPoint(Material m, uint tri, vec3 p, vec3 v0, vec3 v1, vec3 v2) {
  if (!hasTexture(m.emissiveTexture)) return m.emission;
  vec2 b12 = barycentricsOf(p, v0, v1, v2);
  SurfaceAttributes a = attributesAt(tri, vec3(1.0 - b12.x - b12.y, b12));
  return m.emission * sampleTexture(m.emissiveTexture.texture, slotUv(m.emissiveTexture, a), true).rgb;
}

// The BSDF-sampling technique and its pdf (local frame). In an all-Lambertian scene (kHasGlossy = 0) the
// glTF BRDF is baseColor / pi and its sampling is cosine sampling: the GGX code is compiled out. The lecture's
// uniform and cosine techniques replace the BSDF's own sampling except where it has delta lobes or transmits,
// which only the BSDF's sampling can reach.
bool usesOwnSampling(GltfMaterial gm) {
  if (kHasDelta == 0u && kHasTransmission == 0u) return false;
  return gm.transmission > 0.0 || isDeltaAlpha(gm.alpha) || (gm.clearcoat > 0.0 && isDeltaAlpha(gm.clearcoatAlpha));
}
bool simpleTechnique(GltfMaterial gm) {
  return kHasGlossy == 0u || (kBsdfSampling != kBsdfSamplingFull && !usesOwnSampling(gm));
}
float techniquePdf(GltfMaterial gm, vec3 wo, vec3 wi) {
  if (!simpleTechnique(gm)) return gltfBsdfPdf(gm, wo, wi);
  if (wi.z <= 0.0) return 0.0;
  if (kBsdfSampling == kBsdfSamplingUniform) return uniformHemispherePdf(wi.z);
  return cosineHemispherePdf(wi.z);
}
vec3 bsdfEval(GltfMaterial gm, vec3 wo, vec3 wi) {
  if (kHasGlossy == 0u) return (wo.z > 0.0 && wi.z > 0.0) ? gm.baseColor * kInvPi : vec3(0.0);
  return gltfBsdfEval(gm, wo, wi);
}
BsdfSample sampleTechnique(GltfMaterial gm, vec3 wo, vec3 u) {
  if (!simpleTechnique(gm)) return sampleGltfBsdf(gm, wo, u);
  BsdfSample bs;
  bs.wi = kBsdfSampling == kBsdfSamplingUniform ? sampleUniformHemisphere(u.yz) : sampleCosineHemisphere(u.yz);
  bs.pdf = techniquePdf(gm, wo, bs.wi);
  bs.weight = bs.pdf > 0.0 ? bsdfEval(gm, wo, bs.wi) * (bs.wi.z / bs.pdf) : vec3(0.0);
  bs.delta = false;
  return bs;
}

uint lightSamplesAt(uint depth) { return splitFactorAt(depth, kSplitDepth, kLightSamples); }

// Solid-angle pdf with which light sampling from p picks this point of emitter `tri`; pmf = selection pmf.
float lightPdf(uint tri, float pmf, vec3 p, float dist2, float cosLight) {
  vec3 v0, v1, v2;
  triangleVertices(tri, v0, v1, v2);
  float area = scaledCrossArea(scaledTriangleCross(v0, v1, v2));
  return triangleLightPdfAt(kLightSampling, p, v0, v1, v2, pmf, area, dist2, cosLight);
}

// Alias-table pick of one light: its light entry (scene_layout.h).
uvec4 selectLight(float u) {
  uint n = uint(imageSize(lights));
  float scaled = u * float(n);
  uint slot = aliasSlot(scaled, n);
  uvec4 e = imageLoad(lights, int(slot));
  uint pick = aliasChoice(scaled, slot, e);
  return pick == slot ? e : imageLoad(lights, int(pick));
}

// The radiance of the environment seen along world direction w (0 without one).
vec3 environmentRadiance(vec3 w) {
  if (kHasEnvironment == 0u || envHeader.width == 0u) return vec3(0.0);
  return envRadiance[environmentPixel(envHeader, environmentUv(envHeader, w))].rgb;
}

// One light sample from s: the direction, the end of the shadow segment (its origin is offset from s), what
// arrives (radiance for area and environment lights, irradiance at normal incidence for delta lights), and the
// solid-angle pdf times the selection pmf (delta lights: the pmf alone, and no MIS: BSDF sampling cannot hit them).
struct LightSample {
  vec3 wi;
  vec3 target;
  vec3 arriving;
  float pdf;
  bool delta;
};

// The vertex of (v0, v1, v2) that is neither a nor b: the far corner of an emitter quad's second half.
vec3 emitterFreeVertex(vec3 v0, vec3 v1, vec3 v2, vec3 a, vec3 b) {
  if (v0 != a && v0 != b) return v0;
  if (v1 != a && v1 != b) return v1;
  return v2;
}

// A light sample on emissive triangle `tri`, chosen with probability pmf. When `tri` is the first half of an emitter
// quad (render/emitter_pairs.h) the entry stands for the pair: u's unit square maps onto the first half below its
// diagonal and onto the second above it, so which half and where on it are stratified together. Each half then has
// its own pmf (half the pair's) over its own area as density, as when sampled alone, which is what MIS at a BSDF hit
// assumes (lightPdf). Under solid-angle sampling u.x picks the half, which is sampled as a triangle.
bool sampleEmissiveTriangle(uint tri, float pmf, SurfacePoint s, vec2 u, out LightSample ls) {
  vec3 v0, v1, v2;
  float partnerCode;
  triangleVertices(tri, v0, v1, v2, partnerCode);
  bool pairPoint = false;
  TriangleLightSample ts;
  if (hasEmitterPartner(partnerCode)) {
    pmf *= 0.5;
    uint apex = emitterApex(partnerCode);  // p1; the shared edge is p0-p2
    vec3 p0 = apex == 0u ? v2 : (apex == 1u ? v0 : v1);
    vec3 p1 = apex == 0u ? v0 : (apex == 1u ? v1 : v2);
    vec3 p2 = apex == 0u ? v1 : (apex == 1u ? v2 : v0);
    bool second = kLightSampling == kLightSamplingArea ? emitterQuadSecondHalf(u) : u.x >= 0.5;
    if (kLightSampling != kLightSamplingArea) u.x = min(second ? 2.0 * u.x - 1.0 : 2.0 * u.x, kOneMinusEpsilon);
    if (second) {
      tri = emitterPartner(partnerCode);
      triangleVertices(tri, v0, v1, v2);
    }
    if (kLightSampling == kLightSamplingArea) {
      vec3 x = second ? emitterFreeVertex(v0, v1, v2, p0, p2) : p1;
      vec3 wt = emitterQuadWeights(u);
      ts.point = wt.x * p0 + wt.y * p2 + wt.z * x;
      ts.pointError = barycentricError(wt, p0, p2, x);
      ts.spherical = false;
      ts.solidAngle = 0.0;
      pairPoint = true;
    }
  }
  vec4 cr = scaledTriangleCross(v0, v1, v2);
  float area = scaledCrossArea(cr);
  if (!(area > 0.0)) return false;
  vec3 nl = normalize(cr.xyz);
  if (!pairPoint) ts = sampleTriangleLight(kLightSampling, s.p, v0, v1, v2, u);
  vec3 toLight = ts.point - s.p;
  float dist2 = dot(toLight, toLight);
  if (!(dist2 > 0.0)) return false;
  ls.wi = toLight * inversesqrt(dist2);
  float cosLight = dot(nl, -ls.wi);
  Material lm = loadMaterial(triangleInfoMaterial(imageLoad(triangleInfo, int(tri))));
  if (!emitsToward(lm, cosLight > 0.0)) return false;
  cosLight = abs(cosLight);
  if (cosLight <= 0.0) return false;
  ls.pdf = triangleLightPdf(ts.spherical, ts.solidAngle, pmf, area, dist2, cosLight);
  ls.target = offsetRayOrigin(ts.point, ts.pointError, nl, -ls.wi);
  ls.arriving = emissionAtPoint(lm, tri, ts.point, v0, v1, v2);
  ls.delta = false;
  return true;
}

bool samplePunctual(uint index, float pmf, SurfacePoint s, out LightSample ls) {
  PunctualLightSample ps = samplePunctualLight(punctualLights[index], s.p);
  ls.wi = ps.wi;
  ls.target = s.p + ps.wi * ps.distance;
  ls.arriving = ps.irradiance;
  ls.pdf = pmf;
  ls.delta = true;
  return ps.distance > 0.0;
}

bool sampleEnvironmentLight(float pmf, SurfacePoint s, vec2 u, out LightSample ls) {
  float pdf = 0.0;
  ls.wi = sampleEnvironment(envHeader, u, pdf);
  ls.pdf = pmf * pdf;
  ls.target = s.p + ls.wi * (length(s.p - envHeader.sceneSphere.xyz) + 2.0 * envHeader.sceneSphere.w + 1.0);
  ls.arriving = environmentRadiance(ls.wi);
  ls.delta = false;
  return pdf > 0.0;
}

// Whether wi (world; wiLocal in the shading frame) leaves s on the same side of both normals: above for
// reflection, below for a material that transmits. Elsewhere shading and geometric normals disagree, and light
// would leak through the surface.
bool onConsistentSide(SurfacePoint s, GltfMaterial gm, vec3 wi, vec3 wiLocal) {
  float side = dot(s.ng, wi);
  if (side > 0.0) return wiLocal.z > 0.0;
  return side < 0.0 && wiLocal.z < 0.0 && kHasTransmission != 0u && gm.transmission > 0.0;
}

// Light sample j of `samples` at s: the shadow ray to trace, carrying the contribution it adds if unoccluded,
// weighted `share` (1 / samples; under EARS 1 / qL for floor(qL + u) samples, whose mean is still the light
// technique's: MIS counts `samples` on both sides); false when the sample adds nothing (or was rouletted away).
// `slot` is the path copy's slot (EARS trains on it).
bool prepareLightSample(PathState path, uint slot, SurfacePoint s, GltfMaterial gm, vec3 wo, uint j, uint samples,
                        float share, out ShadowRay ray) {
  uint depth = path.depth;
  SampleStream stream = pathStream(path);
  uvec4 light = selectLight(sampleU(stream, lightDim(depth, j, 0u)));
  uint kind = lightEntryKind(light);
  float pmf = lightEntryPmf(light);
  vec2 u = sampleU2(stream, lightDim(depth, j, 1u));  // 2u is its second dimension
  LightSample ls;
  bool sampled = false;
  if (kind == kLightKindTriangle) sampled = sampleEmissiveTriangle(lightEntryIndex(light), pmf, s, u, ls);
  else if (kHasPunctual != 0u && kind == kLightKindPunctual) sampled = samplePunctual(lightEntryIndex(light), pmf, s, ls);
  else if (kHasEnvironment != 0u && kind == kLightKindEnvironment) sampled = sampleEnvironmentLight(pmf, s, u, ls);
  if (!sampled || !(ls.pdf > 0.0)) return false;
  vec3 wiLocal = ls.wi * s.frame;
  vec3 woLocal = wo * s.frame;
  if (!onConsistentSide(s, gm, ls.wi, wiLocal)) return false;
  vec3 f = bsdfEval(gm, woLocal, wiLocal);
  // MIS over one BSDF sample and `samples` light samples: the light technique's pdf counts samples times.
  float weight = kMis == kMisNone || ls.delta ? 1.0 : misWeight(kMis, float(samples) * ls.pdf, techniquePdf(gm, woLocal, wiLocal));
  vec3 contribution = path.throughput.rgb * f * ls.arriving * (abs(wiLocal.z) * weight * share / ls.pdf);
  if (!allFinite(contribution)) ++rareCounts.y;  // still queued: it poisons the sample
  else if (!(maxComponent(contribution) > 0.0)) return false;
  if (kShadowRouletteThreshold > 0.0 && luminance(contribution) < kShadowRouletteThreshold * loadPixelEstimate(pathPixelOf(path.pixel)).w) {
    RouletteStep rr = fixedRoulette(kShadowRouletteQ, sampleU(stream, lightDim(depth, j, 3u)));
    if (!rr.survives) return false;
    contribution /= rr.survival;
  }
  vec3 origin = offsetRayOrigin(s.p, s.pError, s.ng, ls.wi);
  ray.origin = vec4(origin, uintBitsToFloat(slot));
  ray.direction = vec4(ls.target - origin, uintBitsToFloat(path.rootPath));
  ray.contribution = vec4(contribution, uintBitsToFloat(alphaKey(streamHash(stream), lightDim(depth, j, 0u) | 0x80000000u)));
  return true;
}

// Radiance an escaped ray brings: the background, and the environment light MIS-weighted against light sampling
// for BSDF-sampled rays (as emissionAt weighs emitters); a camera ray, the backdrop where there is one.
vec3 escapedRadiance(PathState path) {
  if (path.depth == 0u && hasBackdrop(pc.background)) return path.throughput.rgb * vec3(pc.background.w);
  vec3 radiance = pc.background.rgb;
  if (kHasEnvironment != 0u) {
    vec3 w = path.direction.xyz;
    float weight = 1.0;
    if (kNee != 0u && path.direction.w > 0.0 && envHeader.selectionPmf > 0.0) {
      float pl = envHeader.selectionPmf * environmentPdf(envHeader, w);
      weight = kMis == kMisNone ? 0.0 : misWeight(kMis, path.direction.w, float(lightSamplesAt(path.depth - 1u)) * pl);
    }
    radiance += environmentRadiance(w) * weight;
  }
  return path.throughput.rgb * radiance;
}

// Emission seen at s from the path's last ray, MIS-weighted against light sampling for BSDF-sampled rays.
vec3 emissionAt(PathState path, SurfacePoint s, Material m, uint tri, vec4 hit, vec3 wo) {
  if (!emitsToward(m, s.frontFace)) return vec3(0.0);
  float weight = 1.0;
  bool bsdfSampled = path.direction.w > 0.0;
  if (kHasLights != 0u && kNee != 0u && bsdfSampled) {
    if (kMis == kMisNone) {
      weight = 0.0;  // light sampling alone accounts for direct light
    } else {
      float pmf = imageLoad(triangles, int(kTriangleTexels * tri + kTriangleLightPmfTexel)).w;
      float cosLight = max(dot(s.ng, wo), 1e-30);
      float pl = lightPdf(tri, pmf, path.origin.xyz, hit.x * hit.x, cosLight);
      weight = misWeight(kMis, path.direction.w, float(lightSamplesAt(path.depth - 1u)) * pl);
    }
  }
  return path.throughput.rgb * s.emission * weight;
}

// Below the depth cap a vertex samples lights; it also continues unless, with light sampling alone (NEE
// without MIS), the next vertex at the cap would only add emission, which it ignores.
bool belowDepthCap(uint depth) { return kMaxDepth == 0u || depth < kMaxDepth; }
bool continuationIsUseful(uint depth) {
  bool lastVertexIsUseless = kMaxDepth > 0u && depth + 1u >= kMaxDepth && kNee != 0u && kMis == kMisNone &&
                             kHasLights != 0u && kHasDelta == 0u && maxComponent(pc.background.rgb) == 0.0;
  return belowDepthCap(depth) && !lastVertexIsUseless;
}

// BSDF continuation c of q (q > 1 splits, see splitCount) of `path` (in slot `id`) at s: false when it ends,
// else the child's next ray, throughput and info in `next` (radiance left to the caller). Russian roulette
// ends or reweights it; the fixed mode's constant c on termination goes to `gathered`, as does a non-finite
// throughput (counted: it poisons the sample, which accumulate counts and excludes, never dropped silently).
bool continuePath(PathState path, uint id, SurfacePoint s, GltfMaterial gm, vec3 woLocal, uint c, float q,
                  inout vec3 gathered, out PathState next) {
  uint depth = path.depth;
  SampleStream stream = pathStream(path);
  stream.key = childKey(path.rngKey, depth, c);
  vec3 u = vec3(sampleU(stream, bounceDim(depth, kDimBsdfLobe)), sampleU2(stream, bounceDim(depth, kDimBsdf)));
  BsdfSample bs = sampleTechnique(gm, woLocal, u);
  vec3 wi = s.frame * bs.wi;
  bool continues = onConsistentSide(s, gm, wi, bs.wi);
  vec3 beta = continues ? path.throughput.rgb * bs.weight / q : vec3(0.0);
  if (!allFinite(beta)) {
    ++rareCounts.z;
    gathered += beta;
    return false;
  }
  // Roulette judges a child by its unsplit throughput. Under EARS q < 1 is itself roulette, which the throughput
  // keeps: judged without it, survival would shrink like the product of past survivals (infinite variance).
  float splitWeight = path.throughput.w * max(q, 1.0);
  continues = continues && maxComponent(beta) > 0.0;
  // pbrt-v4's etaScale: radiance entering a denser medium is scaled by 1 / eta^2 (bsdf_gltf.h); roulette judges
  // the throughput without that factor, so paths are not killed for being inside glass.
  float etaScale = path.origin.w;
  if (kHasTransmission != 0u && bs.wi.z < 0.0 && !gm.thinWalled) etaScale *= gm.eta * gm.eta;

  // EARS decides at the vertex (ears_shade.glsl), before its copies: q arrives here as the split factor.
  if (continues && rouletteApplies(depth, kRouletteDepth) && kRouletteMode != kRouletteNone && kRouletteMode != kRouletteEars) {
    float r = sampleU(stream, bounceDim(depth, kDimRoulette));
    float scale = kRouletteMode == kRouletteEfficiency ? rouletteScale[min(depth, kRouletteTableDepths - 1u)] : 1.0;
    RouletteStep rr = rouletteStep(kRouletteMode, maxComponent(beta) * splitWeight * etaScale, scale, kRouletteQ, r);
    vec3 cValue = beta * kRouletteC;  // the fixed mode's constant c, as throughput
    if (kRouletteMode == kRouletteFixed && rr.survives) gathered -= cValue * fixedRouletteCompensation(kRouletteQ);
    if (kRouletteMode == kRouletteFixed && !rr.survives) gathered += cValue;
    continues = rr.survives;
    beta /= rr.survival;
  }
  if (kRecordDepthStats != 0u && depth < kRouletteTableDepths && continues)
    depthStats[id * kRouletteTableDepths + depth].x = maxComponent(beta);
  next.origin = vec4(offsetRayOrigin(s.p, s.pError, s.ng, wi), etaScale);
  next.direction = vec4(wi, bs.delta ? 0.0 : bs.pdf);  // after a delta lobe emission counts in full, as after the camera
  next.throughput = vec4(beta, splitWeight);
  next.pixel = path.pixel;
  next.rngKey = stream.key;
  next.depth = depth + 1u;
  next.rootPath = path.rootPath;
  next.radiance = path.radiance;
  return continues;
}
