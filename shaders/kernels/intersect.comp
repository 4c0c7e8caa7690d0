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
  bool complete;
  hits[id] = traceRay(p.origin.xyz, p.direction.xyz, 3.0e38, false, complete);
  if (!complete) {  // counted, and the sample poisoned so accumulate excludes it: never a silently wrong hit
    atomicAdd(control.nonfinite.w, 1u);
    paths[p.info.w].radiance.r = uintBitsToFloat(0x7fc00000u);
  }
}
