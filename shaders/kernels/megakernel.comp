#version 460
#extension GL_GOOGLE_include_directive : require
// The megakernel integrator: one invocation follows one sample's whole path, with the same stage functions as
// the wavefront (camera.glsl, traversal.glsl, shading.glsl), shadow rays traced where they are made, and leaves
// its estimate in its path slot for accumulate. One dispatch per sample pass; no queues, no indirect dispatches,
// no path state between stages, at the price of divergence (lanes of a SIMD group run paths of different
// lengths). BSDF splitting (several continuations per vertex) needs the wavefront's path pool: the host refuses
// it here.
#include "common.glsl"
#include "camera.glsl"
#include "traversal.glsl"
#include "shading.glsl"

#define kNaN uintBitsToFloat(0x7fc00000u)

// One walk per loop iteration, the path's next ray or its vertex's next light sample, through one traceRay call
// site: the kernel holds one copy of the walk (and of its inline deep walk) instead of two, which is what its
// first-dispatch compile on llvmpipe costs. Rays, random numbers and sums are those of the two-loop form.
void tracePath(uint id) {
  PathState path = cameraPath(id);
  vec3 radiance = vec3(0.0);
  uint camera = 0u, extension = 0u, shadow = 0u, cut = 0u;
  bool alive = path.throughput.x > 0.0;  // camera-ray roulette may end it at once
  camera = alive ? 1u : 0u;
  // The vertex being shaded while its light samples are traced.
  SurfacePoint s;
  GltfMaterial gm;
  vec3 wo = vec3(0.0), woLocal = vec3(0.0), gathered = vec3(0.0);
  uint samples = 0u, j = 0u;
  ShadowRay ray;
  bool tracingLightSample = false;
  while (alive) {
    bool anyHit = tracingLightSample;
    vec3 origin = anyHit ? ray.origin.xyz : path.origin.xyz;
    vec3 dir = anyHit ? ray.direction.xyz : path.direction.xyz;
    float tMax = anyHit ? kShadowRayTMax : 3.0e38;
    bool complete;
    walkRayKey = anyHit ? floatBitsToUint(ray.contribution.w) : alphaKey(streamHash(pathStream(path)), bounceDim(path.depth, 0u));
    vec4 hit = traceRay(origin, dir, tMax, anyHit, complete);
    if (anyHit) {
      if (!complete) {  // as in shadow: counted, and the sample poisoned
        ++cut;
        gathered += vec3(kNaN);
      } else if (floatBitsToUint(hit.w) == kMissPrimitive) {
        gathered += ray.contribution.rgb;
      }
      ++j;
    } else {
      uint tri = floatBitsToUint(hit.w);
      wo = -path.direction.xyz;
      if (!complete) {  // as in intersect: counted, and the sample poisoned
        ++cut;
        radiance += vec3(kNaN);
        break;
      }
      if (tri == kMissPrimitive) {
        radiance += escapedRadiance(path);
        break;
      }
      s = surfaceAt(tri, hit.yz, wo);
      Material m = loadMaterial(s.material);
      path.throughput.rgb *= volumeTransmittance(m, s, hit.x);
      takeSpectralChannel(path, m);
      uint depth = path.depth;
      gm = shadeSurface(m, s, wo);
      gathered = emissionAt(path, s, m, tri, hit, wo);
      woLocal = wo * s.frame;
      samples = belowDepthCap(depth) && kHasLights != 0u && kNee != 0u ? lightSamplesAt(depth) : 0u;
      j = 0u;
    }
    // The vertex's next light sample, if any is left; else the vertex is done and the path continues.
    tracingLightSample = false;
    for (; j < samples; ++j) {
      if (prepareLightSample(path, id, s, gm, wo, j, samples, 1.0 / float(samples), ray)) {
        ++shadow;
        tracingLightSample = true;
        break;
      }
    }
    if (!tracingLightSample) {
      PathState next;
      alive = continuationIsUseful(path.depth) && continuePath(path, id, s, gm, woLocal, 0u, 1.0, gathered, next);
      if (!allFinite(gathered)) ++rareCounts.x;
      radiance += gathered;
      if (alive) {
        path = next;
        ++extension;
      }
    }
  }
  storeRadiance(id, vec4(radiance, path.radiance.w));  // w: the pixel-filter weight
  storePathBookkeeping(id, path);                       // its depth: the sample's cost (accumulate)
  // Ray counts, one atomic per path and counter (llvmpipe runs atomics lane by lane).
  if (camera > 0u) atomicAdd(control.cameraRays, camera);
  if (extension > 0u) atomicAdd(control.extensionRays, extension);
  if (shadow > 0u) atomicAdd(control.shadowRays, shadow);
  if (cut > 0u) atomicAdd(control.walksCut, cut);
}

void main() {
  uint id = invocationIndex();
  if (id < pc.pathCount) tracePath(id);
  flushRareCounts();
}
