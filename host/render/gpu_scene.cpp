// Builds the device buffers from the scene in BVH leaf order and checks them against device limits.
#include "render/gpu_scene.h"

#include <unistd.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <glm/gtc/packing.hpp>
#include <optional>
#include <string_view>

#include "../shaders/shared/environment_map.h"
#include "../shaders/shared/geometry.h"
#include "../shaders/shared/layer_albedo_table.h"
#include "../shaders/shared/layout.h"
#include "../shaders/shared/punctual_light.h"
#include "../shaders/shared/sampling.h"
#include "../shaders/shared/scene_layout.h"
#include "../shaders/shared/texture_layout.h"
#include "error.h"
#include "render/alias_table.h"
#include "render/emitter_pairs.h"
#include "render/gpu_textures.h"
#include "scene/dispersion.h"
#include "scene/scene_features.h"
#include "scene/texture_sampler.h"

namespace vkmc {
namespace {

// A texel format named by its GLSL image-format qualifier (layout.h's TEXEL_FORMAT_*).
VkFormat formatOfQualifier(std::string_view qualifier) {
  if (qualifier == "rgba32f") return VK_FORMAT_R32G32B32A32_SFLOAT;
  if (qualifier == "rgba32ui") return VK_FORMAT_R32G32B32A32_UINT;
  if (qualifier == "r32ui") return VK_FORMAT_R32_UINT;
  throw Error("internal error: no VkFormat for the texel format " + std::string(qualifier));
}
#define VKMC_TOKEN_TEXT(x) #x
#define VKMC_MACRO_TEXT(x) VKMC_TOKEN_TEXT(x)

// A texel buffer's size: as is where the kernels read its length (imageSize), else notPowerOfTwoBytes.
enum class TexelSize { Exact, NotPowerOfTwo };

vk::Buffer makeTexelBuffer(vk::Context& ctx, const void* data, size_t bytes, uint32_t binding, const char* name,
                           TexelSize size = TexelSize::NotPowerOfTwo, size_t texelBytes = 16) {
  uint64_t texels = bytes / texelBytes;
  if (texels > ctx.properties().limits.maxTexelBufferElements)
    throw Error(std::string("scene too big for the device: ") + name + " needs " + std::to_string(texels) +
                " texels, the device allows " + std::to_string(ctx.properties().limits.maxTexelBufferElements));
  const size_t allocated =
      size == TexelSize::Exact ? std::max<size_t>(bytes, 16) : notPowerOfTwoTexelBytes(ctx, bytes, texelBytes);
  vk::Buffer b(ctx, allocated, VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT, vk::MemoryKind::DeviceLocal);
  b.upload(data, bytes);
  b.createView(sceneTexelFormat(binding));
  return b;
}

vk::Buffer makeStorageBuffer(vk::Context& ctx, const void* data, size_t bytes) {
  vk::Buffer b(ctx, std::max<size_t>(bytes, 16), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::DeviceLocal);
  if (bytes > 0) b.upload(data, bytes);
  return b;
}

double luminance(const glm::vec3& c) { return 0.2126 * double(c.x) + 0.7152 * double(c.y) + 0.0722 * double(c.z); }

gpu::PunctualLight toGpu(const PunctualLight& l, const glm::vec3& sceneCentre, float sceneRadius) {
  gpu::PunctualLight g{};
  bool directional = l.kind == PunctualKind::Directional;
  g.position = directional ? glm::vec4(sceneCentre, sceneRadius) : glm::vec4(l.position, 0.0f);
  g.direction = glm::vec4(l.direction, 0.0f);
  g.intensity = glm::vec4(l.intensity, 0.0f);
  g.kind = directional ? gpu::kPunctualDirectional : l.kind == PunctualKind::Spot ? gpu::kPunctualSpot : gpu::kPunctualPoint;
  g.cosOuter = std::cos(l.outerConeAngle);
  g.cosInner = std::cos(l.innerConeAngle);
  return g;
}

// What the device reads of the scene's lights: the alias entries (BINDING_LIGHTS), each triangle's selection pmf
// (the triangle texels' w), the punctual lights and the environment (its header and radiance, its table).
struct LightData {
  std::vector<glm::uvec4> entries;
  std::vector<float> trianglePmf;      // per triangle in BVH order, 0 unless it emits
  std::vector<float> trianglePartner;  // per triangle: an emitter quad's first half names its second (scene_layout.h)
  std::vector<gpu::PunctualLight> punctual;
  std::vector<glm::vec4> environment{3};  // gpu::EnvironmentHeader's 48 bytes, then the radiance texels
  std::vector<float> environmentTable{0.0f};
  uint32_t emissiveTriangles = 0;
  double emittedPower = 0.0;  // of the emissive triangles
};

// One light of the table before the alias table is built: what it is and its power.
struct LightRow {
  uint32_t kind, index;
  double power;
  std::optional<EmitterPair> pair;  // a triangle entry that stands for an emitter quad
};

// Every light of the scene with its power (gpu_scene.h), emissive triangles first; fills the punctual and
// environment data of `out` on the way.
std::vector<LightRow> collectLights(const Scene& scene, const Bvh& bvh, gpu::EnvironmentHeader& env, LightData& out) {
  const glm::vec3 centre = scene.bounds.valid() ? scene.bounds.center() : glm::vec3(0.0f);
  const float radius = scene.bounds.valid() ? 0.5f * glm::length(scene.bounds.extent()) : 0.0f;
  std::vector<LightRow> rows;
  // The emitters, and which of them may pair into quads (untextured, opaque: one emission over both halves).
  std::vector<glm::vec3> corners;
  std::vector<uint8_t> pairable;
  std::vector<uint32_t> materialOf;
  for (uint32_t i = 0; i < scene.triangleCount(); ++i) {
    uint32_t src = bvh.triangleOrder[i];
    const glm::vec3* p = &scene.positions[3 * src];
    glm::vec4 c = gpu::scaledTriangleCross(p[0], p[1], p[2]);  // the area the GPU's light pdfs use
    float area = 0.5f * glm::length(glm::vec3(c)) * c.w * c.w;
    const Material& m = scene.materials[scene.materialIds[src]];
    // A textured emitter is weighted by its mean emission over its area.
    if (!m.isEmissive() || !(area > 0.0f)) continue;
    rows.push_back({gpu::kLightKindTriangle, i, triangleEmittedPower(averageEmission(scene, src), m.doubleSided, area), {}});
    corners.insert(corners.end(), p, p + 3);
    pairable.push_back(!m.emissiveTexture.present() && m.alphaMode == AlphaMode::Opaque && i <= gpu::kMaxEmitterPartner);
    materialOf.push_back(scene.materialIds[src]);
  }
  out.emissiveTriangles = static_cast<uint32_t>(rows.size());
  std::vector<uint8_t> merged(rows.size(), 0);
  for (const EmitterPair& e : findEmitterPairs(corners, pairable, materialOf)) {
    rows[e.first].power += rows[e.second].power;
    rows[e.first].pair = EmitterPair{rows[e.first].index, rows[e.second].index, e.apex};
    merged[e.second] = 1;
  }
  size_t kept = 0;
  for (size_t r = 0; r < rows.size(); ++r)
    if (!merged[r]) rows[kept++] = rows[r];
  rows.resize(kept);
  for (const PunctualLight& l : scene.punctualLights) {
    double w = punctualLightPower(l, radius);
    if (!(w > 0.0)) continue;  // black: never sampled, never seen
    rows.push_back({gpu::kLightKindPunctual, uint32_t(out.punctual.size()), w});
    out.punctual.push_back(toGpu(l, centre, radius));
  }
  env.sceneSphere = glm::vec4(centre, radius);
  if (scene.environment) {
    const EnvironmentMap& e = *scene.environment;
    env.width = e.width, env.height = e.height;
    env.cosRotation = std::cos(glm::radians(e.rotationDegrees));
    env.sinRotation = std::sin(glm::radians(e.rotationDegrees));
    for (const glm::vec3& L : e.radiance) out.environment.emplace_back(L, 0.0f);
    out.environmentTable = environmentDistribution(e);
    double w = environmentPower(e, radius);
    if (w > 0.0 && out.environmentTable[0] > 0.0f) rows.push_back({gpu::kLightKindEnvironment, 0, w});
  }
  return rows;
}

// The light table: emissive triangles, punctual lights and the environment chosen together, in proportion to
// their power (or uniformly).
LightData buildLights(const Scene& scene, const Bvh& bvh, bool uniformLightSelection) {
  LightData out;
  gpu::EnvironmentHeader env{};
  std::vector<LightRow> rows = collectLights(scene, bvh, env, out);
  out.trianglePmf.assign(scene.triangleCount(), 0.0f);
  out.trianglePartner.assign(scene.triangleCount(), 0.0f);
  if (!rows.empty()) {
    // A light whose luminance is 0 but whose color is not (pure blue at tiny levels) still gets a chance.
    double total = 0.0;
    for (const LightRow& r : rows) total += r.power;
    std::vector<double> weights;
    for (const LightRow& r : rows) {
      weights.push_back(uniformLightSelection ? (r.pair ? 2.0 : 1.0) : std::max(r.power, total * 1e-12));
      if (r.kind == gpu::kLightKindTriangle) out.emittedPower += std::max(r.power, total * 1e-12);
    }
    std::vector<AliasEntry> table = buildAliasTable(weights);
    for (size_t k = 0; k < table.size(); ++k) {
      const LightRow& r = rows[k];
      out.entries.push_back(gpu::encodeLightEntry(table[k].probability, table[k].alias, r.kind, r.index, table[k].pmf));
      if (r.kind == gpu::kLightKindTriangle && !r.pair) out.trianglePmf[r.index] = table[k].pmf;
      if (r.pair) {  // each half: half the pair's pmf (shading.glsl, sampleEmissiveTriangle)
        out.trianglePmf[r.pair->first] = out.trianglePmf[r.pair->second] = 0.5f * table[k].pmf;
        out.trianglePartner[r.pair->first] = gpu::encodeEmitterPartner(r.pair->second, r.pair->apex);
      }
      if (r.kind == gpu::kLightKindEnvironment) env.selectionPmf = table[k].pmf;
    }
  } else {
    out.entries.emplace_back(0u, 0u, 0u, 0u);  // bound but never read (SPEC_HAS_LIGHTS = 0)
  }
  static_assert(sizeof(gpu::EnvironmentHeader) == 3 * sizeof(glm::vec4));
  std::memcpy(out.environment.data(), &env, sizeof(env));
  return out;
}

}  // namespace

double triangleEmittedPower(glm::vec3 emission, bool doubleSided, float area) {
  // In double: a finite emission near FLT_MAX times area and pi would overflow float.
  return luminance(emission) * double(area) * double(gpu::kPi) * (doubleSided ? 2.0 : 1.0);
}

double punctualLightPower(const PunctualLight& l, double sceneRadius) {
  double I = luminance(l.intensity);
  switch (l.kind) {
    case PunctualKind::Point: return 4.0 * double(gpu::kPi) * I;
    case PunctualKind::Spot: return I * gpu::spotSolidAngleFactor(std::cos(l.outerConeAngle), std::cos(l.innerConeAngle));
    case PunctualKind::Directional: return I * double(gpu::kPi) * sceneRadius * sceneRadius;
  }
  return 0.0;
}

double environmentPower(const EnvironmentMap& e, double sceneRadius) {
  // pi r^2 times the integral of luminance over the sphere, each row of pixels over its exact solid angle.
  double integral = 0.0;
  for (uint32_t row = 0; row < e.height; ++row) {
    double rowSolidAngle = 2.0 * M_PI * (std::cos(M_PI * row / e.height) - std::cos(M_PI * (row + 1) / e.height)) / e.width;
    for (uint32_t col = 0; col < e.width; ++col) integral += luminance(e.radiance[size_t(row) * e.width + col]) * rowSolidAngle;
  }
  return M_PI * sceneRadius * sceneRadius * integral;
}

std::vector<float> environmentDistribution(const EnvironmentMap& e) {
  const uint32_t w = e.width, h = e.height;
  std::vector<float> table(gpu::envDistributionSize(w, h), 0.0f);
  std::vector<double> rowIntegral(h, 0.0);
  const uint32_t fo = gpu::envFunctionOffset(w, h), co = gpu::envConditionalCdfOffset(h);
  for (uint32_t row = 0; row < h; ++row) {
    double sinTheta = gpu::envRowSinTheta(row, h);
    std::vector<double> f(w);
    for (uint32_t col = 0; col < w; ++col) {
      f[col] = luminance(e.radiance[size_t(row) * w + col]) * sinTheta;
      table[fo + row * w + col] = float(f[col]);
      rowIntegral[row] += f[col] / w;
    }
    double sum = 0.0;
    float* cdf = &table[co + row * (w + 1)];
    for (uint32_t col = 0; col < w; ++col) {
      cdf[col] = rowIntegral[row] > 0.0 ? float(sum / (rowIntegral[row] * w)) : float(col) / float(w);
      sum += f[col];
    }
    cdf[w] = 1.0f;
    table[gpu::envRowIntegralOffset(h) + row] = float(rowIntegral[row]);
  }
  double integral = 0.0;
  for (double r : rowIntegral) integral += r / h;
  double sum = 0.0;
  float* marginal = &table[gpu::envMarginalCdfOffset()];
  for (uint32_t row = 0; row < h; ++row) {
    marginal[row] = integral > 0.0 ? float(sum / (integral * h)) : float(row) / float(h);
    sum += rowIntegral[row];
  }
  marginal[h] = 1.0f;
  table[0] = float(integral);
  return table;
}

size_t notPowerOfTwoBytes(size_t bytes, size_t maxBytes) {
  const size_t exact = std::max<size_t>(bytes, 16);
  size_t n = exact;
  while ((n & (n - 1)) == 0) n += 16;
  return n <= maxBytes ? n : exact;
}

size_t notPowerOfTwoTexelBytes(const vk::Context& ctx, size_t bytes, size_t texelBytes) {
  return notPowerOfTwoBytes(bytes, size_t(ctx.properties().limits.maxTexelBufferElements) * texelBytes);
}

VkFormat sceneTexelFormat(uint32_t binding) {
  switch (binding) {
    case BINDING_TRIANGLES: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_TRIANGLES));
    case BINDING_TRIANGLE_INFO: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_TRIANGLE_INFO));
    case BINDING_BVH_NODES: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_BVH_NODES));
    case BINDING_LIGHTS: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_LIGHTS));
    case BINDING_TEXTURE_TEXELS: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_TEXTURE_TEXELS));
    case BINDING_TEXTURES: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_TEXTURES));
    case BINDING_TRIANGLE_ATTRIBUTES: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_TRIANGLE_ATTRIBUTES));
    case BINDING_LAYER_ALBEDO: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_LAYER_ALBEDO));
    case BINDING_EARS_SAMPLING: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_EARS_SAMPLING));
    case BINDING_MATERIALS: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_MATERIALS));
    case BINDING_PATH_TEXELS: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_PATH_TEXELS));
    case BINDING_HIT_TEXELS: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_HIT_TEXELS));
    case BINDING_PIXEL_ESTIMATE: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_PIXEL_ESTIMATE));
    case BINDING_QUEUE_TEXELS: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_QUEUE_TEXELS));
    case BINDING_SHADOW_TEXELS: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_SHADOW_TEXELS));
  }
  throw Error("internal error: binding " + std::to_string(binding) + " is not a scene texel binding");
}

