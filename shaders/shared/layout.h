// Every struct that crosses host <-> GPU, defined once (std430), with layout checks and binding numbers.
#ifndef VKMC_LAYOUT_H
#define VKMC_LAYOUT_H
#include "glsl_cpp.h"
#include "ears.h"
#include "roulette.h"  // the roulette modes

// Descriptor bindings of the single set used by every kernel.
#define BINDING_TRIANGLES 0      // imageBuffer: triangle vertices and light pmfs (scene_layout.h)
#define BINDING_TRIANGLE_INFO 1  // uimageBuffer: per-triangle normals and material (scene_layout.h)
#define BINDING_BVH_NODES 2      // uimageBuffer: BVH nodes (bvh_layout.h)
#define BINDING_LIGHTS 3         // uimageBuffer: light alias table (scene_layout.h)
#define BINDING_MATERIALS 4      // uimageBuffer: Material[] as texels (kMaterialTexels each)
#define BINDING_PATHS 5          // PathState[]
#define BINDING_HITS 6           // vec4[] (t, b1, b2, triangle bits)
#define BINDING_RAY_QUEUES \
  7                             // uint[2 * capacity]: path ids, ping-pong by bounce parity (EARS:
                                // 3 * capacity, the third EARS's copy queue)
#define BINDING_SHADOW_QUEUE 8  // ShadowRay[]
#define BINDING_CONTROL 9       // Control
#define BINDING_FILM 10         // FilmPixel[]
#define BINDING_TEST_RAYS 11    // TestRay[] (texture probes; trace_rays reads its rays at BINDING_PATH_TEXELS)
#define BINDING_TEST_HITS 12    // vec4[] (trace_rays kernel only)
#define BINDING_PIXEL_ESTIMATE \
  13                               // imageBuffer: running estimate per pixel, rgb and w its luminance
                                   // (shadow roulette, EARS)
#define BINDING_ROULETTE_TABLE 14  // float[kRouletteTableDepths]: efficiency roulette scale per depth
#define BINDING_DEPTH_STATS 15     // vec2[pool * kRouletteTableDepths]: pilot (beta, gathered) per path and depth
#define BINDING_QUEUE_STATS 16     // uvec2[kQueueStatsBounces]: per bounce, paths queued (x) and shadow rays (y)
#define BINDING_DEEP_WALKS 17      // uint[]: items whose walk outgrew the register stack (deferred_walk.glsl)
#define BINDING_TEXTURE_TEXELS \
  18                                         // uimageBuffer: the texture pages' RGBA8 texels, one r32ui each: only
                                             // `vkmc bench-textures` reads textures this way (texture_layout.h)
#define BINDING_TEXTURES 19                  // uimageBuffer: one TextureInfo texel per texture (texture_layout.h)
#define BINDING_TRIANGLE_ATTRIBUTES 20       // uimageBuffer: per-triangle uvs, tangents, colours (texture_layout.h)
#define BINDING_PUNCTUAL_LIGHTS 21           // PunctualLight[] (punctual_light.h)
#define BINDING_ENVIRONMENT 22               // vec4[]: environment radiance, row-major, + header (environment_map.h)
#define BINDING_ENVIRONMENT_DISTRIBUTION 23  // float[]: its sampling distribution (environment_map.h)
#define BINDING_PIXEL_FILTER 24              // PixelFilterHeader + float[]: the pixel filter's table (pixel_filter.h)
#define BINDING_LAYER_ALBEDO 25              // uimageBuffer: the clearcoat and sheen albedo table as float bits (layer_albedo.h)
#define BINDING_TEXTURE_PAGES 26  // sampler2DArray[kTexturePageViews]: every texture in one array image (texture_layout.h)
#define BINDING_EARS_HEADER 27    // EarsHeader (ears.h): the cache's parameters and the factor histogram
#define BINDING_EARS_CELLS 28     // EarsCell[]: the learned cache
#define BINDING_EARS_RECORDS 29   // EarsRecord[pool * kEarsDepths]: each slot's training vertices
#define BINDING_EARS_SLOTS 30     // EarsSlot[pool]
#define BINDING_EARS_SAMPLING 31  // imageBuffer: per cell, what the factors read (ears.h kEarsSamplingTexels)
#define BINDING_PATH_TEXELS \
  32                              // uimageBuffer: BINDING_PATHS's PathState[] as texels (kPathTexels a path),
                                  // read with imageLoad: on lavapipe a gather, not a loop over the lanes
