#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_atomic_float : require
// Stage 3b under EARS: the copies a bounce's vertices split off (ears_shade.glsl), one per invocation: the
// surface and material at the stored hit again, then the copy's light samples and BSDF continuation.
#include "common.glsl"
#include "shading.glsl"
#include "shade_output.glsl"
#include "ears_shade.glsl"

void shadeCopy(uint i) {
  uint target = loadQueued(copyQueueBase() + i);
  PathState path = loadPath(target);
  vec4 hit = loadHit(floatBitsToUint(path.radiance.z));  // the parent's: no stage writes hits before the next intersect
  vec3 wo = -path.direction.xyz;
  SurfacePoint s = surfaceAt(floatBitsToUint(hit.w), hit.yz, wo);
  Material m = loadMaterial(s.material);
  takeSpectralChannel(path, m);  // taken already where the parent took it (its queued path is after that)
  GltfMaterial gm = shadeSurface(m, s, wo);
  vec3 poisoned;
  // qL is 0 unless the light cells decide (kEarsLightMax > 0): as a constant it folds the copy's light-sample loop
  // into straight code, which llvmpipe otherwise runs as a loop with its live state spilled around it.
  float qL = kEarsLightMax > 0.0 ? path.radiance.w : 0.0;
  float rays = shadeEarsCopy(path, target, floatBitsToUint(path.radiance.z), s, gm, wo, wo * s.frame, path.radiance.x,
                             qL, floatBitsToUint(path.radiance.y), earsCellKey(s.p, s.ng, earsHeader.grid),
                             vec3(0.0), poisoned);
  addToEarsSample(target, path.rootPath, poisoned, vec3(0.0), rays);
}

void main() {
  uint i = invocationIndex();
  if (i < control.copyQueueCount) shadeCopy(i);
  flushRareCounts();
}