uint64_t maxSceneTriangles(const vk::Context& ctx) {
  uint64_t limit = uint64_t(ctx.properties().limits.maxTexelBufferElements) / 3;
  if (ctx.maxAllocationBytes() > 0) limit = std::min<uint64_t>(limit, ctx.maxAllocationBytes() / 48);
  if (ctx.largestDeviceLocalHeapBytes() > 0) limit = std::min<uint64_t>(limit, ctx.largestDeviceLocalHeapBytes() / 2 / 96);
  long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  if (pages > 0 && pageSize > 0) limit = std::min<uint64_t>(limit, uint64_t(pages) * uint64_t(pageSize) / 2 / 320);
  return std::min<uint64_t>(limit, LoadLimits{}.maxTriangles);
}

LoadLimits deviceLoadLimits(const vk::Context& ctx) {
  LoadLimits limits;
  limits.maxTriangles = maxSceneTriangles(ctx);
  // A texture and its one-texel gutters must fit a page of the texture pages' array image (texture_atlas.h).
  limits.maxTextureSide = std::min<uint32_t>(limits.maxTextureSide, ctx.properties().limits.maxImageDimension2D - 2);
  return limits;
}

namespace {
// A material as the kernels read it (gpu::Material, shaders/shared).
gpu::Material gpuMaterial(const Material& m) {
  gpu::Material g{};
  g.baseColor = glm::vec4(m.baseColor, m.alpha);
  g.emission = m.emission;
  g.flags = (m.doubleSided ? gpu::kMaterialDoubleSided : 0u) | (m.alphaMode == AlphaMode::Mask ? gpu::kMaterialAlphaMask : 0u) |
            (m.alphaMode == AlphaMode::Blend ? gpu::kMaterialAlphaBlend : 0u);
  g.metallic = m.metallic;
  g.roughness = m.roughness;
  g.specular = m.specular;
  g.alphaCutoff = m.alphaCutoff;
  g.baseColorTexture = textureSlot(m.baseColorTexture);
  g.metallicRoughnessTexture = textureSlot(m.metallicRoughnessTexture);
  g.normalTexture = textureSlot(m.normalTexture);
  g.emissiveTexture = textureSlot(m.emissiveTexture);
  g.specularColor = glm::vec4(m.specularColor, m.ior);
  g.attenuation = glm::vec4(m.attenuation, m.transmission);
  g.sheen = glm::vec4(m.sheenColor, m.sheenRoughness);
  g.clearcoat = m.clearcoat;
  g.clearcoatRoughness = m.clearcoatRoughness;
  g.volumetric = m.volumetric ? 1u : 0u;
  g.transmissionTexture = textureSlot(m.transmissionTexture);
  g.clearcoatTexture = textureSlot(m.clearcoatTexture);
  g.clearcoatRoughnessTexture = textureSlot(m.clearcoatRoughnessTexture);
  g.clearcoatNormalTexture = textureSlot(m.clearcoatNormalTexture);
  g.sheenColorTexture = textureSlot(m.sheenColorTexture);
  g.sheenRoughnessTexture = textureSlot(m.sheenRoughnessTexture);
  g.specularTexture = textureSlot(m.specularTexture);
  g.specularColorTexture = textureSlot(m.specularColorTexture);
  g.iridescence = glm::vec4(m.iridescence, m.iridescenceIor, m.iridescenceThicknessMin, m.iridescenceThicknessMax);
  g.iridescenceTexture = textureSlot(m.iridescenceTexture);
  g.iridescenceThicknessTexture = textureSlot(m.iridescenceThicknessTexture);
  g.anisotropy = glm::vec4(m.anisotropyStrength, std::cos(m.anisotropyRotation), std::sin(m.anisotropyRotation), 0.0f);
  g.anisotropyTexture = textureSlot(m.anisotropyTexture);
  g.dispersion = glm::vec4(channelIors(m.ior, m.dispersion), m.hasDispersion() ? 1.0f : 0.0f);
  return g;
}
}  // namespace

