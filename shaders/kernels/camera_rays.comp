#version 460
#extension GL_GOOGLE_include_directive : require
// Stage 1: one camera ray per path (one sample of one pixel, camera.glsl), pushed onto ray queue 0; a path the
// camera-ray roulette ended is not queued.
#include "common.glsl"
#include "camera.glsl"

void main() {
  uint id = invocationIndex();
  if (kCameraRouletteQ == 0.0 && id == 0u) control.rayQueueCount[0] = pc.pathCount;
  if (id >= pc.pathCount) return;
  PathState p = cameraPath(id);
  storePath(id, p);
  if (kCameraRouletteQ == 0.0) rayQueues[id] = id;
  else if (p.throughput.x > 0.0) rayQueues[atomicAdd(control.rayQueueCount[0], 1u)] = id;
}
