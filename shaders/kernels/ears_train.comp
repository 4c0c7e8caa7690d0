#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_atomic_float : require
// EARS training, step 2 of 3: each record (one copy of a training vertex) adds its Lr (what its subtree gathered,
// per unit throughput at the vertex) and its rays to the training sums of its cell at every level, then is
// cleared, as is its slot, for the next pass. pc.pathCount: the slots the pass used (kEarsDepths records each).
#include "common.glsl"

void main() {
  uint i = invocationIndex();
  if (i >= pc.pathCount * kEarsDepths) return;
  if (i % kEarsDepths == 0u) earsSlots[i / kEarsDepths] = EarsSlot(vec4(0.0), 0u, 0u, 0u, 0u);
  EarsRecord r = earsRecords[i];
  uint keyCode = floatBitsToUint(r.scale.w);
  if (keyCode == 0u) return;
  earsRecords[i].scale.w = 0.0;
  vec3 lr = r.gathered.rgb * r.scale.rgb;
  float rays = max(r.gathered.w, 0.0);
  if (!allFinite(lr * lr) || isnan(rays) || isinf(rays)) return;  // lr^2 finite: lr is too
  for (uint level = 0u; level < kEarsLevels; ++level) {
    uint cell = earsCellIndex(keyCode - 1u, level, earsHeader.cellMask);
    atomicAdd(earsCells[cell].sum.r, lr.r);
    atomicAdd(earsCells[cell].sum.g, lr.g);
    atomicAdd(earsCells[cell].sum.b, lr.b);
    atomicAdd(earsCells[cell].sum.w, 1.0);
    atomicAdd(earsCells[cell].sumSquares.r, lr.r * lr.r);
    atomicAdd(earsCells[cell].sumSquares.g, lr.g * lr.g);
    atomicAdd(earsCells[cell].sumSquares.b, lr.b * lr.b);
    atomicAdd(earsCells[cell].sumSquares.w, rays);
  }
}
