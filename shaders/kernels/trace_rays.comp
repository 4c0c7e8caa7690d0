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
  testHits[id] = traceRay(r.origin.xyz, r.direction.xyz, r.origin.w, kAnyHit != 0u);
}
