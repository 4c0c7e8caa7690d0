#version 460
#extension GL_GOOGLE_include_directive : require
// EARS training, step 3 of 3: each cell's sampling statistics from its training sums of every pass so far, for
// the next pass's factors (ears.h earsSampling). pc.pathCount: the cells.
#include "common.glsl"

void main() {
  uint i = invocationIndex();
  if (i >= pc.pathCount) return;
  EarsCell c = earsCells[i];
  if (!(c.sum.w > 0.0)) return;
  earsSampling(c.sum, c.sumSquares, c.momentPerCost, c.variancePerCost);
  earsCells[i].momentPerCost = c.momentPerCost;
  earsCells[i].variancePerCost = c.variancePerCost;
}
