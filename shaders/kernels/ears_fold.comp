#version 460
#extension GL_GOOGLE_include_directive : require
// EARS training, step 3 of 3: for each finest-level cell whose key a slot holds (ears.h earsKeyWord), what a
// vertex in it reads from now on (the rest of this pass, the next ones): its levels' statistics from their
// training sums of every pass so far, shrunk coarsest first (earsResolveLevel), and its light cells' alike, with
// the key they were resolved for. pc.pathCount: the copies' cells.
#include "common.glsl"

layout(binding = BINDING_EARS_SAMPLING, TEXEL_FORMAT_EARS_SAMPLING) uniform writeonly imageBuffer earsLearned;

// The statistics resolved for finest cell `cell` (or its light cell, `light`) into its texels.
void resolve(uint keyCode, uint cell, bool light) {
  vec3 moment = vec3(0.0), variance = vec3(0.0);
  float copies = 0.0;
  for (int level = int(kEarsLevels) - 1; level >= 0; --level) {
    uint c = earsCellIndex(keyCode - 1u, uint(level), earsHeader.cellMask);
    if (light) c = earsLightCell(c, earsHeader.cellMask);
    earsResolveLevel(earsCells[c].sum, earsCells[c].sumSquares, moment, variance, copies);
  }
  imageStore(earsLearned, int(kEarsSamplingTexels * cell), vec4(moment, copies));
  imageStore(earsLearned, int(kEarsSamplingTexels * cell + 1u), vec4(variance, float(keyCode)));
}

void main() {
  uint i = invocationIndex();
  if (i >= pc.pathCount) return;
  uint keyCode = earsCellWords[earsKeyWord(i, earsTableCells())];
  if (keyCode == 0u) return;
  resolve(keyCode, i, false);
  if (kEarsLightMax > 0.0) resolve(keyCode, earsLightCell(i, earsHeader.cellMask), true);
}
