#version 460
#extension GL_GOOGLE_include_directive : require
// Stage 5: each finished path's estimate into its pixel's batch sums. One invocation per pixel walks that
// pixel's samples of the pass, so no atomics. Non-finite estimates are counted and left out, never written.
#include "common.glsl"

void main() {
  uint i = invocationIndex();
  if (i >= pc.pixelCount) return;
  uint pixel = pc.firstPixel + i;
  FilmPixel f = film[pixel];
  for (uint s = 0u; s < pc.samplesPerPass; ++s) {
    vec3 L = paths[s * pc.pixelCount + i].radiance.rgb;
    if (allFinite(L) && allFinite(L * L)) {
      f.sum += vec4(L, 1.0);
      f.sumSq.rgb += L * L;
    } else {
      f.sumSq.w += 1.0;
    }
  }
  film[pixel] = f;
}