#define BINDING_HIT_TEXELS 33     // imageBuffer: BINDING_HITS as texels, for reading
#define BINDING_QUEUE_TEXELS 34   // uimageBuffer: BINDING_RAY_QUEUES as texels, for reading
#define BINDING_SHADOW_TEXELS 35  // uimageBuffer: BINDING_SHADOW_QUEUE's ShadowRay[] as texels (3 a ray)
#define BINDING_EARS_TRAINING \
  36  // uint[pool * (kEarsDepths + 1)]: the records written and the slots split off
      // by training paths this pass (ears.h EarsHeader training*)
#define BINDING_SAMPLE_RUNS \
  37  // uint[]: a pass of sample runs (pc.sampleRuns: adaptive sampling): pc.pixelCount SampleRuns of 4 words,
      // then one word a camera path, its run
#define BINDING_COUNT 38

// Texel formats of the scene bindings as GLSL image-format qualifiers (common.glsl declares the bindings with
// them); the host derives each VkFormat from the same token (sceneTexelFormat in host/render/gpu_scene.cpp).
#define TEXEL_FORMAT_TRIANGLES rgba32f
#define TEXEL_FORMAT_TRIANGLE_INFO rgba32ui
#define TEXEL_FORMAT_BVH_NODES rgba32ui
#define TEXEL_FORMAT_LIGHTS rgba32ui
#define TEXEL_FORMAT_TEXTURE_TEXELS r32ui
#define TEXEL_FORMAT_TEXTURES rgba32ui
#define TEXEL_FORMAT_TRIANGLE_ATTRIBUTES rgba32ui
#define TEXEL_FORMAT_LAYER_ALBEDO r32ui
#define TEXEL_FORMAT_EARS_SAMPLING rgba32f
#define TEXEL_FORMAT_MATERIALS rgba32ui
#define TEXEL_FORMAT_PATH_TEXELS rgba32ui
#define TEXEL_FORMAT_HIT_TEXELS rgba32ui  // w carries the triangle index as float bits: a typed float load could flush them
#define TEXEL_FORMAT_QUEUE_TEXELS r32ui
#define TEXEL_FORMAT_SHADOW_TEXELS rgba32ui
#define TEXEL_FORMAT_PIXEL_ESTIMATE rgba32f

