#version 460
#extension GL_GOOGLE_include_directive : require
#ifdef VKMC_FLOAT_ATOMICS
#extension GL_EXT_shader_atomic_float : require
#endif
// Stage 3: at each hit, the estimator chosen by specialization constants:
//   emission, MIS-weighted against light sampling for BSDF-sampled rays;
//   next-event estimation with M light samples (M > 1 splits the first kSplitDepth bounces), each queued as a
//   shadow ray, optionally rouletted when its contribution is tiny against the pixel's running estimate;
//   the BSDF continuation (uniform, cosine or glTF BRDF sampling) and Russian roulette on it.
// Escaped rays gather the uniform background.
#include "common.glsl"
#include "bsdf_gltf.h"
#include "light_sampling.h"

struct SurfacePoint {
  vec3 p;
  vec3 pError;
  vec3 ng;  // geometric normal, facing the incoming ray's side
  mat3 frame;  // shading frame; column 2 is the shading normal, on the side of ng
  bool frontFace;
  uint material;
};

SurfacePoint surfaceAt(uint tri, vec2 b12, vec3 wo) {
  vec3 v0, v1, v2;
  triangleVertices(tri, v0, v1, v2);
  vec3 b = vec3(1.0 - b12.x - b12.y, b12.x, b12.y);
  SurfacePoint s;
  s.p = b.x * v0 + b.y * v1 + b.z * v2;
  s.pError = barycentricError(b, v0, v1, v2);
  s.ng = normalize(cross(v1 - v0, v2 - v0));
  s.frontFace = dot(s.ng, wo) > 0.0;
  if (!s.frontFace) s.ng = -s.ng;
  uvec4 info = texelFetch(triangleInfo, int(tri));
  s.material = info.w;
  vec3 n = b.x * decodeOctahedral(unpackSnorm2x16(info.x)) + b.y * decodeOctahedral(unpackSnorm2x16(info.y)) +
           b.z * decodeOctahedral(unpackSnorm2x16(info.z));
  float len = length(n);
  vec3 ns = len > 0.0 ? n / len : s.ng;
  if (dot(ns, s.ng) < 0.0) ns = -ns;
  s.frame = basisFromNormal(ns);
  return s;
}

bool emitsToward(Material m, bool frontFace) {
  return (frontFace || (floatBitsToUint(m.emission.w) & kMaterialDoubleSided) != 0u) &&
         maxComponent(m.emission.rgb) > 0.0;
}

GltfMaterial gltfMaterial(Material m) { return makeGltfMaterial(m.baseColor.rgb, m.params.x, m.params.y, m.params.z); }

// The BSDF-sampling technique and its pdf (local frame). In an all-Lambertian scene (kHasGlossy = 0) the
// glTF BRDF is baseColor / pi and its sampling is cosine sampling: the GGX code is compiled out.
vec3 sampleTechnique(GltfMaterial gm, vec3 wo, vec3 u) {
  if (kBsdfSampling == kBsdfSamplingUniform) return sampleUniformHemisphere(u.yz);
  if (kBsdfSampling == kBsdfSamplingCosine || kHasGlossy == 0u) return sampleCosineHemisphere(u.yz);
  return sampleGltfBsdf(gm, wo, u);
}
float techniquePdf(GltfMaterial gm, vec3 wo, vec3 wi) {
  if (wi.z <= 0.0) return 0.0;
  if (kBsdfSampling == kBsdfSamplingUniform) return uniformHemispherePdf(wi.z);
  if (kBsdfSampling == kBsdfSamplingCosine || kHasGlossy == 0u) return cosineHemispherePdf(wi.z);
  return gltfBsdfPdf(gm, wo, wi);
}
vec3 bsdfEval(GltfMaterial gm, vec3 wo, vec3 wi) {
  if (kHasGlossy == 0u) return (wo.z > 0.0 && wi.z > 0.0) ? gm.baseColor * kInvPi : vec3(0.0);
  return gltfBsdfEval(gm, wo, wi);
}

float misWeight(float pdfThis, float pdfOther) {
  if (kMis == kMisBalance) return balanceHeuristic(pdfThis, pdfOther);
  if (kMis == kMisPower) return powerHeuristic(pdfThis, pdfOther);
  return 1.0;
}

