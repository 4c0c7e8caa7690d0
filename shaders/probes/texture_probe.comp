#version 460
#extension GL_GOOGLE_include_directive : require
// Texture lookups as the shading code makes them (textures.glsl), for tests/gpu/texture_probe_test.cpp: lookup i
// reads TestRay i (origin.xy: uv0, origin.zw: uv1, direction.x: material index bits, direction.y: slot 0-3 as
// float bits, direction.z: 1 for sRGB) and writes the filtered RGBA to hit i.
#include "common.glsl"
#include "textures.glsl"

layout(binding = BINDING_TEST_RAYS, std430) readonly buffer Lookups { TestRay lookups[]; };
layout(binding = BINDING_TEST_HITS, std430) writeonly buffer Results { vec4 results[]; };

void main() {
  uint i = invocationIndex();
  if (i >= pc.pathCount) return;
  TestRay r = lookups[i];
  Material m = loadMaterial(floatBitsToUint(r.direction.x));
  uint slot = floatBitsToUint(r.direction.y);
  TextureSlot t = slot == 0u ? m.baseColorTexture
                             : (slot == 1u ? m.metallicRoughnessTexture : (slot == 2u ? m.normalTexture : m.emissiveTexture));
  SurfaceAttributes a;
  a.uv0 = r.origin.xy;
  a.uv1 = r.origin.zw;
  a.color = vec4(1.0);
  a.tangent = vec4(1.0, 0.0, 0.0, 1.0);
  results[i] = sampleTexture(t.texture, slotUv(t, a), r.direction.z > 0.5);
}