// Specialization constant ids.
#define SPEC_WORKGROUP_SIZE 0
#define SPEC_MAX_DEPTH 1   // scattering events; 0 = no cap (Russian roulette only)
#define SPEC_RR_DEPTH 2    // first depth at which roulette applies
#define SPEC_HAS_LIGHTS 3  // 0: nothing to sample (no emissive triangles, punctual lights, environment): NEE removed
#define SPEC_ANY_HIT 4     // trace_rays: 1 = any-hit query
// Estimator settings (see host/estimators/estimator_config.h, the one place that sets them).
#define SPEC_NEE 5             // 0/1: next-event estimation
#define SPEC_MIS 6             // kMis*
#define SPEC_BSDF_SAMPLING 7   // kBsdfSampling*
#define SPEC_LIGHT_SAMPLING 8  // kLightSampling*
#define SPEC_RR_MODE 9         // kRoulette*
#define SPEC_RR_Q 10           // float: fixed termination probability q
#define SPEC_RR_C 11           // float: fixed-mode constant c returned on termination
#define SPEC_LIGHT_SAMPLES 12  // M light samples per hit at depths below SPEC_SPLIT_DEPTH
#define SPEC_SPLIT_DEPTH 13
#define SPEC_SHADOW_RR_THRESHOLD 14  // float: 0 = off
#define SPEC_SHADOW_RR_Q 15          // float: termination probability of a tiny shadow ray
#define SPEC_CAMERA_RR_Q 16          // float: 0 = off
#define SPEC_HAS_GLOSSY 19           // 0: every material is Lambertian; GGX code compiled out
#define SPEC_RECORD_DEPTH_STATS 18   // 1: the efficiency-roulette pilot records per-depth statistics
#define SPEC_BSDF_SAMPLES 17         // float: continuations per hit below SPEC_SPLIT_DEPTH (1 = no splitting)
#define SPEC_HAS_TEXTURES 21         // 0: no material samples a texture or vertex colour; texture code compiled out
#define SPEC_HAS_NORMAL_MAPS 22      // 0: no normal textures
#define SPEC_HAS_ALPHA 23            // 0: every material opaque; the walks' alpha tests compiled out
#define SPEC_WALK_STATS 20           // trace_rays: 1 = count the register-stack walk's steps into Control.walkStats
// 21-23: the textures' spec constants.
#define SPEC_HAS_PUNCTUAL 24       // 0: no punctual lights, their sampling code removed
#define SPEC_HAS_ENVIRONMENT 25    // 0: no environment light (escaped rays see pc.background alone)
#define SPEC_PIXEL_FILTER 26       // kPixelFilterSampling*: the pixel's box (u as is) or a filter from BINDING_PIXEL_FILTER
#define SPEC_SAMPLER 27            // kSampler* (sampler.h)
#define SPEC_SAMPLER_LOG2_SPP 28   // zsobol: log2 of a replicate's sample count, rounded up
#define SPEC_SAMPLER_DIGITS 29     // zsobol: base-4 digits of the Morton index (pixel bits + log2 spp)
#define SPEC_CULLS_BACK_FACES 30   // 0: every material double-sided; the walks' back-face test compiled out
#define SPEC_HAS_TRANSMISSION 31   // 0: no KHR_materials_transmission (nor volume): the btdf and attenuation compiled out
#define SPEC_HAS_CLEARCOAT 32      // 0: no KHR_materials_clearcoat
#define SPEC_HAS_SHEEN 33          // 0: no KHR_materials_sheen
#define SPEC_HAS_DELTA 34          // 0: no lobe can be smooth (delta): every BSDF sample is MIS-weighted
#define SPEC_EARS_MAX 35           // float: rr ears's largest factor q, at most kEarsFactorMax (1: learned roulette alone)
#define SPEC_EARS_LIGHT_MAX 36     // float: rr ears's largest light factor qL; 0: light samples not learned (ears.h)
#define SPEC_EARS_TRAINS 37        // 0/1: rr ears: this kernel's paths train the cache (common.glsl earsTrains)
#define SPEC_SAMPLE_REPLICATES 38  // replicates a pixel's samples are split into, 1..kMaxSampleReplicates (sampler.h)
#define SPEC_DEEP_WALKS 39         // 0: the BVH is too shallow for any walk to outgrow the register stack: no deep pass
#define SPEC_REGISTER_STACK \
  40  // the walk's register stack entries: 4, 8 or kBvhRegisterStackEntries (bvh.h registerStackEntries)
#define SPEC_HAS_IRIDESCENCE 41  // 0: no KHR_materials_iridescence
#define SPEC_HAS_ANISOTROPY 42   // 0: no KHR_materials_anisotropy
#define SPEC_HAS_DISPERSION 43   // 0: no KHR_materials_dispersion

VKMC_BEGIN_NAMESPACE