uint lightSamplesAt(uint depth) { return depth < kSplitDepth ? kLightSamples : 1u; }

// Solid-angle pdf with which light sampling from p picks this point of emitter `tri`; pmf = selection pmf.
float lightPdf(uint tri, float pmf, vec3 p, float dist2, float cosLight) {
  vec3 v0, v1, v2;
  triangleVertices(tri, v0, v1, v2);
  if (kLightSampling == kLightSamplingSolidAngle) {
    float omega = triangleSolidAngle(p, v0, v1, v2);
    if (useSphericalSampling(omega)) return pmf / omega;
  }
  float area = 0.5 * length(cross(v1 - v0, v2 - v0));
  return pmf * dist2 / (area * cosLight);
}

// Alias-table pick of one emissive triangle: x = triangle, y = pmf bits.
uvec2 selectLight(float u) {
  uint n = uint(textureSize(lights));
  float scaled = u * float(n);
  uint i = min(uint(scaled), n - 1u);
  uvec4 e = texelFetch(lights, int(i));
  uint pick = (scaled - float(i)) < uintBitsToFloat(e.x) ? i : e.y;
  uvec4 chosen = pick == i ? e : texelFetch(lights, int(pick));
  return uvec2(chosen.z, chosen.w);
}

void queueLightSample(PathState path, SurfacePoint s, GltfMaterial gm, vec3 wo, uint j, uint samples) {
  uint depth = path.info.z;
  uint key = path.info.y;
  uvec2 light = selectLight(randomUnit(key, lightDim(depth, j, 0u)));
  float pmf = uintBitsToFloat(light.y);
  vec3 v0, v1, v2;
  triangleVertices(light.x, v0, v1, v2);
  vec3 cr = cross(v1 - v0, v2 - v0);
  float area = 0.5 * length(cr);
  if (!(area > 0.0)) return;
  vec3 nl = cr / (2.0 * area);
  vec2 u = vec2(randomUnit(key, lightDim(depth, j, 1u)), randomUnit(key, lightDim(depth, j, 2u)));
  vec3 pl;
  vec3 plError;
  float pdf = 0.0;
  bool spherical = false;
  if (kLightSampling == kLightSamplingSolidAngle) {
    float omega = triangleSolidAngle(s.p, v0, v1, v2);
    spherical = useSphericalSampling(omega);
    if (spherical) {
      vec3 w = sampleSphericalTriangle(s.p, v0, v1, v2, u, omega);
      pl = pointOnTrianglePlane(s.p, w, v0, nl);
      plError = gammaBound(16.0) * (abs(pl) + abs(v0) + abs(v1) + abs(v2));
      pdf = pmf / omega;
    }
  }
  if (!spherical) {
    vec3 b = sampleUniformTriangle(u);
    pl = b.x * v0 + b.y * v1 + b.z * v2;
    plError = barycentricError(b, v0, v1, v2);
  }
  vec3 toLight = pl - s.p;
  float dist2 = dot(toLight, toLight);
  if (!(dist2 > 0.0)) return;
  vec3 wi = toLight * inversesqrt(dist2);
  float cosLight = dot(nl, -wi);
  Material lm = materials[texelFetch(triangleInfo, int(light.x)).w];
  if (!emitsToward(lm, cosLight > 0.0)) return;
  cosLight = abs(cosLight);
  if (cosLight <= 0.0 || dot(s.ng, wi) <= 0.0) return;
  if (!spherical) pdf = pmf * dist2 / (area * cosLight);
  vec3 wiLocal = wi * s.frame;
  vec3 woLocal = wo * s.frame;
  if (wiLocal.z <= 0.0 || !(pdf > 0.0)) return;
  vec3 f = bsdfEval(gm, woLocal, wiLocal);
  // MIS over one BSDF sample and `samples` light samples: the light technique's pdf counts samples times.
  float weight = kMis == kMisNone ? 1.0 : misWeight(float(samples) * pdf, techniquePdf(gm, woLocal, wiLocal));
  vec3 contribution = path.throughput.rgb * f * lm.emission.rgb * (wiLocal.z * weight / (pdf * float(samples)));
  if (!allFinite(contribution)) atomicAdd(control.nonfinite.y, 1u);  // still queued: it poisons the sample
  else if (!(maxComponent(contribution) > 0.0)) return;
  if (kShadowRouletteThreshold > 0.0 && luminance(contribution) < kShadowRouletteThreshold * pixelEstimate[path.info.x]) {
    if (randomUnit(key, lightDim(depth, j, 3u)) < kShadowRouletteQ) return;
    contribution /= 1.0 - kShadowRouletteQ;
  }
  vec3 origin = offsetRayOrigin(s.p, s.pError, s.ng, wi);
  vec3 target = offsetRayOrigin(pl, plError, nl, -wi);
  uint slot = atomicAdd(control.counts.z, 1u);
  shadowRays[slot].origin = vec4(origin, 1.0 - 1e-4);
  shadowRays[slot].direction = vec4(target - origin, uintBitsToFloat(path.info.w));
  shadowRays[slot].contribution = vec4(contribution, 0.0);
}

