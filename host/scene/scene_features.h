// What a scene needs, scanned once after loading (pbrt-v4's haveMedia/haveSubsurface idea): the renderer
// turns it into specialization constants, so code for absent features is compiled out and stages the scene
// cannot use are never dispatched.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace vkmc {

struct SceneFeatures {
  uint32_t triangles = 0;
  uint32_t emissiveTriangles = 0;
  uint32_t materials = 0;
  bool glossy = false;  // a material that is not Lambertian (a specular lobe, transmission, clearcoat or sheen)
  bool metallic = false;
  bool nonDefaultSpecular = false;  // KHR_materials_specular factor other than 1
  bool doubleSided = false;
  bool singleSided = false;     // a material is single-sided (glTF's default): the walks cull its back faces
  bool textures = false;        // a material samples a texture (or vertex colours tint it)
  bool normalMaps = false;      // a material has a normal texture
  bool alpha = false;           // a material is alpha MASK or BLEND: any-hit tests in the walks
  bool transmission = false;    // KHR_materials_transmission
  bool volumes = false;         // transmission into a KHR_materials_volume (refraction, attenuation)
  bool clearcoat = false;       // KHR_materials_clearcoat
  bool sheen = false;           // KHR_materials_sheen
  bool iridescence = false;     // KHR_materials_iridescence
  bool anisotropy = false;      // KHR_materials_anisotropy (its tangent frames come with the textures' attributes)
  bool dispersion = false;      // KHR_materials_dispersion on a volume: paths carry a colour channel past it
  bool delta = false;           // a lobe can be smooth (roughness^2 below kDeltaAlpha): delta BSDF samples
  uint32_t punctualLights = 0;  // KHR_lights_punctual instances
  // An environment light (Scene::environment): --environment's, or the file's world's (the studio, a white world).
  bool environment = false;
  // Some BVH walk can outgrow the register stack (walksCanOutgrowRegisterStack): the deep passes are built. Known
  // only once the BVH is; true until then.
  bool deepWalks = true;
  // The walks' register stack entries (registerStackEntries in bvh.h: 4, 8 or 12); the largest until the BVH is known.
  uint32_t registerStackEntries = 12;

  bool emitters() const { return emissiveTriangles > 0; }
  // Anything next-event estimation can sample: emissive triangles, punctual lights, the environment.
  bool lights() const { return emitters() || punctualLights > 0 || environment; }
  const char* sizeClass() const;  // "small" (< 1k triangles), "medium" (< 100k), "large"
  std::vector<std::string> unsupported() const;
};

SceneFeatures scanFeatures(const Scene& scene);

// All features on: the pipelines a renderer without per-scene specialization would build.
SceneFeatures allFeatures(const SceneFeatures& scene);

}  // namespace vkmc
