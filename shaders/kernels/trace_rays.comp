#version 460
#extension GL_GOOGLE_include_directive : require
// Traces an array of rays (closest or any hit): the traversal under test and under benchmark.
#include "common.glsl"
#include "traversal.glsl"

layout(binding = BINDING_TEST_RAYS, std430) readonly buffer TestRays { TestRay testRays[]; };
layout(binding = BINDING_TEST_HITS, std430) writeonly buffer TestHits { vec4 testHits[]; };

void main() {
  uint id = invocationIndex();
  if (id >= pc.pathCount) return;
  TestRay r = testRays[id];
  bool complete;
  vec4 h = traceRay(r.origin.xyz, r.direction.xyz, r.origin.w, kAnyHit != 0u, complete);
  if (!complete) h.x = uintBitsToFloat(0x7fc00000u);  // a walk cut short reads as t = NaN
  testHits[id] = h;
}