// Radiance of a sample accumulates in its root path. A non-finite value is counted here by kind and still
// added: the whole sample is then excluded (and counted) by accumulate, never written to the image. Without BSDF splitting a path is its own root and is
// alone in its slot during this dispatch; with splitting, siblings add concurrently, hence the atomics.
void addToSample(uint id, uint root, vec3 value) {
  if (!allFinite(value)) atomicAdd(control.nonfinite.x, 1u);
  else if (!(maxComponent(abs(value)) > 0.0)) return;
#ifdef VKMC_FLOAT_ATOMICS
  if (kBsdfSamples > 1.0) {
    atomicAdd(paths[root].radiance.r, value.r);
    atomicAdd(paths[root].radiance.g, value.g);
    atomicAdd(paths[root].radiance.b, value.b);
    return;
  }
#endif
  paths[id].radiance.rgb += value;
}

void main() {
  uint slot = invocationIndex();
  if (slot >= inQueueCount()) return;
  uint id = rayQueues[inQueueBase() + slot];
  PathState path = paths[id];
  vec4 hit = hits[id];
  uint tri = floatBitsToUint(hit.w);
  uint root = path.info.w;
  vec3 wo = -path.direction.xyz;
  // Pilot of efficiency roulette: what the sample had gathered when the previous vertex decided to go on.
  if (kRecordDepthStats != 0u && path.info.z >= 1u && path.info.z <= kRouletteTableDepths)
    depthStats[id * kRouletteTableDepths + path.info.z - 1u].y = luminance(path.radiance.rgb);
  if (tri == kMissPrimitive) {
    addToSample(id, root, path.throughput.rgb * pc.background.rgb);
    return;
  }
  SurfacePoint s = surfaceAt(tri, hit.yz, wo);
  Material m = materials[s.material];
  uint depth = path.info.z;
  vec3 gathered = vec3(0.0);

  if (emitsToward(m, s.frontFace)) {
    float weight = 1.0;
    bool bsdfSampled = path.direction.w > 0.0;
    if (kHasLights != 0u && kNee != 0u && bsdfSampled) {
      if (kMis == kMisNone) {
        weight = 0.0;  // light sampling alone accounts for direct light
      } else {
        float pmf = texelFetch(triangles, int(3u * tri + 1u)).w;
        float cosLight = max(dot(s.ng, wo), 1e-30);
        float pl = lightPdf(tri, pmf, path.origin.xyz, hit.x * hit.x, cosLight);
        weight = misWeight(path.direction.w, float(lightSamplesAt(depth - 1u)) * pl);
      }
    }
    gathered += path.throughput.rgb * m.emission.rgb * weight;
  }

  bool alive = kMaxDepth == 0u || depth < kMaxDepth;
  GltfMaterial gm = gltfMaterial(m);
  vec3 woLocal = wo * s.frame;
  if (alive && kHasLights != 0u && kNee != 0u) {
    uint samples = lightSamplesAt(depth);
    for (uint j = 0u; j < samples; ++j) queueLightSample(path, s, gm, wo, j, samples);
  }
  // With light sampling alone (NEE without MIS) the vertex at the depth cap only adds emission, which it
  // ignores: the continuation ray would be traced for nothing.
  bool lastVertexIsUseless = kMaxDepth > 0u && depth + 1u >= kMaxDepth && kNee != 0u && kMis == kMisNone &&
                             kHasLights != 0u && maxComponent(pc.background.rgb) == 0.0;
  alive = alive && !lastVertexIsUseless;

  // BSDF continuations: q = kBsdfSamples at split depths gives floor(q + u) children weighted 1/q; child 0
  // continues in this slot, the others take slots from the pool (none left: no split, weight 1, unbiased).
  uint key = path.info.y;
  float q = (kBsdfSamples > 1.0 && depth < kSplitDepth) ? kBsdfSamples : 1.0;
  uint children = alive ? (q > 1.0 ? splitCount(q, randomUnit(key, bounceDim(depth, kDimSplit))) : 1u) : 0u;
  uint firstChild = 0u;
  if (children > 1u) {
    uint base = atomicAdd(control.counts.w, children - 1u);
    if (pc.pathCount + base + children - 1u > pc.queueCapacity) {
      children = 1u;
      q = 1.0;
    } else {
      firstChild = pc.pathCount + base;
    }
  }
  for (uint c = 0u; c < children; ++c) {
    uint ckey = childKey(key, depth, c);
    vec3 u = vec3(randomUnit(ckey, bounceDim(depth, kDimBsdfLobe)), randomUnit(ckey, bounceDim(depth, kDimBsdf)),
                  randomUnit(ckey, bounceDim(depth, kDimBsdf + 1u)));
    vec3 wiLocal = sampleTechnique(gm, woLocal, u);
    float pdf = techniquePdf(gm, woLocal, wiLocal);
    vec3 wi = s.frame * wiLocal;
    bool continues = pdf > 0.0 && wiLocal.z > 0.0 && dot(wi, s.ng) > 0.0;
    vec3 beta = continues ? path.throughput.rgb * bsdfEval(gm, woLocal, wiLocal) * (wiLocal.z / (pdf * q)) : vec3(0.0);
    if (!allFinite(beta)) {  // never dropped silently: it poisons the sample, which accumulate counts and excludes
      atomicAdd(control.nonfinite.z, 1u);
      gathered += beta;
      continue;
    }
    float splitWeight = path.throughput.w * q;  // roulette judges a child by its unsplit throughput
    continues = continues && maxComponent(beta) > 0.0;

    if (continues && depth + 1u >= kRouletteDepth && kRouletteMode != kRouletteNone) {
      float r = randomUnit(ckey, bounceDim(depth, kDimRoulette));
      if (kRouletteMode == kRouletteFixed) {
        // F' = (F - q c) / (1 - q) with probability 1 - q, else c: unbiased for any c.
        vec3 cValue = beta * kRouletteC;
        if (r < kRouletteQ) {
          gathered += cValue;
          continues = false;
        } else {
          gathered -= cValue * (kRouletteQ / (1.0 - kRouletteQ));
          beta /= 1.0 - kRouletteQ;
        }
      } else {
        float unsplit = maxComponent(beta) * splitWeight;
        float scale = kRouletteMode == kRouletteEfficiency ? rouletteScale[min(depth, kRouletteTableDepths - 1u)] : 1.0;
        float survival = rouletteSurvival(unsplit, scale, kRouletteMaxSurvival);
        continues = splitCount(survival, r) > 0u;
        beta /= survival;
      }
    }
    if (kRecordDepthStats != 0u && depth < kRouletteTableDepths && continues)
      depthStats[id * kRouletteTableDepths + depth].x = maxComponent(beta);
    if (!continues) continue;
    uint target = c == 0u ? id : firstChild + c - 1u;
    paths[target].origin = vec4(offsetRayOrigin(s.p, s.pError, s.ng, wi), 0.0);
    paths[target].direction = vec4(wi, pdf);
    paths[target].throughput = vec4(beta, splitWeight);
    paths[target].info = uvec4(path.info.x, ckey, depth + 1u, root);
    if (c > 0u) paths[target].radiance = vec4(0.0);
    uint out_ = atomicAdd(control.counts[((pc.bounce + 1u) & 1u)], 1u);
    rayQueues[outQueueBase() + out_] = target;
  }
  addToSample(id, root, gathered);
}
