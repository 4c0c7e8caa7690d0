// Subgroup arithmetic and ballot: the walk's step counters (SPEC_WALK_STATS), EARS's histogram and the queue
// appends (shade_output.glsl); an #extension must come before any code.
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// Declarations every kernel shares: version, spec constants, push constants, scene and queue bindings.
#include "layout.h"
#include "scene_layout.h"
#include "texture_layout.h"
#include "rng.h"
#include "sampler.h"
#include "sampling.h"
#include "geometry.h"

layout(local_size_x_id = SPEC_WORKGROUP_SIZE) in;
layout(constant_id = SPEC_MAX_DEPTH) const uint kMaxDepth = 0u;
layout(constant_id = SPEC_RR_DEPTH) const uint kRouletteDepth = 3u;
layout(constant_id = SPEC_HAS_LIGHTS) const uint kHasLights = 1u;
layout(constant_id = SPEC_HAS_PUNCTUAL) const uint kHasPunctual = 1u;
layout(constant_id = SPEC_HAS_ENVIRONMENT) const uint kHasEnvironment = 1u;
layout(constant_id = SPEC_HAS_GLOSSY) const uint kHasGlossy = 1u;
layout(constant_id = SPEC_ANY_HIT) const uint kAnyHit = 0u;
layout(constant_id = SPEC_NEE) const uint kNee = 1u;
layout(constant_id = SPEC_MIS) const uint kMis = 2u;
layout(constant_id = SPEC_BSDF_SAMPLING) const uint kBsdfSampling = 2u;
layout(constant_id = SPEC_LIGHT_SAMPLING) const uint kLightSampling = 0u;
layout(constant_id = SPEC_RR_MODE) const uint kRouletteMode = 2u;
layout(constant_id = SPEC_RR_Q) const float kRouletteQ = 0.5;
layout(constant_id = SPEC_RR_C) const float kRouletteC = 0.0;
layout(constant_id = SPEC_LIGHT_SAMPLES) const uint kLightSamples = 1u;
layout(constant_id = SPEC_SPLIT_DEPTH) const uint kSplitDepth = 1u;
layout(constant_id = SPEC_SHADOW_RR_THRESHOLD) const float kShadowRouletteThreshold = 0.0;
layout(constant_id = SPEC_SHADOW_RR_Q) const float kShadowRouletteQ = 0.5;
layout(constant_id = SPEC_CAMERA_RR_Q) const float kCameraRouletteQ = 0.0;
layout(constant_id = SPEC_EARS_MAX) const float kEarsMaxFactor = 20.0;
layout(constant_id = SPEC_EARS_LIGHT_MAX) const float kEarsLightMax = 0.0;
layout(constant_id = SPEC_EARS_TRAINS) const uint kEarsTrains = 1u;
layout(constant_id = SPEC_BSDF_SAMPLES) const float kBsdfSamples = 1.0;
layout(constant_id = SPEC_RECORD_DEPTH_STATS) const uint kRecordDepthStats = 0u;
layout(constant_id = SPEC_WALK_STATS) const uint kWalkStats = 0u;
layout(constant_id = SPEC_HAS_TEXTURES) const uint kHasTextures = 1u;
layout(constant_id = SPEC_HAS_NORMAL_MAPS) const uint kHasNormalMaps = 1u;
layout(constant_id = SPEC_HAS_ALPHA) const uint kHasAlpha = 1u;
layout(constant_id = SPEC_CULLS_BACK_FACES) const uint kCullsBackFaces = 1u;
layout(constant_id = SPEC_HAS_TRANSMISSION) const uint kHasTransmission = 1u;
layout(constant_id = SPEC_HAS_CLEARCOAT) const uint kHasClearcoat = 1u;
layout(constant_id = SPEC_HAS_SHEEN) const uint kHasSheen = 1u;
layout(constant_id = SPEC_HAS_IRIDESCENCE) const uint kHasIridescence = 1u;
layout(constant_id = SPEC_HAS_ANISOTROPY) const uint kHasAnisotropy = 1u;
layout(constant_id = SPEC_HAS_DISPERSION) const uint kHasDispersion = 1u;
layout(constant_id = SPEC_HAS_DELTA) const uint kHasDelta = 1u;
layout(constant_id = SPEC_SAMPLER) const uint kSampler = 0u;
layout(constant_id = SPEC_SAMPLER_LOG2_SPP) const uint kSamplerLog2Spp = 0u;
layout(constant_id = SPEC_SAMPLER_DIGITS) const uint kSamplerDigits = 0u;
layout(constant_id = SPEC_SAMPLE_REPLICATES) const uint kSampleReplicates = 2u;
layout(constant_id = SPEC_DEEP_WALKS) const uint kDeepWalks = 1u;
layout(constant_id = SPEC_REGISTER_STACK) const uint kRegisterStackEntries = 12u;
layout(constant_id = SPEC_PIXEL_FILTER) const uint kPixelFilterSampling = 0u;

