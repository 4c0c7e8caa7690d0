#version 460
#extension GL_GOOGLE_include_directive : require
// One invocation: dispatch arguments of the shadow stage from the shadow queue's size; empties the deep-walk
// queue.
#include "common.glsl"

void main() {
  if (gl_GlobalInvocationID.x != 0u) return;
  uint n = control.shadowQueueCount;
  control.shadowArgs = uvec4((n + gl_WorkGroupSize.x - 1u) / gl_WorkGroupSize.x, 1u, 1u, 0u);
  queueStats[min(pc.bounce, kQueueStatsBounces - 1u)].y += n;
  control.shadowRays += n;
  control.deepArgs = uvec4(0u, 1u, 1u, 0u);  // the shadow stage's deferred walks start empty
}
