#version 460
#extension GL_GOOGLE_include_directive : require
// Stage 5: each finished path's estimate into its pixel's batch sums. A pass holds one path per pixel, so no
// atomics. Non-finite estimates are counted and left out, never written.
#include "common.glsl"

void main() {
  uint id = invocationIndex();
  if (id >= pc.pathCount) return;
  PathState p = paths[id];
  uint pixel = p.info.x;
  vec3 L = p.radiance.rgb;
  if (allFinite(L) && allFinite(L * L)) {
    film[pixel].sum += vec4(L, 1.0);
    film[pixel].sumSq.rgb += L * L;
  } else {
    film[pixel].sumSq.w += 1.0;
  }
}