layout(push_constant, std430) uniform Push { PushConstants pc; };

// Read-only scene data lives in storage texel buffers, read with imageLoad: on lavapipe that is an inline
// vector gather, while a texelFetch is an out-of-line sampler call (every live register spilled around it; the
// walk was 10-15% slower with it) and an SSBO load is a loop over the lanes (docs/architecture.md, "What lavapipe does with these kernels",
// docs/journal/performance.md).
layout(binding = BINDING_TRIANGLES, TEXEL_FORMAT_TRIANGLES) uniform readonly imageBuffer triangles;
layout(binding = BINDING_TRIANGLE_INFO, TEXEL_FORMAT_TRIANGLE_INFO) uniform readonly uimageBuffer triangleInfo;
layout(binding = BINDING_BVH_NODES, TEXEL_FORMAT_BVH_NODES) uniform readonly uimageBuffer bvhNodes;
layout(binding = BINDING_LIGHTS, TEXEL_FORMAT_LIGHTS) uniform readonly uimageBuffer lights;
layout(binding = BINDING_TEXTURES, TEXEL_FORMAT_TEXTURES) uniform readonly uimageBuffer textureInfos;
layout(binding = BINDING_TRIANGLE_ATTRIBUTES, TEXEL_FORMAT_TRIANGLE_ATTRIBUTES) uniform readonly uimageBuffer triangleAttributes;
layout(binding = BINDING_LAYER_ALBEDO, TEXEL_FORMAT_LAYER_ALBEDO) uniform readonly uimageBuffer layerAlbedoTable;
layout(binding = BINDING_MATERIALS, TEXEL_FORMAT_MATERIALS) uniform readonly uimageBuffer materialTexels;
layout(binding = BINDING_PATHS, std430) buffer Paths { PathState paths[]; };  // the radiance atomics
// The path state, hits, ray queues and shadow rays are written through their storage buffers and read through
// texel views of the same memory: on lavapipe a texel load is a gather where a storage-buffer load loops over
// the lanes, and a texel store loops once per channel where a storage-buffer store loops once.
layout(binding = BINDING_PATH_TEXELS, TEXEL_FORMAT_PATH_TEXELS) uniform readonly uimageBuffer pathTexels;
layout(binding = BINDING_HIT_TEXELS, TEXEL_FORMAT_HIT_TEXELS) uniform readonly uimageBuffer hitTexels;
layout(binding = BINDING_QUEUE_TEXELS, TEXEL_FORMAT_QUEUE_TEXELS) uniform readonly uimageBuffer queueTexels;
layout(binding = BINDING_SHADOW_TEXELS, TEXEL_FORMAT_SHADOW_TEXELS) uniform readonly uimageBuffer shadowTexels;
layout(binding = BINDING_RAY_QUEUES, std430) buffer RayQueues { uint rayQueues[]; };
// The same memory as 64-bit pairs, for stores: llvmpipe stores a vector one lane at a time, each component
// behind its own bounds check, so 16 bytes stored as two 64-bit components cost a third less than as four
// 32-bit ones (docs/journal/performance.md).
layout(binding = BINDING_PATHS, std430) buffer PathPairs { u64vec2 pathPairs[]; };
layout(binding = BINDING_HITS, std430) buffer HitPairs { u64vec2 hitPairs[]; };
layout(binding = BINDING_SHADOW_QUEUE, std430) buffer ShadowPairs { u64vec2 shadowPairs[]; };
layout(binding = BINDING_FILM, std430) buffer FilmPairs { u64vec2 filmPairs[]; };
u64vec2 wordPairs(uvec4 v) { return u64vec2(packUint2x32(v.xy), packUint2x32(v.zw)); }
u64vec2 wordPairs(vec4 v) { return wordPairs(floatBitsToUint(v)); }
layout(binding = BINDING_CONTROL, std430) buffer ControlBuffer { Control control; };
// The same block as words, for the rare counters' one site (layout.h kControlWord*).
layout(binding = BINDING_CONTROL, std430) buffer ControlWords { uint controlWords[]; };

