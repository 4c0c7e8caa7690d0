#version 460
#extension GL_GOOGLE_include_directive : require
// Stage 4: any-hit visibility of each light sample; an unoccluded one adds its contribution to its path.
// Each path has at most one shadow ray per bounce, so the add needs no atomic.
#include "common.glsl"
#include "traversal.glsl"

void main() {
  uint slot = invocationIndex();
  if (slot >= control.counts.z) return;
  ShadowRay s = shadowRays[slot];
  vec4 h = traceRay(s.origin.xyz, s.direction.xyz, s.origin.w, true);
  if (floatBitsToUint(h.w) != kMissPrimitive) return;
  uint id = floatBitsToUint(s.direction.w);
  paths[id].radiance.rgb += s.contribution.rgb;
}