GpuScene::GpuScene(vk::Context& ctx, const Scene& scene, const Bvh& bvh, bool uniformLightSelection, bool keepBinaryBvh) {
  const size_t n = scene.triangleCount();
  info_.triangles = static_cast<uint32_t>(n);
  info_.registerStackEntries = registerStackEntries(bvh.stats);
  info_.deepWalks = walksCanOutgrowRegisterStack(bvh.stats);
  info_.materials = static_cast<uint32_t>(scene.materials.size());
  if (scene.bounds.valid()) info_.boundsMin = scene.bounds.min, info_.boundsMax = scene.bounds.max;

  LightData lights = buildLights(scene, bvh, uniformLightSelection);
  info_.emissiveTriangles = lights.emissiveTriangles;
  info_.punctualLights = static_cast<uint32_t>(lights.punctual.size());
  info_.emittedPower = lights.emittedPower;
  const std::vector<float>& lightPmf = lights.trianglePmf;

  std::vector<glm::vec4> triTexels(gpu::kTriangleTexels * n);
  std::vector<glm::uvec4> infoTexels(n);
  for (uint32_t i = 0; i < n; ++i) {
    uint32_t src = bvh.triangleOrder[i];
    glm::vec4* texels = &triTexels[gpu::kTriangleTexels * i];
    for (int k = 0; k < 3; ++k) texels[k] = glm::vec4(scene.positions[3 * src + k], 0.0f);
    texels[gpu::kTriangleLightPmfTexel].w = lightPmf[i];
    texels[gpu::kTrianglePartnerTexel].w = lights.trianglePartner[i];
    const Material& m = scene.materials[scene.materialIds[src]];
    info_.alphaTested |= m.alphaMode != AlphaMode::Opaque;
    texels[gpu::kTriangleSidesTexel].w = gpu::encodeTriangleSingleSided(m.culledFromBehind());
    infoTexels[i] = gpu::encodeTriangleInfo(scene.normals[3 * src], scene.normals[3 * src + 1], scene.normals[3 * src + 2],
                                            scene.materialIds[src], m.alphaMode != AlphaMode::Opaque);
  }

  std::vector<gpu::Material> mats;
  for (const Material& m : scene.materials) mats.push_back(gpuMaterial(m));

  triangles_ = makeTexelBuffer(ctx, triTexels.data(), triTexels.size() * 16, BINDING_TRIANGLES, "triangles");
  triangleInfo_ = makeTexelBuffer(ctx, infoTexels.data(), infoTexels.size() * 16, BINDING_TRIANGLE_INFO, "triangle info");
  bvhNodes_ =
      makeTexelBuffer(ctx, bvh.wideNodes.data(), bvh.wideNodes.size() * sizeof(BvhWideNode), BINDING_BVH_NODES, "BVH nodes");
  if (keepBinaryBvh)
    binaryBvhNodes_ =
        makeTexelBuffer(ctx, bvh.nodes.data(), bvh.nodes.size() * sizeof(BvhGpuNode), BINDING_BVH_NODES, "binary BVH nodes");
  // The light count is the table's length (shading.glsl selectLight).
  lights_ = makeTexelBuffer(ctx, lights.entries.data(), lights.entries.size() * 16, BINDING_LIGHTS, "lights", TexelSize::Exact);
  // Textures and attributes only where a material reads them (SceneFeatures::textures); one texel otherwise.
  bool textured = scanFeatures(scene).textures;
  const VkPhysicalDeviceLimits& limits = ctx.properties().limits;
  const std::vector<Texture> none;
  PackedTextures packed = packTextures(textured ? scene.textures : none, limits.maxImageDimension2D, limits.maxImageArrayLayers);
  if (packed.infos.empty()) packed.infos.emplace_back(0u);
  std::vector<glm::uvec4> attributes = textured ? packTriangleAttributes(scene, bvh.triangleOrder) : std::vector<glm::uvec4>{};
  if (attributes.empty()) attributes.emplace_back(0u);
  const TextureAtlas& atlas = packed.atlas;
  texturePages_ = std::make_unique<vk::ArrayImage>(ctx, atlas.pageWidth, atlas.pageHeight, atlas.layers, atlas.texels.data());
  bilinear_ = std::make_unique<vk::Sampler>(ctx, VK_FILTER_LINEAR);
  textures_ = makeTexelBuffer(ctx, packed.infos.data(), packed.infos.size() * 16, BINDING_TEXTURES, "textures");
  layerAlbedo_ = makeTexelBuffer(ctx, gpu::kLayerAlbedo, sizeof(gpu::kLayerAlbedo), BINDING_LAYER_ALBEDO, "layer albedo",
                                 TexelSize::NotPowerOfTwo, 4);
  triangleAttributes_ =
      makeTexelBuffer(ctx, attributes.data(), attributes.size() * 16, BINDING_TRIANGLE_ATTRIBUTES, "triangle attributes",
                      TexelSize::Exact);  // its length bounds the reads (textures.glsl)
  materials_ = makeTexelBuffer(ctx, mats.data(), mats.size() * sizeof(gpu::Material), BINDING_MATERIALS, "materials");
  punctualLights_ = makeStorageBuffer(ctx, lights.punctual.data(), lights.punctual.size() * sizeof(gpu::PunctualLight));
  environment_ = makeStorageBuffer(ctx, lights.environment.data(), lights.environment.size() * sizeof(glm::vec4));
  environmentDistribution_ =
      makeStorageBuffer(ctx, lights.environmentTable.data(), lights.environmentTable.size() * sizeof(float));
  info_.bufferBytes = {
      {"triangles", triTexels.size() * 16},
      {"triangle_info", infoTexels.size() * 16},
      {"bvh_nodes", bvh.wideNodes.size() * sizeof(BvhWideNode)},
      {"lights", lights.entries.size() * 16},
      {"materials", mats.size() * sizeof(gpu::Material)},
      {"punctual_lights", lights.punctual.size() * sizeof(gpu::PunctualLight)},
      {"environment", lights.environment.size() * sizeof(glm::vec4) + lights.environmentTable.size() * sizeof(float)},
      {"texture_pages", atlas.texels.size() * 4},
      {"triangle_attributes", attributes.size() * 16}};
}