// Rare events counted per invocation (x: non-finite emission, y: light samples, z: throughput; w: refused splits)
// and added once at the kernel's end by flushRareCounts, which every kernel that counts calls from main's top
// level, where all of its subgroup's lanes are active (lane k adds counter k: layout.h kRareCounters).
uvec4 rareCounts = uvec4(0u);
void flushRareCounts() {
  const uvec4 words = uvec4(kControlWordNonfiniteEmission, kControlWordNonfiniteLightSamples,
                            kControlWordNonfiniteThroughput, kControlWordSplitsRefused);
  uvec4 total = subgroupAdd(rareCounts);
  uint lane = gl_SubgroupInvocationID;
  if (lane < kRareCounters && total[lane] > 0u) atomicAdd(controlWords[words[lane]], total[lane]);
}
layout(binding = BINDING_FILM, std430) buffer Film { FilmPixel film[]; };
layout(binding = BINDING_SAMPLE_RUNS, std430) readonly buffer SampleRuns { uint sampleRunWords[]; };
SampleRun loadSampleRun(uint run) {
  uint w = run * kSampleRunWords;
  return SampleRun(sampleRunWords[w], sampleRunWords[w + 1u], sampleRunWords[w + 2u], sampleRunWords[w + 3u]);
}
// The pixel (x) and sample number (y) of camera path `id`: a pixel range's (path id = sample * pixelCount + pixel
// offset), or its sample run's (adaptive sampling).
uvec2 cameraPathSample(uint id) {
  if (pc.sampleRuns == 0u) return uvec2(pc.firstPixel + id % pc.pixelCount, pc.sampleIndex + id / pc.pixelCount);
  SampleRun run = loadSampleRun(sampleRunWords[pc.pixelCount * kSampleRunWords + id]);
  return uvec2(run.pixel, run.firstSample + (id - run.firstPath));
}
// Read per vertex (EARS) or per light sample (shadow roulette): a texel load, not a storage-buffer lane loop.
layout(binding = BINDING_PIXEL_ESTIMATE, TEXEL_FORMAT_PIXEL_ESTIMATE) uniform readonly imageBuffer pixelEstimates;
vec4 loadPixelEstimate(uint pixel) { return imageLoad(pixelEstimates, int(pixel)); }
layout(binding = BINDING_ROULETTE_TABLE, std430) readonly buffer RouletteTable { float rouletteScale[]; };
layout(binding = BINDING_DEPTH_STATS, std430) buffer DepthStats { vec2 depthStats[]; };
layout(binding = BINDING_QUEUE_STATS, std430) buffer QueueStats { uvec2 queueStats[]; };
layout(binding = BINDING_EARS_HEADER, std430) buffer EarsHeaderBuffer { EarsHeader earsHeader; };
layout(binding = BINDING_EARS_CELLS, std430) buffer EarsCells { EarsCell earsCells[]; };
// The same buffer as words: the finest cells' keys after the table's cells (ears.h earsKeyWord).
layout(binding = BINDING_EARS_CELLS, std430) buffer EarsCellWords { uint earsCellWords[]; };
uint earsTableCells() { return (kEarsLightMax > 0.0 ? 2u : 1u) * (earsHeader.cellMask + 1u); }
layout(binding = BINDING_EARS_RECORDS, std430) buffer EarsRecords { EarsRecord earsRecords[]; };
// The same buffer as vec4s: the light records after the pool's records (ears.h, ears_light_max > 0).
layout(binding = BINDING_EARS_RECORDS, std430) buffer EarsRecordTexels { vec4 earsRecordVec4s[]; };
uint earsLightRecord(uint record) { return 2u * kEarsDepths * pc.queueCapacity + record; }
// The pass's training lists: record indices from 0, the slots split off by training paths from earsChildList().
layout(binding = BINDING_EARS_TRAINING, std430) buffer EarsTraining { uint earsTrainingList[]; };
uint earsChildList() { return kEarsDepths * pc.queueCapacity; }
// Slot i of the pass's training slots: its first `cameras` camera paths (slot = sample), then the listed children.
uint earsTrainingSlot(uint i, uint cameras) { return i < cameras ? i : earsTrainingList[earsChildList() + i - cameras]; }
layout(binding = BINDING_EARS_SLOTS, std430) buffer EarsSlots { EarsSlot earsSlots[]; };
layout(binding = BINDING_PUNCTUAL_LIGHTS, std430) readonly buffer PunctualLights { PunctualLight punctualLights[]; };
layout(binding = BINDING_ENVIRONMENT, std430) readonly buffer Environment {
  EnvironmentHeader envHeader;
  vec4 envRadiance[];  // rgb radiance per pixel, row-major from the top row (environment_map.h)
};
layout(binding = BINDING_ENVIRONMENT_DISTRIBUTION, std430) readonly buffer EnvironmentDistribution { float envDistribution[]; };

