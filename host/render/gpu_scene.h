// The scene on the device: reordered triangles, per-triangle info, BVH nodes, light table, materials.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bvh/bvh.h"
#include "scene/gltf_loader.h"
#include "scene/scene.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/image.h"
#include "vk/kernel.h"

namespace vkmc {

struct GpuSceneInfo {
  uint32_t triangles = 0;
  uint32_t emissiveTriangles = 0;
  uint32_t materials = 0;
  uint32_t punctualLights = 0;                 // in the light table (black ones are left out)
  bool alphaTested = false;                    // some triangle's material is alpha MASK or BLEND (the walks' any-hit test)
  uint32_t registerStackEntries = 12;          // the walks' register stack for this BVH (registerStackEntries in bvh.h)
  bool deepWalks = true;                       // some walk can outgrow it (walksCanOutgrowRegisterStack): deep passes needed
  double emittedPower = 0.0;                   // sum over emissive triangles of luminance(Le) * area * pi * sides
  glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // the scene's bounding box (EARS lays its cache grid over it)
  std::vector<std::pair<std::string, uint64_t>> bufferBytes;
};

// The view format of a scene texel binding (BINDING_TRIANGLES ... BINDING_LIGHTS), as common.glsl declares it.
VkFormat sceneTexelFormat(uint32_t binding);

// Bytes for a texel buffer of `bytes` whose length no kernel reads: at least 16 and never a power of two.
// llvmpipe keys a compiled kernel on whether a texel buffer's texel count is a power of two (for 16- and 4-byte
// texels exactly when the size is one), and the warm-up compiles for counts that are not
// (background_warm_up.cpp); a power of two (an empty array's 16 bytes, a small scene's 512 bytes of BVH nodes, a
// 256x256 image's pixel estimates) made the render compile those kernels a second time. Where padding would pass
// maxBytes (the device's texel limit), the size stays as it is.
size_t notPowerOfTwoBytes(size_t bytes, size_t maxBytes = SIZE_MAX);
// The same within this device's texel limit for texels of texelBytes.
size_t notPowerOfTwoTexelBytes(const vk::Context& ctx, size_t bytes, size_t texelBytes = 16);

// The most triangles a scene may have on this device and machine: its largest buffer (3 texels a triangle)
// within maxTexelBufferElements and one allocation, the scene (~96 bytes a triangle: triangles, their info, BVH
// nodes) within half of device-local memory, and the host's peak (~320 bytes a triangle while loading and
// building) within half of physical memory.
uint64_t maxSceneTriangles(const vk::Context& ctx);
// The loader's limits for scenes bound for this device (maxSceneTriangles).
LoadLimits deviceLoadLimits(const vk::Context& ctx);

// The powers (luminance, in W) that power-proportional light selection weighs, pbrt-v4's conventions for the
// lights without a surface, with r the radius of the scene's bounding sphere:
//   an emissive triangle: luminance(mean Le) area pi (times 2 when double-sided; textured: averageEmission);
//   a point light 4 pi I; a spot I 2 pi (1 - cosInner + (cosInner - cosOuter) / 3) (exact for the spec's falloff);
//   a directional light E pi r^2; the environment pi r^2 times the integral of its luminance over the sphere.
double triangleEmittedPower(glm::vec3 emission, bool doubleSided, float area);  // emission: its mean over the area
double punctualLightPower(const PunctualLight& light, double sceneRadius);
double environmentPower(const EnvironmentMap& environment, double sceneRadius);
// The environment's sampling table (BINDING_ENVIRONMENT_DISTRIBUTION; shaders/shared/environment_map.h).
std::vector<float> environmentDistribution(const EnvironmentMap& environment);

// The texture pages' views (texture_layout.h kTexturePage*) to BINDING_TEXTURE_PAGES.
void bindTexturePages(vk::KernelLayout& layout, const vk::ArrayImage& pages, const vk::Sampler& bilinear);

class GpuScene {
 public:
  // uniformLightSelection: every emissive triangle equally likely; otherwise in proportion to emitted power.
  // keepBinaryBvh: also upload the binary node layout, for side-by-side traversal benchmarks.
  GpuScene(vk::Context& ctx, const Scene& scene, const Bvh& bvh, bool uniformLightSelection = false, bool keepBinaryBvh = false);
  const GpuSceneInfo& info() const { return info_; }
  const vk::Buffer& triangles() const { return triangles_; }
  const vk::Buffer& triangleInfo() const { return triangleInfo_; }
  const vk::Buffer& bvhNodes() const { return bvhNodes_; }
  const vk::Buffer& lights() const { return lights_; }
  const vk::Buffer& materials() const { return materials_; }
  // Binds the scene's buffers (triangles, triangle info, BVH nodes, lights, materials, punctual lights,
  // environment) to their bindings.
  void bindTo(vk::KernelLayout& layout, bool binaryBvh = false) const;

 private:
  GpuSceneInfo info_;
  vk::Buffer triangles_, triangleInfo_, bvhNodes_, binaryBvhNodes_, lights_, materials_, punctualLights_, environment_,
      environmentDistribution_;
  vk::Buffer textures_, triangleAttributes_, layerAlbedo_;
  std::unique_ptr<vk::ArrayImage> texturePages_;
  std::unique_ptr<vk::Sampler> bilinear_;
};

}  // namespace vkmc
