#version 460
#extension GL_GOOGLE_include_directive : require
// The GLSL side of every host <-> GPU encoding, for tests/layout_probe_test.cpp: one invocation reads what the
// host wrote and writes it back word by word, by field name, so the test compares the two languages' views.
// kEchoStructs = 1: the fields of PathState, ShadowRay, Material, FilmPixel, Control and PushConstants, each
// read from a buffer the host filled with a pattern, then two hits; the path, shadow ray, film pixel and hits are
// also stored back into the next slots. kEchoStructs = 0: the scene texels decoded with the shared
// functions (scene_layout.h, bvh_layout.h): pc.pathCount triangles, pc.pixelCount light picks, pc.width wide
// nodes and pc.height leaf entries.
#include "common.glsl"
#include "bvh_layout.h"

layout(constant_id = 100) const uint kEchoStructs = 1u;
layout(binding = BINDING_TEST_HITS, std430) writeonly buffer Words { uint words[]; };

uint next = 0u;
void put(uint v) { words[next++] = v; }
void putf(float v) { put(floatBitsToUint(v)); }
void put3(vec3 v) { putf(v.x); putf(v.y); putf(v.z); }
void put4(vec4 v) { putf(v.x); putf(v.y); putf(v.z); putf(v.w); }
void put4u(uvec4 v) { put(v.x); put(v.y); put(v.z); put(v.w); }
void putSlot(TextureSlot t) { put4(t.uvRow0); put4(t.uvRow1); put(t.texture); put(t.texCoord); put(t.unusedSlot0); put(t.unusedSlot1); }

void echoStructs() {
  PathState p = loadPath(0u);
  put4(p.origin); put4(p.direction); put4(p.throughput); put4(p.radiance);
  put(p.pixel); put(p.rngKey); put(p.depth); put(p.rootPath);
  ShadowRay r = loadShadowRay(0u);
  put4(r.origin); put4(r.direction); put4(r.contribution);
  Material m = loadMaterial(0u);
  put4(m.baseColor); put3(m.emission); put(m.flags);
  putf(m.metallic); putf(m.roughness); putf(m.specular); putf(m.alphaCutoff);
  putSlot(m.baseColorTexture); putSlot(m.metallicRoughnessTexture); putSlot(m.normalTexture); putSlot(m.emissiveTexture);
  put4(m.specularColor); put4(m.attenuation); put4(m.sheen);
  putf(m.clearcoat); putf(m.clearcoatRoughness); put(m.volumetric); put(m.unusedMaterial0);
  putSlot(m.transmissionTexture); putSlot(m.clearcoatTexture); putSlot(m.clearcoatRoughnessTexture);
  putSlot(m.clearcoatNormalTexture); putSlot(m.sheenColorTexture); putSlot(m.sheenRoughnessTexture);
  putSlot(m.specularTexture); putSlot(m.specularColorTexture);
  put4(m.iridescence); putSlot(m.iridescenceTexture); putSlot(m.iridescenceThicknessTexture);
  put4(m.anisotropy); putSlot(m.anisotropyTexture); put4(m.dispersion);
  FilmPixel f = film[0];
  put4(f.sum); put4(f.sumSq); put4(f.sumHigh); put4(f.sumSqHigh);
  for (uint r = 0u; r + 1u < kMaxSampleReplicates; ++r) put4(f.replicate[r]);
  put(control.rayQueueCount[0]); put(control.rayQueueCount[1]); put(control.shadowQueueCount); put(control.splitChildren);
  put4u(control.rayArgs); put4u(control.shadowArgs); put4u(control.accumulateArgs);
  put(control.cameraRays); put(control.extensionRays); put(control.shadowRays); put(control.copyQueueCount);
  put(control.nonfiniteEmission); put(control.nonfiniteLightSamples); put(control.nonfiniteThroughput); put(control.walksCut);
  put4u(control.deepArgs);
  put(control.deepWalksDeferred); put(control.deepWalksTraced); put(control.extraShadowRays); put(control.splitsRefused);
  put(control.walkIterations); put(control.walkNodeSteps); put(control.walkTriangleTests); put(control.walkSlowestLaneIterations);
  put4u(control.copyArgs);
  put(pc.pathCount); put(pc.firstPixel); put(pc.sampleIndex); put(pc.bounce);
  put(pc.width); put(pc.height); put(pc.seed); put(pc.queueCapacity);
  put4(pc.cameraOrigin); put4(pc.cameraForward); put4(pc.cameraRight); put4(pc.cameraUp); put4(pc.background);
  put(pc.pixelCount); put(pc.samplesPerPass); put(pc.earsTrains); put(pc.sampleRuns);
  // Hits: a triangle index in w (a denormal as a float) and a miss (kMissPrimitive, a NaN) must keep their bits.
  put4(loadHit(0u)); put4(loadHit(1u));
  // The stores (64-bit halves, common.glsl): slot 1 gets what slot 0 holds; the host compares the bytes.
  storePath(1u, p);
  storeShadowRay(1u, r);
  storeHit(2u, loadHit(0u));
  storeHit(3u, loadHit(1u));
  storeFilmPixel(1u, f);
}