// Indirect dispatches may round up, and big ones use a 2D grid.
uint invocationIndex() {
  return gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x;
}

// EARS: whether this wavefront's paths train the cache. A pass's first samples (ears.h earsTrainingSamples) run
// as a wavefront of their own (pc.earsTrains); the rest run on shade and copy kernels built without the training
// code (kEarsTrains = 0), since llvmpipe runs every line of a kernel for every lane, needed or not. The shadow
// stage's few training lines stay, decided at run time (one kernel fewer to compile).
bool earsTrains() { return kEarsTrains != 0u && pc.earsTrains != 0u; }

uint inQueueBase() { return (pc.bounce & 1u) * pc.queueCapacity; }
uint outQueueBase() { return ((pc.bounce + 1u) & 1u) * pc.queueCapacity; }
uint inQueueCount() { return (pc.bounce & 1u) == 0u ? control.rayQueueCount[0] : control.rayQueueCount[1]; }

void triangleVertices(uint tri, out vec3 v0, out vec3 v1, out vec3 v2) {
  v0 = imageLoad(triangles, int(kTriangleTexels * tri)).xyz;
  v1 = imageLoad(triangles, int(kTriangleTexels * tri + 1u)).xyz;
  v2 = imageLoad(triangles, int(kTriangleTexels * tri + 2u)).xyz;
}
// The vertices and, riding in the third vertex's texel, an emitter quad's partner code (scene_layout.h).
void triangleVertices(uint tri, out vec3 v0, out vec3 v1, out vec3 v2, out float partnerCode) {
  v0 = imageLoad(triangles, int(kTriangleTexels * tri)).xyz;
  v1 = imageLoad(triangles, int(kTriangleTexels * tri + 1u)).xyz;
  vec4 t2 = imageLoad(triangles, int(kTriangleTexels * tri + kTrianglePartnerTexel));
  v2 = t2.xyz;
  partnerCode = t2.w;
}
// The vertices for a walk's test, and whether a ray meeting the triangle's back must pass it (SPEC_CULLS_BACK_FACES
// and a single-sided triangle): the flag rides in a texel the walk loads anyway.
void triangleVertices(uint tri, out vec3 v0, out vec3 v1, out vec3 v2, out bool cullBack) {
  vec4 t0 = imageLoad(triangles, int(kTriangleTexels * tri));
  v0 = t0.xyz;
  v1 = imageLoad(triangles, int(kTriangleTexels * tri + 1u)).xyz;
  v2 = imageLoad(triangles, int(kTriangleTexels * tri + 2u)).xyz;
  cullBack = kCullsBackFaces != 0u && triangleSingleSided(t0);  // t0: texel kTriangleSidesTexel
}

