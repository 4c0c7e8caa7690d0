#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_atomic_float : require
// EARS training, step 2 of 3: each record (one copy of a training vertex) adds its Lr (what its subtree gathered,
// per unit throughput at the vertex) and its rays to the training sums of its cell at every level, and its first
// light sample's v and ray to the light cell beside each (ears.h earsLightCell), then is
// cleared for the next pass. One invocation per listed record, then one per training slot (as ears_gather), which
// it clears. pc.pathCount: the pass's training camera paths.
#include "common.glsl"

// One training sample x (per channel) and its rays into a cell's sums.
void addToCell(uint cell, vec3 x, float rays) {
  atomicAdd(earsCells[cell].sum.r, x.r);
  atomicAdd(earsCells[cell].sum.g, x.g);
  atomicAdd(earsCells[cell].sum.b, x.b);
  atomicAdd(earsCells[cell].sum.w, 1.0);
  atomicAdd(earsCells[cell].sumSquares.r, x.r * x.r);
  atomicAdd(earsCells[cell].sumSquares.g, x.g * x.g);
  atomicAdd(earsCells[cell].sumSquares.b, x.b * x.b);
  atomicAdd(earsCells[cell].sumSquares.w, rays);
}

void main() {
  uint records = earsHeader.trainingRecords, n = invocationIndex();
  if (n >= records + pc.pathCount + earsHeader.trainingChildren) return;
  if (n >= records) {
    earsSlots[earsTrainingSlot(n - records, pc.pathCount)] = EarsSlot(vec4(0.0), 0u, 0u, 0u, 0u);
    return;
  }
  uint i = earsTrainingList[n];
  EarsRecord r = earsRecords[i];
  uint keyCode = floatBitsToUint(r.scale.w);
  if (keyCode == 0u) return;
  earsRecords[i].scale.w = 0.0;
  vec3 lr = r.gathered.rgb * r.scale.rgb;
  float rays = max(r.gathered.w, 0.0);
  bool copyFinite = allFinite(lr * lr) && !isnan(rays) && !isinf(rays);  // lr^2 finite: lr is too
  // The copy's first light sample: v where its ray was unoccluded, else 0; a ray where one was traced.
  vec4 light = kEarsLightMax > 0.0 ? earsRecordVec4s[earsLightRecord(i)] : vec4(0.0);
  vec3 v = light.w == kEarsLightUnoccluded ? light.rgb : vec3(0.0);
  float lightRays = light.w >= kEarsLightTraced ? 1.0 : 0.0;
  bool lightSampled = kEarsLightMax > 0.0 && light.w != kEarsLightNone && allFinite(v * v);
  earsCellWords[earsKeyWord(earsCellIndex(keyCode - 1u, 0u, earsHeader.cellMask), earsTableCells())] = keyCode;
  for (uint level = 0u; level < kEarsLevels; ++level) {
    uint cell = earsCellIndex(keyCode - 1u, level, earsHeader.cellMask);
    if (copyFinite) addToCell(cell, lr, rays);
    if (lightSampled) addToCell(earsLightCell(cell, earsHeader.cellMask), v, lightRays);
  }
}
