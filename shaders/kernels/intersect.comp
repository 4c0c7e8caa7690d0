#version 460
#extension GL_GOOGLE_include_directive : require
// Stage 2: closest hit of every queued ray.
#include "common.glsl"
#include "traversal.glsl"

void main() {
  uint slot = invocationIndex();
  if (slot >= inQueueCount()) return;
  uint id = rayQueues[inQueueBase() + slot];
  PathState p = paths[id];
  hits[id] = traceRay(p.origin.xyz, p.direction.xyz, 3.0e38, false);
}
