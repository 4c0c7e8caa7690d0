#version 460
#extension GL_GOOGLE_include_directive : require
// Traces an array of rays (closest or any hit): the traversal under test and under benchmark. Built as intersect
// is: a register-stack pass, and with VKMC_DEEP_PASS the pass over the walks it deferred.
#include "common.glsl"
#include "traversal.glsl"
#include "deferred_walk.glsl"

layout(binding = BINDING_TEST_RAYS, std430) readonly buffer TestRays { TestRay testRays[]; };
layout(binding = BINDING_TEST_HITS, std430) writeonly buffer TestHits { vec4 testHits[]; };

void main() {
  uint id;
  if (!walkItem(pc.pathCount, id)) return;
  TestRay r = testRays[id];
  vec4 h;
  bool complete;
  if (!traceItem(id, r.origin.xyz, r.direction.xyz, r.origin.w, kAnyHit != 0u, h, complete)) return;
  if (!complete) h.x = uintBitsToFloat(0x7fc00000u);  // a walk cut short reads as t = NaN
  testHits[id] = h;
}