void bindTexturePages(vk::KernelLayout& layout, const vk::ArrayImage& pages, const vk::Sampler& bilinear) {
  layout.bindSampledImage(BINDING_TEXTURE_PAGES, gpu::kTexturePageUnorm, pages.unormView(), bilinear.handle());
  layout.bindSampledImage(BINDING_TEXTURE_PAGES, gpu::kTexturePageSrgb, pages.srgbView(), bilinear.handle());
}

void GpuScene::bindTo(vk::KernelLayout& layout, bool binaryBvh) const {
  if (binaryBvh && !binaryBvhNodes_.handle()) throw Error("internal error: the binary BVH layout was not uploaded");
  layout.bindTexel(BINDING_TRIANGLES, triangles_);
  layout.bindTexel(BINDING_TRIANGLE_INFO, triangleInfo_);
  layout.bindTexel(BINDING_BVH_NODES, binaryBvh ? binaryBvhNodes_ : bvhNodes_);
  layout.bindTexel(BINDING_LIGHTS, lights_);
  layout.bindTexel(BINDING_MATERIALS, materials_);
  layout.bindTexel(BINDING_LAYER_ALBEDO, layerAlbedo_);
  bindTexturePages(layout, *texturePages_, *bilinear_);
  layout.bindTexel(BINDING_TEXTURES, textures_);
  layout.bindTexel(BINDING_TRIANGLE_ATTRIBUTES, triangleAttributes_);
  layout.bindStorage(BINDING_PUNCTUAL_LIGHTS, punctualLights_);
  layout.bindStorage(BINDING_ENVIRONMENT, environment_);
  layout.bindStorage(BINDING_ENVIRONMENT_DISTRIBUTION, environmentDistribution_);
}

}  // namespace vkmc