VKMC_CONST uint kMissPrimitive = 0xffffffffu;
VKMC_CONST float kShadowRayTMax = 1.0f - 1e-4f;  // a shadow ray's end, in units of its direction (short of the light)
VKMC_CONST uint kWorkgroupSize = 64u;
VKMC_CONST uint kMaterialDoubleSided = 1u;  // Material.flags bits
VKMC_CONST uint kMaterialAlphaMask = 2u;    // alpha below alphaCutoff: the surface is not there
VKMC_CONST uint kMaterialAlphaBlend = 4u;   // stochastic transparency: a ray passes with probability 1 - alpha
VKMC_CONST uint kNoTexture = 0xffffffffu;
VKMC_CONST uint kCameraPerspective = 0u;
VKMC_CONST uint kCameraOrthographic = 1u;
VKMC_CONST uint kRouletteTableDepths = 16u;  // depths with their own efficiency-roulette scale
VKMC_CONST uint kQueueStatsBounces = 64u;    // queue occupancy is recorded per bounce up to here (the last sums the rest)
VKMC_CONST uint kMisNone = 0u, kMisBalance = 1u, kMisPower = 2u;
VKMC_CONST uint kBsdfSamplingUniform = 0u, kBsdfSamplingCosine = 1u, kBsdfSamplingFull = 2u;
VKMC_CONST uint kLightSamplingArea = 0u, kLightSamplingSolidAngle = 1u;
VKMC_CONST uint kPunctualPoint = 0u, kPunctualSpot = 1u, kPunctualDirectional = 2u;
VKMC_CONST uint kPixelFilterBox = 0u, kPixelFilterGaussian = 1u, kPixelFilterMitchell = 2u, kPixelFilterBlackmanHarris = 3u;
// SPEC_PIXEL_FILTER: the box of radius 1/2 places a sample at u in its pixel, weight 1, and reads nothing (the
// default: no filter code in the kernels); every other filter is sampled from BINDING_PIXEL_FILTER's table.
VKMC_CONST uint kPixelFilterSamplingUniform = 0u, kPixelFilterSamplingTable = 1u;

// A path between stages. direction.w is the solid-angle pdf of the sampling that produced the ray
// (0 for camera rays: their emission hits are never MIS-weighted).
struct PathState {
  vec4 origin;      // xyz: ray origin, w: etaScale, the eta^2 factors its radiance scaling divided out (roulette)
  vec4 direction;   // xyz: unit direction, w: pdf of the direction
  vec4 throughput;  // rgb: path throughput, w: product of the split factors that divided it (roulette undoes none)
  vec4 radiance;    // rgb: radiance gathered so far, w: the sample's pixel-filter weight (accumulate applies it)
  uint pixel;       // the pixel (low kPathPixelBits), then its spectral channel (pathChannelOf) and whether it is taken
  uint rngKey;      // random-number key (a split child gets its own)
  uint depth;       // scattering events so far
  uint rootPath;    // the slot of the path's sample, where its radiance accumulates
};

// KHR_materials_dispersion: a path's colour channel (0-2, chosen at the camera) above its pixel's bits, and the bit
// that says its throughput has been masked to that channel (shading.glsl takeSpectralChannel).
VKMC_CONST uint kPathPixelBits = 29u;
VKMC_CONST uint kPathChannelTaken = 0x80000000u;
VKMC_FN uint pathPixelOf(uint packed) { return packed & ((1u << kPathPixelBits) - 1u); }
VKMC_FN uint pathChannelOf(uint packed) { return (packed >> kPathPixelBits) & 3u; }

VKMC_CONST uint kPathTexels = 5u;       // 16-byte texels of a PathState (BINDING_PATH_TEXELS)
VKMC_CONST uint kShadowRayTexels = 3u;  // and of a ShadowRay (BINDING_SHADOW_TEXELS)

struct ShadowRay {
  vec4 origin;        // xyz, w: the slot of the path copy that sampled it, as float bits (EARS training)
  vec4 direction;     // xyz: unnormalized (to the light point, tmax kShadowRayTMax), w: root path id as float bits
  vec4 contribution;  // rgb added to the path if unoccluded, w: its stochastic-alpha key (rng.h alphaKey) as float bits
};

// A material's texture: uv' = (dot(uvRow0.xyz, (u, v, 1)), dot(uvRow1.xyz, (u, v, 1))) (KHR_texture_transform).
struct TextureSlot {
  vec4 uvRow0;    // xyz: first row of the uv transform, w: normal-map scale (normalTexture.scale)
  vec4 uvRow1;    // xyz: second row, w: unused
  uint texture;   // index of its TextureInfo texel, or kNoTexture
  uint texCoord;  // 0: TEXCOORD_0, 1: TEXCOORD_1
  uint unusedSlot0, unusedSlot1;
};

