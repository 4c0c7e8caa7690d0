#version 460
#extension GL_GOOGLE_include_directive : require
// Stage 3: at each hit, emission (MIS-weighted for BSDF-sampled rays), next-event estimation with one light
// sample (shadow ray queued), cosine-weighted continuation, Russian roulette on throughput.
// Escaped rays gather the uniform background. Lambertian surfaces; the glTF BRDF is its own issue.
#include "common.glsl"

struct SurfacePoint {
  vec3 p;
  vec3 pError;
  vec3 ng;  // geometric normal, facing the incoming ray's side
  vec3 ns;  // shading normal, same side as ng
  bool frontFace;
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
  vec3 n = b.x * decodeOctahedral(unpackSnorm2x16(info.x)) + b.y * decodeOctahedral(unpackSnorm2x16(info.y)) +
           b.z * decodeOctahedral(unpackSnorm2x16(info.z));
  float len = length(n);
  s.ns = len > 0.0 ? n / len : s.ng;
  if (dot(s.ns, s.ng) < 0.0) s.ns = -s.ns;
  return s;
}

bool emitsToward(Material m, bool frontFace) {
  return (frontFace || (floatBitsToUint(m.emission.w) & kMaterialDoubleSided) != 0u) &&
         maxComponent(m.emission.rgb) > 0.0;
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

void queueLightSample(uint id, PathState path, SurfacePoint s, vec3 albedo) {
  uint depth = path.info.z;
  uint key = path.info.y;
  uvec2 light = selectLight(randomUnit(key, bounceDim(depth, kDimLightSelect)));
  vec3 v0, v1, v2;
  triangleVertices(light.x, v0, v1, v2);
  vec3 b = sampleUniformTriangle(vec2(randomUnit(key, bounceDim(depth, kDimLightPoint)),
                                      randomUnit(key, bounceDim(depth, kDimLightPoint + 1u))));
  vec3 pl = b.x * v0 + b.y * v1 + b.z * v2;
  vec3 cr = cross(v1 - v0, v2 - v0);
  float area = 0.5 * length(cr);
  vec3 nl = cr / (2.0 * area);
  vec3 toLight = pl - s.p;
  float dist2 = dot(toLight, toLight);
  if (!(dist2 > 0.0) || !(area > 0.0)) return;
  vec3 wi = toLight * inversesqrt(dist2);
  float cosLight = dot(nl, -wi);
  Material lm = materials[texelFetch(triangleInfo, int(light.x)).w];
  if (!emitsToward(lm, cosLight > 0.0)) return;
  cosLight = abs(cosLight);
  float cosSurface = dot(s.ns, wi);
  if (cosSurface <= 0.0 || dot(s.ng, wi) <= 0.0 || cosLight <= 0.0) return;
  float lightPdf = uintBitsToFloat(light.y) / area * dist2 / cosLight;
  float bsdfPdf = cosineHemispherePdf(cosSurface);
  vec3 f = albedo * kInvPi;
  vec3 contribution = path.throughput.rgb * f * lm.emission.rgb * (cosSurface * powerHeuristic(lightPdf, bsdfPdf) / lightPdf);
  if (maxComponent(contribution) <= 0.0) return;
  vec3 origin = offsetRayOrigin(s.p, s.pError, s.ng, wi);
  vec3 target = offsetRayOrigin(pl, barycentricError(b, v0, v1, v2), nl, -wi);
  uint slot = atomicAdd(control.counts.z, 1u);
  shadowRays[slot].origin = vec4(origin, 1.0 - 1e-4);
  shadowRays[slot].direction = vec4(target - origin, uintBitsToFloat(id));
  shadowRays[slot].contribution = vec4(contribution, 0.0);
}

void main() {
  uint slot = invocationIndex();
  if (slot >= inQueueCount()) return;
  uint id = rayQueues[inQueueBase() + slot];
  PathState path = paths[id];
  vec4 hit = hits[id];
  uint tri = floatBitsToUint(hit.w);
  vec3 wo = -path.direction.xyz;
  if (tri == kMissPrimitive) {
    paths[id].radiance.rgb += path.throughput.rgb * pc.background.rgb;
    return;
  }
  SurfacePoint s = surfaceAt(tri, hit.yz, wo);
  Material m = materials[texelFetch(triangleInfo, int(tri)).w];

  if (emitsToward(m, s.frontFace)) {
    float weight = 1.0;
    if (kHasLights != 0u && path.direction.w > 0.0) {
      float lightPdfArea = texelFetch(triangles, int(3u * tri + 1u)).w;
      float lightPdf = lightPdfArea * hit.x * hit.x / max(dot(s.ng, wo), 1e-30);
      weight = powerHeuristic(path.direction.w, lightPdf);
    }
    path.radiance.rgb += path.throughput.rgb * m.emission.rgb * weight;
  }

  uint depth = path.info.z;
  bool alive = kMaxDepth == 0u || depth < kMaxDepth;
  vec3 albedo = m.baseColor.rgb;
  if (alive && kHasLights != 0u) queueLightSample(id, path, s, albedo);

  uint key = path.info.y;
  vec3 local = sampleCosineHemisphere(vec2(randomUnit(key, bounceDim(depth, kDimBsdf)),
                                           randomUnit(key, bounceDim(depth, kDimBsdf + 1u))));
  vec3 wi = basisFromNormal(s.ns) * local;
  float pdf = cosineHemispherePdf(local.z);
  alive = alive && dot(wi, s.ng) > 0.0 && pdf > 0.0 && maxComponent(albedo) > 0.0;
  path.throughput.rgb *= albedo;  // f * cos / pdf for a Lambertian surface sampled by cosine
  if (alive && depth + 1u >= kRouletteDepth) {
    float survival = min(maxComponent(path.throughput.rgb), kRouletteMaxSurvival);
    if (randomUnit(key, bounceDim(depth, kDimRoulette)) >= survival) alive = false;
    else path.throughput.rgb /= survival;
  }
  if (alive) {
    path.origin = vec4(offsetRayOrigin(s.p, s.pError, s.ng, wi), 0.0);
    path.direction = vec4(wi, pdf);
    path.info.z = depth + 1u;
    uint out_ = atomicAdd(control.counts[((pc.bounce + 1u) & 1u)], 1u);
    rayQueues[outQueueBase() + out_] = id;
  }
  paths[id] = path;
}