void decodeScene() {
  for (uint t = 0u; t < pc.pathCount; ++t) {
    vec3 v0, v1, v2;
    triangleVertices(t, v0, v1, v2);
    put3(v0); put3(v1); put3(v2);
    putf(imageLoad(triangles, int(kTriangleTexels * t + kTriangleLightPmfTexel)).w);
    uvec4 info = imageLoad(triangleInfo, int(t));
    put(triangleInfoMaterial(info));
    for (uint k = 0u; k < 3u; ++k) {
      vec3 n = decodeOctahedral(info[k]);
      put3(n);
      put(encodeOctahedral(n));
    }
  }
  uint lightCount = uint(imageSize(lights));
  for (uint k = 0u; k < pc.pixelCount; ++k) {
    float scaled = (float(k) + 0.5) / float(pc.pixelCount) * float(lightCount);
    uint slot = aliasSlot(scaled, lightCount);
    uvec4 chosen = imageLoad(lights, int(aliasChoice(scaled, slot, imageLoad(lights, int(slot)))));
    put(lightEntryIndex(chosen));
    putf(lightEntryPmf(chosen));
  }
  for (uint w = 0u; w < pc.width; ++w) {
    int base = int(kBvhNodeTexels * w);
    uvec4 grid = imageLoad(bvhNodes, base + int(kBvhWideGridTexel));
    uvec4 xy = imageLoad(bvhNodes, base + int(kBvhWideXyPlanesTexel));
    uvec4 z = imageLoad(bvhNodes, base + int(kBvhWideZPlanesTexel));
    put3(uintBitsToFloat(grid.xyz));
    put3(bvhWideStep(grid.w));
    for (uint axis = 0u; axis < 3u; ++axis) {
      uvec2 planes = bvhWidePlaneWords(xy, z, axis);
      put4u(bvhWidePlaneSteps(planes.x));
      put4u(bvhWidePlaneSteps(planes.y));
    }
    uvec4 children = imageLoad(bvhNodes, base + int(kBvhWideChildTexel));
    for (uint c = 0u; c < 4u; ++c) {
      uint e = children[c];
      bool leaf = e != kBvhEmptySlot && bvhIsLeaf(e);
      put(leaf ? 1u : 0u);
      put(leaf ? bvhLeafFirst(e) : e);
      put(leaf ? bvhLeafCount(e) : 0u);
    }
  }
  for (uint i = 0u; i < pc.height; ++i) {
    uint first = (i * 2654435761u) % kBvhLeafFirstLimit, count = 1u + i % kBvhMaxLeafSize;
    uint e = bvhLeafEntry(first, count);
    put(e); put(bvhLeafFirst(e)); put(bvhLeafCount(e)); put(bvhIsLeaf(e) ? 1u : 0u);
  }
}

void main() {
  if (invocationIndex() != 0u) return;
  if (kEchoStructs != 0u) echoStructs();
  else decodeScene();
}
