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

void main() {
  uint id = invocationIndex();
  if (id >= pc.pathCount) return;
  PathState path = cameraPath(id);
  vec3 radiance = vec3(0.0);
  uint camera = 0u, extension = 0u, shadow = 0u, cut = 0u;
  bool alive = path.throughput.x > 0.0;  // camera-ray roulette may end it at once
  camera = alive ? 1u : 0u;
  while (alive) {
    bool complete;
    vec4 hit = traceRay(path.origin.xyz, path.direction.xyz, 3.0e38, false, complete);
    if (!complete) {  // as in intersect: counted, and the sample poisoned
      ++cut;
      radiance += vec3(kNaN);
      break;
    }
    uint tri = floatBitsToUint(hit.w);
    vec3 wo = -path.direction.xyz;
    if (tri == kMissPrimitive) {
      radiance += path.throughput.rgb * pc.background.rgb;
      break;
    }
    SurfacePoint s = surfaceAt(tri, hit.yz, wo);
    Material m = materials[s.material];
    uint depth = path.info.z;
    vec3 gathered = emissionAt(path, s, m, tri, hit, wo);
    GltfMaterial gm = gltfMaterial(m);
    vec3 woLocal = wo * s.frame;
    if (belowDepthCap(depth) && kHasLights != 0u && kNee != 0u) {
      uint samples = lightSamplesAt(depth);
      for (uint j = 0u; j < samples; ++j) {
        ShadowRay ray;
        if (!prepareLightSample(path, s, gm, wo, j, samples, ray)) continue;
        ++shadow;
        bool visible;
        vec4 blocker = traceRay(ray.origin.xyz, ray.direction.xyz, ray.origin.w, true, visible);
        if (!visible) {
          ++cut;
          gathered += vec3(kNaN);
        } else if (floatBitsToUint(blocker.w) == kMissPrimitive) {
          gathered += ray.contribution.rgb;
        }
      }
    }
    PathState next;
    alive = continuationIsUseful(depth) && continuePath(path, id, s, gm, woLocal, 0u, 1.0, gathered, next);
    if (!allFinite(gathered)) atomicAdd(control.nonfinite.x, 1u);
    radiance += gathered;
    if (alive) {
      path = next;
      ++extension;
    }
  }
  paths[id].radiance = vec4(radiance, 0.0);
  // Ray counts, one atomic per path and counter (llvmpipe runs atomics lane by lane).
  if (camera > 0u) atomicAdd(control.totals.x, camera);
  if (extension > 0u) atomicAdd(control.totals.y, extension);
  if (shadow > 0u) atomicAdd(control.totals.z, shadow);
  if (cut > 0u) atomicAdd(control.nonfinite.w, cut);
}
