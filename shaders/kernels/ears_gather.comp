#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_atomic_float : require
// EARS training, step 1 of 3, after the last bounce of a pass's training wavefront: each path slot adds what it
// gathered and the rays it traced to its own records and to those of the copies it descends from (its parent's
// below the depth that split it off, and so on up to the camera path), so each record ends with its whole
// subtree's sums. One invocation per training slot (earsTrainingSlot): pc.pathCount training camera paths, then the
// listed children.
#include "common.glsl"

void addToRecord(uint r, vec4 value) {
  atomicAdd(earsRecords[r].gathered.r, value.r);
  atomicAdd(earsRecords[r].gathered.g, value.g);
  atomicAdd(earsRecords[r].gathered.b, value.b);
  atomicAdd(earsRecords[r].gathered.w, value.w);
}

void main() {
  uint i = invocationIndex();
  if (i >= pc.pathCount + earsHeader.trainingChildren) return;
  uint slot = earsTrainingSlot(i, pc.pathCount);
  EarsSlot own = earsSlots[slot];
  if (own.gathered == vec4(0.0)) return;
  uint s = slot, from = own.splitDepth, to = kEarsDepths, parent = own.parent;
  while (true) {
    for (uint d = from; d < to; ++d) {
      uint r = s * kEarsDepths + d;
      if (earsRecords[r].scale.w != 0.0) addToRecord(r, own.gathered);
    }
    if (parent == 0u) break;
    to = min(from, kEarsDepths);
    s = parent - 1u;
    EarsSlot up = earsSlots[s];
    from = up.splitDepth;
    parent = up.parent;
  }
}
