#version 460
#extension GL_GOOGLE_include_directive : require
// Traces an array of rays (closest or any hit): the traversal under test and under benchmark. Built as intersect
// is: a register-stack pass, and with VKMC_DEEP_PASS the pass over the walks it deferred.
#include "common.glsl"
#include "traversal.glsl"
#include "deferred_walk.glsl"

// As the renderer's intersect reads its paths and stores its hits (common.glsl): the rays through a texel view of
// their buffer (bound at BINDING_PATH_TEXELS, two texels a ray), the hits in 64-bit halves.
layout(binding = BINDING_TEST_HITS, std430) writeonly buffer TestHits { u64vec2 testHits[]; };

TestRay loadTestRay(uint id) {
  int t = int(2u * id);
  return TestRay(uintBitsToFloat(imageLoad(pathTexels, t)), uintBitsToFloat(imageLoad(pathTexels, t + 1)));
}

void main() {
  uint id;
  if (!walkItem(pc.pathCount, id)) return;
  TestRay r = loadTestRay(id);
  vec4 h;
  bool complete;
  if (!traceItem(id, r.origin.xyz, r.direction.xyz, r.origin.w, kAnyHit != 0u, h, complete)) return;
  if (!complete) h.x = uintBitsToFloat(0x7fc00000u);  // a walk cut short reads as t = NaN
  testHits[id] = wordPairs(h);
}