struct Material {
  vec4 baseColor;  // rgb, a: alpha factor
  vec3 emission;   // emitted radiance (factor x strength)
  uint flags;      // kMaterial* bits
  float metallic;
  float roughness;
  float specular;     // KHR_materials_specular's specularFactor
  float alphaCutoff;  // kMaterialAlphaMask
  TextureSlot baseColorTexture, metallicRoughnessTexture, normalTexture, emissiveTexture;
  // The material extensions (bsdf_gltf.h)
  vec4 specularColor;  // rgb: KHR_materials_specular specularColorFactor, w: KHR_materials_ior ior
  vec4 attenuation;    // rgb: KHR_materials_volume's coefficient -ln(attenuationColor) / attenuationDistance, w: transmission
  vec4 sheen;          // rgb: sheenColorFactor, w: sheenRoughnessFactor
  float clearcoat, clearcoatRoughness;
  uint volumetric;  // 1: transmission refracts into a closed mesh (KHR_materials_volume thicknessFactor > 0)
  uint unusedMaterial0;
  TextureSlot transmissionTexture, clearcoatTexture, clearcoatRoughnessTexture, clearcoatNormalTexture, sheenColorTexture,
      sheenRoughnessTexture, specularTexture, specularColorTexture;
  vec4 iridescence;  // KHR_materials_iridescence: x factor, y the film's ior, z and w its thickness range (nm)
  TextureSlot iridescenceTexture, iridescenceThicknessTexture;
  vec4 anisotropy;  // KHR_materials_anisotropy: x strength, y and z cos and sin of its rotation, w unused
  TextureSlot anisotropyTexture;
  // KHR_materials_dispersion: rgb the volume's ior at the red, green and blue channels' wavelengths; w 1 where it
  // disperses (a volume that transmits), else 0.
  vec4 dispersion;
};

VKMC_CONST uint kMaterialTexels = 55u;  // 16-byte texels of a Material (BINDING_MATERIALS)

// A KHR_lights_punctual light instance in world space (punctual_light.h samples it).
struct PunctualLight {
  vec4 position;   // xyz: position (point, spot); directional: the scene's bounding-sphere centre, w its radius
  vec4 direction;  // xyz: unit direction the light shines along (spot, directional), w: unused
  vec4 intensity;  // rgb: radiant intensity I (W/sr; point, spot) or irradiance E (W/m^2; directional), w: unused
  uint kind;       // kPunctual*
  float cosOuter;  // spot: cos(outerConeAngle)
  float cosInner;  // spot: cos(innerConeAngle)
  float unused;
};

// The head of BINDING_ENVIRONMENT, followed by width x height texels of radiance (rgb, row-major from the top
// row, strength applied); environment_map.h maps directions to them and samples them.
struct EnvironmentHeader {
  uint width, height;              // 0 x 0: no environment light (escaped rays see pc.background alone)
  float cosRotation, sinRotation;  // of the map's rotation about +Y
  vec4 sceneSphere;                // xyz: the scene's bounding-sphere centre, w: radius (shadow rays end past it)
  float selectionPmf;              // the environment's light-selection probability (0: not sampled)
  float unused0, unused1, unused2;
};

// The head of BINDING_PIXEL_FILTER, followed by its sampling table (pixel_filter.h, built by
// host/render/pixel_filter_table.cpp).
struct PixelFilterHeader {
  uint kind;          // kPixelFilter*
  float radius;       // pixels, per axis
  float invIntegral;  // 1 / integral of the 1D filter over [-radius, radius]
  uint unused0;
  vec4 params;  // gaussian: x sigma, y exp(-radius^2 / (2 sigma^2)); mitchell: x B, y C
};

