#version 460
#extension GL_GOOGLE_include_directive : require
// Stage 2: closest hit of every queued ray (built twice: the register-stack pass, and with VKMC_DEEP_PASS the
// pass over the walks it deferred).
#include "common.glsl"
#include "traversal.glsl"
#include "deferred_walk.glsl"

void main() {
  uint slot;
  if (!walkItem(inQueueCount(), slot)) return;
  uint id = loadQueued(inQueueBase() + slot);
  PathState p = loadPath(id);
  vec4 hit;
  bool complete;
  walkRayKey = alphaKey(streamHash(pathStream(p)), bounceDim(p.depth, 0u));
  if (!traceItem(slot, p.origin.xyz, p.direction.xyz, 3.0e38, false, hit, complete)) return;
  storeHit(id, hit);
  if (!complete) {  // counted, and the sample poisoned so accumulate excludes it: never a silently wrong hit
    atomicAdd(control.walksCut, 1u);
    paths[p.rootPath].radiance.r = uintBitsToFloat(0x7fc00000u);
  }
}
