#version 460
#extension GL_GOOGLE_include_directive : require
// One invocation: turns the incoming ray queue's size into dispatch arguments, empties the outgoing queues,
// counts rays, empties the deep-walk queue, and arms the film accumulation once no path is alive.
#include "common.glsl"

void main() {
  if (gl_GlobalInvocationID.x != 0u) return;
  uint n = inQueueCount();
  control.rayArgs = uvec4((n + gl_WorkGroupSize.x - 1u) / gl_WorkGroupSize.x, 1u, 1u, 0u);
  queueStats[min(pc.bounce, kQueueStatsBounces - 1u)].x += n;  // queue occupancy, for bench-kernels
  if (pc.bounce == 0u) control.cameraRays += n;
  else control.extensionRays += n;
  control.rayQueueCount[(pc.bounce + 1u) & 1u] = 0u;
  control.shadowQueueCount = 0u;
  control.copyQueueCount = 0u;
  control.extraShadowRays = 0u;
  control.deepArgs = uvec4(0u, 1u, 1u, 0u);  // intersect's deferred walks start empty
  uint accumulateGroups = (pc.pixelCount + gl_WorkGroupSize.x - 1u) / gl_WorkGroupSize.x;
  control.accumulateArgs = uvec4(n == 0u ? accumulateGroups : 0u, 1u, 1u, 0u);
}