// Film of one batch: float partial sums, folded into double on the host every batch. A channel whose magnitude
// reaches kFilmHighThreshold (2^56) goes to the high sums scaled by kFilmHighScale (2^-96): its square would
// overflow float past ~1.8e19, and every finite value up to FLT_MAX (2^128) must count. The host adds the high
// sums back times 2^96 (squares 2^192) in double.
// Replicates (sampler.h): sample i of a pixel belongs to replicate i % R (R = the `replicates` setting, at most
// kMaxSampleReplicates); their separate sums give the variance of the pixel mean when the samples inside a
// replicate are correlated (QMC). The last replicate's sums are the rest of `sum` (the host subtracts), which
// keeps the film at 112 bytes a pixel (1024x1024 fits lavapipe's 128 MiB storage-buffer limit); slots of
// replicates beyond R stay 0.
VKMC_CONST uint kMaxSampleReplicates = 4u;
VKMC_CONST uint kFilmPixelWords = 3u + kMaxSampleReplicates;  // 16-byte words of a FilmPixel
struct FilmPixel {
  vec4 sum;        // rgb: sum of estimate channels below the threshold, w: finite samples
  vec4 sumSq;      // rgb: sum of their squares, w: non-finite samples (counted, excluded)
  vec4 sumHigh;    // rgb: sum of channels at or above the threshold, times kFilmHighScale; w: samples with one
  vec4 sumSqHigh;  // rgb: sum of the squares of those scaled channels; w: the samples' camera-path vertices (their cost)
  vec4 replicate[kMaxSampleReplicates - 1u];  // rgb: sum of replicate r's finite samples, w: their count
};
VKMC_CONST float kFilmHighThreshold = 72057594037927936.0f;          // 2^56
VKMC_CONST float kFilmHighScale = 1.2621774483536188886587657e-29f;  // 2^-96

// Queue counters and indirect dispatch arguments (x,y,z used; w pads to 16 bytes).
struct Control {
  uint rayQueueCount[2];  // ray queue sizes, ping-pong by bounce parity
  uint shadowQueueCount;
  uint splitChildren;    // path slots handed to split children this pass
  uvec4 rayArgs;         // dispatch of intersect and shade (x, y, z)
  uvec4 shadowArgs;      // dispatch of shadow
  uvec4 accumulateArgs;  // dispatch of accumulate: non-zero only once no path is alive
  uint cameraRays, extensionRays, shadowRays;
  uint copyQueueCount;  // EARS: vertex copies queued for the copy stage this bounce (ears_shade.glsl)
  // Non-finite values by the stage that produced them (the sample is then excluded by accumulate):
  uint nonfiniteEmission;      // emission and other gathered radiance
  uint nonfiniteLightSamples;  // light-sample contributions
  uint nonfiniteThroughput;    // continuation throughput
  uint walksCut;               // BVH walks cut short (llvmpipe's loop limit, a full deep queue)
  uvec4 deepArgs;              // dispatch of the deferred deep walks: x groups, y = z = 1, w: walks deferred
  uint deepWalksDeferred;      // in all (one that finds the deep queue full is cut short: walksCut)
  uint deepWalksTraced;        // by the deep passes (equals deepWalksDeferred once every deep pass has run)
  uint extraShadowRays;        // EARS: shadow-queue slots reserved past light_samples a copy this bounce (ears_shade.glsl)
  uint splitsRefused;          // vertices whose split found the path pool full this pass (kept whole: q = 1, unbiased)
  // SPEC_WALK_STATS, summed over rays: loop iterations, node steps, triangle tests, and the iterations of each
  // subgroup's slowest lane (summed over subgroups, times the subgroup size).
  uint walkIterations, walkNodeSteps, walkTriangleTests, walkSlowestLaneIterations;
  uvec4 copyArgs;  // dispatch of EARS's copy stage
};

// Control's counters of rare events (non-finite values, refused splits), as word indices: a kernel counts them per
// invocation and adds its subgroup's sums in one atomic site at its end, one lane a counter (common.glsl
// flushRareCounts), since llvmpipe runs every atomic site as a loop over its lanes, whether a lane takes it or not.
VKMC_CONST uint kRareCounters = 4u;  // lanes the flush uses: the device's subgroup must have as many
VKMC_CONST uint kControlWordNonfiniteEmission = 20u;
VKMC_CONST uint kControlWordNonfiniteLightSamples = 21u;
VKMC_CONST uint kControlWordNonfiniteThroughput = 22u;
VKMC_CONST uint kControlWordSplitsRefused = 31u;