// A path's state read through its texel view: five gathers where the storage buffer's load is eight lane loops.
PathState loadPath(uint id) {
  int t = int(id * kPathTexels);
  uvec4 info = imageLoad(pathTexels, t + 4);
  return PathState(uintBitsToFloat(imageLoad(pathTexels, t)), uintBitsToFloat(imageLoad(pathTexels, t + 1)),
                   uintBitsToFloat(imageLoad(pathTexels, t + 2)), uintBitsToFloat(imageLoad(pathTexels, t + 3)), info.x,
                   info.y, info.z, info.w);
}

// A material from its texels (layout.h asserts the offsets): the loads of fields a kernel never reads are dropped.
vec4 materialTexel(int t) { return uintBitsToFloat(imageLoad(materialTexels, t)); }
TextureSlot materialSlot(int t) {
  uvec4 w = imageLoad(materialTexels, t + 2);
  return TextureSlot(materialTexel(t), materialTexel(t + 1), w.x, w.y, w.z, w.w);
}
Material loadMaterial(uint index) {
  int t = int(index * kMaterialTexels);
  Material m;
  m.baseColor = materialTexel(t);
  vec4 e = materialTexel(t + 1);
  m.emission = e.xyz;
  m.flags = floatBitsToUint(e.w);
  vec4 f = materialTexel(t + 2);
  m.metallic = f.x;
  m.roughness = f.y;
  m.specular = f.z;
  m.alphaCutoff = f.w;
  m.baseColorTexture = materialSlot(t + 3);
  m.metallicRoughnessTexture = materialSlot(t + 6);
  m.normalTexture = materialSlot(t + 9);
  m.emissiveTexture = materialSlot(t + 12);
  m.specularColor = materialTexel(t + 15);
  m.attenuation = materialTexel(t + 16);
  m.sheen = materialTexel(t + 17);
  uvec4 c = imageLoad(materialTexels, t + 18);
  m.clearcoat = uintBitsToFloat(c.x);
  m.clearcoatRoughness = uintBitsToFloat(c.y);
  m.volumetric = c.z;
  m.unusedMaterial0 = c.w;
  m.transmissionTexture = materialSlot(t + 19);
  m.clearcoatTexture = materialSlot(t + 22);
  m.clearcoatRoughnessTexture = materialSlot(t + 25);
  m.clearcoatNormalTexture = materialSlot(t + 28);
  m.sheenColorTexture = materialSlot(t + 31);
  m.sheenRoughnessTexture = materialSlot(t + 34);
  m.specularTexture = materialSlot(t + 37);
  m.specularColorTexture = materialSlot(t + 40);
  // The newer extensions' texels only where the scene has them: a scene without them reads 12 texels less a vertex.
  TextureSlot none = TextureSlot(vec4(0.0), vec4(0.0), kNoTexture, 0u, 0u, 0u);
  m.iridescence = kHasIridescence != 0u ? materialTexel(t + 43) : vec4(0.0);
  m.iridescenceTexture = kHasIridescence != 0u ? materialSlot(t + 44) : none;
  m.iridescenceThicknessTexture = kHasIridescence != 0u ? materialSlot(t + 47) : none;
  m.anisotropy = kHasAnisotropy != 0u ? materialTexel(t + 50) : vec4(0.0, 1.0, 0.0, 0.0);
  m.anisotropyTexture = kHasAnisotropy != 0u ? materialSlot(t + 51) : none;
  m.dispersion = kHasDispersion != 0u ? materialTexel(t + 54) : vec4(0.0);
  return m;
}

