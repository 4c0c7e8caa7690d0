#version 460
#extension GL_GOOGLE_include_directive : require
// One invocation: dispatch arguments of EARS's copy stage (ears_copies.comp) from the copy queue's size.
#include "common.glsl"

void main() {
  if (gl_GlobalInvocationID.x != 0u) return;
  uint n = control.copyQueueCount;
  control.copyArgs = uvec4((n + gl_WorkGroupSize.x - 1u) / gl_WorkGroupSize.x, 1u, 1u, 0u);
}