struct TestRay {
  vec4 origin;     // xyz, w: tmax
  vec4 direction;  // xyz
};

// Push constants shared by every kernel (<= 128 bytes).
struct PushConstants {
  uint pathCount;    // paths in this pass
  uint firstPixel;   // pixel of path 0
  uint sampleIndex;  // sample index of the pass's first sample (rng)
  uint bounce;       // current bounce: selects the ping-pong queue
  uint width;
  uint height;
  uint seed;
  uint queueCapacity;   // path pool size: camera paths plus room for split children
  vec4 cameraOrigin;    // xyz, w: camera kind as float (0 perspective, 1 orthographic)
  vec4 cameraForward;   // xyz unit
  vec4 cameraRight;     // xyz: scaled by tan(xfov/2), or half width for orthographic
  vec4 cameraUp;        // xyz: scaled by tan(yfov/2), or half height
  vec4 background;      // rgb: uniform radiance of escaped rays; w: the backdrop (encodeBackground)
  uint pixelCount;      // pixels in this pass; path id = sample * pixelCount + pixel offset
  uint samplesPerPass;  // samples of each pixel in this pass (pathCount = pixelCount * samplesPerPass)
  uint earsTrains;      // rr ears: 1 where this wavefront's paths train the cache (common.glsl earsTrains)
  uint sampleRuns;      // 1: the pass renders BINDING_SAMPLE_RUNS's runs (pixelCount of them), not a pixel range
};

// PushConstants::background: rgb, the uniform radiance every escaped ray brings (with the environment's); w > 0, a
// grey backdrop that camera rays which escape see instead (the studio's and a white world's: a model viewer's
// neutral backdrop, while the scene stays lit by the environment).
VKMC_FN vec4 encodeBackground(vec3 radiance, float backdropGrey) { return vec4(radiance, backdropGrey); }
VKMC_FN bool hasBackdrop(vec4 background) { return background.w > 0.0f; }

// Consecutive samples of one pixel in a pass of sample runs (adaptive sampling): camera paths firstPath ..
// firstPath + paths - 1 are its samples firstSample ... A pixel has one run in a pass at most (accumulate adds a
// run's samples into its pixel without atomics).
struct SampleRun {
  uint pixel;
  uint firstPath;
  uint paths;
  uint firstSample;
};
VKMC_CONST uint kSampleRunWords = 4u;

// Push constants of the analytic furnace probe (shaders/probes/roulette_furnace.comp).
struct FurnaceProbePush {
  float albedo;        // Lambertian albedo of the surface every ray hits
  float emission;      // its emitted radiance Le: L = Le / (1 - albedo)
  uint rouletteDepth;  // as SPEC_RR_DEPTH (the mode is SPEC_RR_MODE, as in shade)
  uint seed;
  uint verticesPerInvocation;  // a lane starts paths until it has traced this many vertices
  uint invocations;
  uint unused0, unused1;
};

// What one lane of the furnace probe returns.
struct FurnaceProbeLane {
  float sum, sumSq;  // Kahan sums of L and L^2 over its finished paths
  uint vertices;     // vertices traced
  uint paths;        // paths finished; top bit: llvmpipe's loop limiter ended the lane with a path in flight
};

VKMC_END_NAMESPACE

