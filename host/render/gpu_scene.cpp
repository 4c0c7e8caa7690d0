// Builds the device buffers from the scene in BVH leaf order and checks them against device limits.
#include "render/gpu_scene.h"

#include <unistd.h>

#include <bit>
#include <glm/gtc/packing.hpp>
#include <string_view>

#include "../shaders/shared/geometry.h"
#include "../shaders/shared/layout.h"
#include "../shaders/shared/sampling.h"
#include "../shaders/shared/scene_layout.h"
#include "error.h"
#include "render/alias_table.h"
#include "render/gpu_textures.h"
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

vk::Buffer makeTexelBuffer(vk::Context& ctx, const void* data, size_t bytes, uint32_t binding, const char* name,
                           size_t texelBytes = 16) {
  uint64_t texels = bytes / texelBytes;
  if (texels > ctx.properties().limits.maxTexelBufferElements)
    throw Error(std::string("scene too big for the device: ") + name + " needs " + std::to_string(texels) +
                " texels, the device allows " + std::to_string(ctx.properties().limits.maxTexelBufferElements));
  vk::Buffer b(ctx, std::max<size_t>(bytes, 16), VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT, vk::MemoryKind::DeviceLocal);
  b.upload(data, bytes);
  b.createView(sceneTexelFormat(binding));
  return b;
}

}  // namespace

VkFormat sceneTexelFormat(uint32_t binding) {
  switch (binding) {
    case BINDING_TRIANGLES: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_TRIANGLES));
    case BINDING_TRIANGLE_INFO: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_TRIANGLE_INFO));
    case BINDING_BVH_NODES: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_BVH_NODES));
    case BINDING_LIGHTS: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_LIGHTS));
    case BINDING_TEXTURE_TEXELS: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_TEXTURE_TEXELS));
    case BINDING_TEXTURES: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_TEXTURES));
    case BINDING_TRIANGLE_ATTRIBUTES: return formatOfQualifier(VKMC_MACRO_TEXT(TEXEL_FORMAT_TRIANGLE_ATTRIBUTES));
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
  limits.maxTextureTexels = std::min<uint64_t>(limits.maxTextureTexels, ctx.properties().limits.maxTexelBufferElements);
  return limits;
}

