#version 460
#extension GL_GOOGLE_include_directive : require
// Runs shared sampling functions on the device for tests: spherical-triangle sampling of the triangle given in
// the camera push constants (cameraOrigin = shading point, cameraForward/Right/Up = vertices). Each invocation
// writes (solid angle, sampled direction) so a host test can compare with the C++ build of the same code.
#include "common.glsl"
#include "light_sampling.h"

layout(binding = BINDING_TEST_HITS, std430) writeonly buffer Probe { vec4 probe[]; };

void main() {
  uint id = invocationIndex();
  if (id >= pc.pathCount) return;
  vec3 p = pc.cameraOrigin.xyz, a = pc.cameraForward.xyz, b = pc.cameraRight.xyz, c = pc.cameraUp.xyz;
  float omega = triangleSolidAngle(p, a, b, c);
  uint key = pathKey(pc.seed, id, 0u);
  vec3 w = sampleSphericalTriangle(p, a, b, c, vec2(randomUnit(key, 0u), randomUnit(key, 1u)), omega);
  probe[id] = vec4(w, omega);
}