#ifdef __cplusplus
namespace vkmc::gpu {
// The bindings read as storage texel buffers (the others are storage buffers).
inline constexpr uint32_t kTexelBindings[] = {
    BINDING_TRIANGLES,   BINDING_TRIANGLE_INFO,       BINDING_BVH_NODES,    BINDING_LIGHTS,        BINDING_TEXTURE_TEXELS,
    BINDING_TEXTURES,    BINDING_TRIANGLE_ATTRIBUTES, BINDING_LAYER_ALBEDO, BINDING_EARS_SAMPLING, BINDING_MATERIALS,
    BINDING_PATH_TEXELS, BINDING_HIT_TEXELS,          BINDING_QUEUE_TEXELS, BINDING_SHADOW_TEXELS, BINDING_PIXEL_ESTIMATE};
// The texel bindings that hold the renderer's own state (not the scene's): standalone kernels bind placeholders.
inline constexpr uint32_t kRendererTexelBindings[] = {BINDING_PATH_TEXELS, BINDING_HIT_TEXELS, BINDING_QUEUE_TEXELS,
                                                      BINDING_SHADOW_TEXELS, BINDING_PIXEL_ESTIMATE};
static_assert(sizeof(PathState) == 80);
static_assert(offsetof(PathState, pixel) == 64 && offsetof(PathState, rootPath) == 76);
static_assert(sizeof(ShadowRay) == 48);
static_assert(sizeof(TextureSlot) == 48);
static_assert(sizeof(Material) == 880 && offsetof(Material, flags) == 28 && offsetof(Material, metallic) == 32);
static_assert(offsetof(Material, baseColorTexture) == 48 && offsetof(Material, emissiveTexture) == 192);
// loadMaterial (common.glsl) reads these texels.
static_assert(sizeof(Material) == 16 * kMaterialTexels && offsetof(Material, specularColor) == 16 * 15 &&
              offsetof(Material, clearcoat) == 16 * 18 && offsetof(Material, transmissionTexture) == 16 * 19 &&
              offsetof(Material, specularColorTexture) == 16 * 40 && sizeof(TextureSlot) == 16 * 3 &&
              offsetof(Material, iridescence) == 16 * 43 && offsetof(Material, iridescenceTexture) == 16 * 44 &&
              offsetof(Material, iridescenceThicknessTexture) == 16 * 47 && offsetof(Material, anisotropy) == 16 * 50 &&
              offsetof(Material, anisotropyTexture) == 16 * 51 && offsetof(Material, dispersion) == 16 * 54);
static_assert(sizeof(PathState) == 16 * kPathTexels && sizeof(ShadowRay) == 16 * kShadowRayTexels);
static_assert(offsetof(Material, specularColor) == 240 && offsetof(Material, transmissionTexture) == 304);
static_assert(sizeof(PunctualLight) == 64 && offsetof(PunctualLight, kind) == 48 && offsetof(PunctualLight, cosInner) == 56);
static_assert(sizeof(EnvironmentHeader) == 48 && offsetof(EnvironmentHeader, sceneSphere) == 16);
static_assert(offsetof(EnvironmentHeader, selectionPmf) == 32);
static_assert(sizeof(PixelFilterHeader) == 32 && offsetof(PixelFilterHeader, params) == 16);
static_assert(sizeof(FilmPixel) == 112 && offsetof(FilmPixel, replicate) == 64 && sizeof(FilmPixel) == 16 * kFilmPixelWords);
static_assert(sizeof(Control) == 160 && offsetof(Control, copyArgs) == 144);
static_assert(offsetof(Control, deepArgs) == 96);
static_assert(offsetof(Control, rayArgs) == 16 && offsetof(Control, accumulateArgs) == 48);
static_assert(offsetof(Control, cameraRays) == 64 && offsetof(Control, walksCut) == 92);
static_assert(offsetof(Control, nonfiniteEmission) == 4 * kControlWordNonfiniteEmission &&
              offsetof(Control, nonfiniteLightSamples) == 4 * kControlWordNonfiniteLightSamples &&
              offsetof(Control, nonfiniteThroughput) == 4 * kControlWordNonfiniteThroughput &&
              offsetof(Control, splitsRefused) == 4 * kControlWordSplitsRefused);
static_assert(offsetof(Control, deepWalksDeferred) == 112 && offsetof(Control, walkIterations) == 128);
static_assert(sizeof(TestRay) == 32);
static_assert(sizeof(SampleRun) == 4 * kSampleRunWords && offsetof(PushConstants, sampleRuns) == 124);
static_assert(sizeof(PushConstants) == 128);
static_assert(offsetof(PushConstants, cameraOrigin) == 32);
static_assert(sizeof(FurnaceProbePush) == 32);
static_assert(sizeof(FurnaceProbeLane) == 16 && offsetof(FurnaceProbeLane, paths) == 12);
}  // namespace vkmc::gpu
#endif
#endif