void storeRadiance(uint id, vec4 radiance) { pathPairs[id * kPathTexels + 3u] = wordPairs(radiance); }
void storeHit(uint id, vec4 hit) { hitPairs[id] = wordPairs(hit); }
void storeFilmPixel(uint pixel, FilmPixel f) {
  uint t = pixel * kFilmPixelWords;
  filmPairs[t] = wordPairs(f.sum);
  filmPairs[t + 1u] = wordPairs(f.sumSq);
  filmPairs[t + 2u] = wordPairs(f.sumHigh);
  filmPairs[t + 3u] = wordPairs(f.sumSqHigh);
  for (uint r = 0u; r + 1u < kMaxSampleReplicates; ++r) filmPairs[t + 4u + r] = wordPairs(f.replicate[r]);
}
void storeShadowRay(uint slot, ShadowRay r) {
  uint t = slot * kShadowRayTexels;
  shadowPairs[t] = wordPairs(r.origin);
  shadowPairs[t + 1u] = wordPairs(r.direction);
  shadowPairs[t + 2u] = wordPairs(r.contribution);
}
// A path's ray, throughput and bookkeeping (the whole state but its radiance) in four stores.
void storePathRay(uint id, PathState p) {
  uint t = id * kPathTexels;
  pathPairs[t] = wordPairs(p.origin);
  pathPairs[t + 1u] = wordPairs(p.direction);
  pathPairs[t + 2u] = wordPairs(p.throughput);
  pathPairs[t + 4u] = wordPairs(uvec4(p.pixel, p.rngKey, p.depth, p.rootPath));
}
// The bookkeeping texel alone: where the megakernel leaves a finished path's depth for accumulate (its cost).
void storePathBookkeeping(uint id, PathState p) { pathPairs[id * kPathTexels + 4u] = wordPairs(uvec4(p.pixel, p.rngKey, p.depth, p.rootPath)); }
void storePath(uint id, PathState p) {
  storePathRay(id, p);
  storeRadiance(id, p.radiance);
}
// The radiance a path has gathered so far, read through the texel view (shadow rays add to it).
vec4 loadRadiance(uint id) { return uintBitsToFloat(imageLoad(pathTexels, int(id * kPathTexels + 3u))); }
// A finished path's scattering events: its camera path's vertices are depth + 1, the sample's cost in the film.
uint loadPathDepth(uint id) { return imageLoad(pathTexels, int(id * kPathTexels + 4u)).z; }

vec4 loadHit(uint id) { return uintBitsToFloat(imageLoad(hitTexels, int(id))); }
uint loadQueued(uint index) { return imageLoad(queueTexels, int(index)).x; }
ShadowRay loadShadowRay(uint slot) {
  int t = int(slot * kShadowRayTexels);
  return ShadowRay(uintBitsToFloat(imageLoad(shadowTexels, t)), uintBitsToFloat(imageLoad(shadowTexels, t + 1)),
                   uintBitsToFloat(imageLoad(shadowTexels, t + 2)));
}

bool allFinite(vec3 v) { return !any(isnan(v)) && !any(isinf(v)); }

// A path's sample stream (sampler.h): its key, its pixel's sample number (the pass's first plus the root
// path's sample slot), its pixel; and dimension `dim` of it from the sampler the kernels are specialized for.
SampleStream pathStream(PathState p) { return SampleStream(p.rngKey, cameraPathSample(p.rootPath).y, pathPixelOf(p.pixel)); }
SamplerShape samplerShape() { return SamplerShape(kSampleReplicates, pc.width, kSamplerLog2Spp, kSamplerDigits); }
float sampleU(SampleStream s, uint dim) { return sampleDimension(kSampler, s, dim, samplerShape()); }
vec2 sampleU2(SampleStream s, uint dim) { return samplePair(kSampler, s, dim, samplerShape()); }  // dim even