GpuScene::GpuScene(vk::Context& ctx, const Scene& scene, const Bvh& bvh, bool uniformLightSelection, bool keepBinaryBvh) {
  const size_t n = scene.triangleCount();
  info_.triangles = static_cast<uint32_t>(n);
  info_.materials = static_cast<uint32_t>(scene.materials.size());

  std::vector<double> power;
  std::vector<uint32_t> lightTriangles;
  std::vector<float> triangleArea(n);
  for (uint32_t i = 0; i < n; ++i) {
    uint32_t src = bvh.triangleOrder[i];
    const glm::vec3* p = &scene.positions[3 * src];
    glm::vec4 c = gpu::scaledTriangleCross(p[0], p[1], p[2]);  // the area the GPU's light pdfs use
    triangleArea[i] = 0.5f * glm::length(glm::vec3(c)) * c.w * c.w;
    const Material& m = scene.materials[scene.materialIds[src]];
    if (m.isEmissive() && triangleArea[i] > 0.0f) {
      double sides = m.doubleSided ? 2.0 : 1.0;
      // In double: a finite emission near FLT_MAX times area and pi would overflow float. A textured emitter
      // is weighted by its mean emission over its area.
      glm::vec3 emission = averageEmission(scene, src);
      power.push_back(double(gpu::luminance(emission)) * double(triangleArea[i]) * double(gpu::kPi) * sides);
      lightTriangles.push_back(i);
    }
  }
  info_.emissiveTriangles = static_cast<uint32_t>(lightTriangles.size());
  std::vector<glm::uvec4> lightTexels;
  std::vector<float> lightPmf(n, 0.0f);
  if (!lightTriangles.empty()) {
    // A light whose luminance is 0 but whose color is not (pure blue at tiny levels) still gets a chance.
    double total = 0.0;
    for (double w : power) total += w;
    for (double& w : power) w = std::max(w, total * 1e-12);
    for (double w : power) info_.emittedPower += w;
    if (uniformLightSelection) std::fill(power.begin(), power.end(), 1.0);
    std::vector<AliasEntry> table = buildAliasTable(power);
    for (size_t k = 0; k < table.size(); ++k) {
      lightTexels.push_back(gpu::encodeLightEntry(table[k].probability, table[k].alias, lightTriangles[k], table[k].pmf));
      lightPmf[lightTriangles[k]] = table[k].pmf;
    }
  } else {
    lightTexels.emplace_back(0u, 0u, 0u, 0u);  // bound but never read (SPEC_HAS_LIGHTS = 0)
  }

  std::vector<glm::vec4> triTexels(gpu::kTriangleTexels * n);
  std::vector<glm::uvec4> infoTexels(n);
  for (uint32_t i = 0; i < n; ++i) {
    uint32_t src = bvh.triangleOrder[i];
    glm::vec4* texels = &triTexels[gpu::kTriangleTexels * i];
    for (int k = 0; k < 3; ++k) texels[k] = glm::vec4(scene.positions[3 * src + k], 0.0f);
    texels[gpu::kTriangleLightPmfTexel].w = lightPmf[i];
    const Material& m = scene.materials[scene.materialIds[src]];
    infoTexels[i] = gpu::encodeTriangleInfo(scene.normals[3 * src], scene.normals[3 * src + 1], scene.normals[3 * src + 2],
                                            scene.materialIds[src], m.alphaMode != AlphaMode::Opaque);
  }

  std::vector<gpu::Material> mats;
  for (const Material& m : scene.materials) {
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
    mats.push_back(g);
  }

  triangles_ = makeTexelBuffer(ctx, triTexels.data(), triTexels.size() * 16, BINDING_TRIANGLES, "triangles");
  triangleInfo_ = makeTexelBuffer(ctx, infoTexels.data(), infoTexels.size() * 16, BINDING_TRIANGLE_INFO, "triangle info");
  bvhNodes_ =
      makeTexelBuffer(ctx, bvh.wideNodes.data(), bvh.wideNodes.size() * sizeof(BvhWideNode), BINDING_BVH_NODES, "BVH nodes");
  if (keepBinaryBvh)
    binaryBvhNodes_ =
        makeTexelBuffer(ctx, bvh.nodes.data(), bvh.nodes.size() * sizeof(BvhGpuNode), BINDING_BVH_NODES, "binary BVH nodes");
  lights_ = makeTexelBuffer(ctx, lightTexels.data(), lightTexels.size() * 16, BINDING_LIGHTS, "lights");
  // Textures and attributes only where a material reads them (SceneFeatures::textures); one texel otherwise.
  bool textured = scanFeatures(scene).textures;
  PackedTextures packed = textured ? packTextures(scene) : PackedTextures{};
  if (packed.texels.empty()) packed.texels.push_back(0u);
  if (packed.infos.empty()) packed.infos.emplace_back(0u);
  std::vector<glm::uvec4> attributes = textured ? packTriangleAttributes(scene, bvh.triangleOrder) : std::vector<glm::uvec4>{};
  if (attributes.empty()) attributes.emplace_back(0u);
  textureTexels_ =
      makeTexelBuffer(ctx, packed.texels.data(), packed.texels.size() * 4, BINDING_TEXTURE_TEXELS, "texture texels", 4);
  textures_ = makeTexelBuffer(ctx, packed.infos.data(), packed.infos.size() * 16, BINDING_TEXTURES, "textures");
  triangleAttributes_ = makeTexelBuffer(ctx, attributes.data(), attributes.size() * 16, BINDING_TRIANGLE_ATTRIBUTES,
                                        "triangle attributes");
  materials_ =
      vk::Buffer(ctx, mats.size() * sizeof(gpu::Material), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::DeviceLocal);
  materials_.upload(mats.data(), mats.size() * sizeof(gpu::Material));
  info_.bufferBytes = {{"triangles", triTexels.size() * 16},
                       {"triangle_info", infoTexels.size() * 16},
                       {"bvh_nodes", bvh.wideNodes.size() * sizeof(BvhWideNode)},
                       {"lights", lightTexels.size() * 16},
                       {"materials", mats.size() * sizeof(gpu::Material)},
                       {"texture_texels", packed.texels.size() * 4},
                       {"triangle_attributes", attributes.size() * 16}};
}

void GpuScene::bindTo(vk::KernelLayout& layout, bool binaryBvh) const {
  if (binaryBvh && !binaryBvhNodes_.handle()) throw Error("internal error: the binary BVH layout was not uploaded");
  layout.bindTexel(BINDING_TRIANGLES, triangles_);
  layout.bindTexel(BINDING_TRIANGLE_INFO, triangleInfo_);
  layout.bindTexel(BINDING_BVH_NODES, binaryBvh ? binaryBvhNodes_ : bvhNodes_);
  layout.bindTexel(BINDING_LIGHTS, lights_);
  layout.bindStorage(BINDING_MATERIALS, materials_);
  layout.bindTexel(BINDING_TEXTURE_TEXELS, textureTexels_);
  layout.bindTexel(BINDING_TEXTURES, textures_);
  layout.bindTexel(BINDING_TRIANGLE_ATTRIBUTES, triangleAttributes_);
}

}  // namespace vkmc
