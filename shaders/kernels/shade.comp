#version 460
#extension GL_GOOGLE_include_directive : require
#ifdef VKMC_FLOAT_ATOMICS
#extension GL_EXT_shader_atomic_float : require
#endif
// Stage 3: at each hit, the estimator chosen by specialization constants (shading.glsl): emission,
// MIS-weighted against light sampling for BSDF-sampled rays; next-event estimation with M light samples (M > 1
// splits the first kSplitDepth bounces), each queued as a shadow ray, optionally rouletted when its
// contribution is tiny against the pixel's running estimate; the BSDF continuation (uniform, cosine or glTF BRDF
// sampling), split K ways at the first bounces, and Russian roulette on it. Escaped rays gather the background and the environment light.
#include "common.glsl"
#include "shading.glsl"

#include "shade_output.glsl"
#include "ears_shade.glsl"

void shadeQueued(uint slot) {
  uint id = loadQueued(inQueueBase() + slot);
  PathState path = loadPath(id);
  vec4 hit = loadHit(id);
  uint tri = floatBitsToUint(hit.w);
  uint root = path.rootPath;
  vec3 wo = -path.direction.xyz;
  // Pilot of efficiency roulette: what the sample had gathered when the previous vertex decided to go on.
  if (kRecordDepthStats != 0u && path.depth >= 1u && path.depth <= kRouletteTableDepths)
    depthStats[id * kRouletteTableDepths + path.depth - 1u].y = luminance(path.radiance.rgb);
  if (tri == kMissPrimitive) {
    addToSample(id, root, escapedRadiance(path));
    return;
  }
  SurfacePoint s = surfaceAt(tri, hit.yz, wo);
  Material m = loadMaterial(s.material);
  path.throughput.rgb *= volumeTransmittance(m, s, hit.x);
  takeSpectralChannel(path, m);
  uint depth = path.depth;
  GltfMaterial gm = shadeSurface(m, s, wo);
  vec3 gathered = emissionAt(path, s, m, tri, hit, wo);
  vec3 woLocal = wo * s.frame;
#ifdef VKMC_FLOAT_ATOMICS  // EARS's copies add to shared roots: only the atomic variant runs it
  if (kRouletteMode == kRouletteEars) {
    shadeEarsVertex(path, id, s, gm, wo, woLocal, gathered);  // the hit's emission: the vertex before gathered it
    return;
  }
#endif
  if (belowDepthCap(depth) && kHasLights != 0u && kNee != 0u) {
    uint samples = lightSamplesAt(depth);
    for (uint j = 0u; j < samples; ++j) {
      ShadowRay ray;
      if (prepareLightSample(path, id, s, gm, wo, j, samples, 1.0 / float(samples), ray)) storeShadowRay(shadowQueueSlot(), ray);
    }
  }

  // BSDF continuations: q = kBsdfSamples at split depths gives floor(q + u) children weighted 1/q; child 0
  // continues in this slot, the others take slots from the pool (none left: no split, weight 1, unbiased).
  float q = splitFactorAt(depth, kSplitDepth, kBsdfSamples);
  uint children = continuationIsUseful(depth) ? (q > 1.0 ? splitCount(q, sampleU(pathStream(path), bounceDim(depth, kDimSplit))) : 1u) : 0u;
  uint firstChild = 0u;
  if (children > 1u && !reserveChildSlots(children - 1u, firstChild)) {
    children = 1u;
    q = 1.0;
  }
  for (uint c = 0u; c < children; ++c) {
    PathState next;
    if (!continuePath(path, id, s, gm, woLocal, c, q, gathered, next)) continue;
    queueContinuation(c == 0u ? id : firstChild + c - 1u, next, c > 0u);
  }
  addToSample(id, root, gathered);
}

void main() {
  uint slot = invocationIndex();
  if (slot < inQueueCount()) shadeQueued(slot);
  flushRareCounts();
#ifdef VKMC_FLOAT_ATOMICS
  if (kRouletteMode == kRouletteEars) flushEarsDecisions();
#endif
}
