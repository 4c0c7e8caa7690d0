#version 460
#extension GL_GOOGLE_include_directive : require
// EARS training, step 3 of 3: each cell's sampling statistics from its training sums of every pass so far, for
// the next pass's factors (ears.h earsSampling). pc.pathCount: the cells.
#include "common.glsl"

layout(binding = BINDING_EARS_SAMPLING, TEXEL_FORMAT_EARS_SAMPLING) uniform writeonly imageBuffer earsLearned;

void main() {
  uint i = invocationIndex();
  if (i >= pc.pathCount) return;
  EarsCell c = earsCells[i];
  if (!(c.sum.w > 0.0)) return;
  vec4 moment, variance;
  earsSampling(c.sum, c.sumSquares, moment, variance);
  imageStore(earsLearned, int(kEarsSamplingTexels * i), moment);
  imageStore(earsLearned, int(kEarsSamplingTexels * i + 1u), variance);
}
