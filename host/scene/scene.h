// The loaded scene as plain data: world-space triangles, materials, cameras. No Vulkan here.
#pragma once
#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vkmc {

// A material's reference to a texture (glTF textureInfo), with KHR_texture_transform as a 2x3 matrix on uv.
struct TextureRef {
  int texture = -1;                    // index into Scene::textures; -1: none
  int texCoord = 0;                    // TEXCOORD_0 or _1
  glm::vec3 uvRow0{1.0f, 0.0f, 0.0f};  // u' = dot(uvRow0, (u, v, 1))
  glm::vec3 uvRow1{0.0f, 1.0f, 0.0f};  // v' = dot(uvRow1, (u, v, 1))
  float scale = 1.0f;                  // normalTexture.scale (1 for the other slots)
  bool present() const { return texture >= 0; }
};

enum class AlphaMode { Opaque, Mask, Blend };
enum class TextureWrap { Repeat, ClampToEdge, MirroredRepeat };

// A decoded image with its sampler's addressing (glTF texture = image + sampler): 8-bit RGBA as stored (sRGB
// or linear is the slot's business: baseColor and emissive are sRGB, the others linear).
struct Texture {
  uint32_t width = 0, height = 0;
  std::vector<uint32_t> texels;  // RGBA8, row-major from the image's top row (uv (0,0) is the top-left corner)
  TextureWrap wrapS = TextureWrap::Repeat, wrapT = TextureWrap::Repeat;
  bool nearest = false;  // magFilter NEAREST; otherwise bilinear
  std::string name;
};

struct Material {
  glm::vec3 baseColor{1.0f};
  float alpha = 1.0f;
  glm::vec3 emission{0.0f};  // emissiveFactor x KHR_materials_emissive_strength, W m^-2 sr^-1
  float metallic = 1.0f;
  float roughness = 1.0f;
  float specular = 1.0f;  // KHR_materials_specular specularFactor
  bool doubleSided = false;
  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;
  TextureRef baseColorTexture, metallicRoughnessTexture, normalTexture, emissiveTexture;
  // The material extensions (scene/gltf_material_extensions.h).
  glm::vec3 specularColor{1.0f};  // KHR_materials_specular specularColorFactor
  float ior = 1.5f;               // KHR_materials_ior
  float transmission = 0.0f;      // KHR_materials_transmission
  bool volumetric = false;        // KHR_materials_volume thicknessFactor > 0: transmission refracts into the mesh
  glm::vec3 attenuation{0.0f};    // its attenuation coefficient, -ln(attenuationColor) / attenuationDistance (1/m)
  float clearcoat = 0.0f, clearcoatRoughness = 0.0f;
  glm::vec3 sheenColor{0.0f};
  float sheenRoughness = 0.0f;
  // KHR_materials_iridescence: the film's strength, ior and thickness range (nm).
  float iridescence = 0.0f, iridescenceIor = 1.3f, iridescenceThicknessMin = 100.0f, iridescenceThicknessMax = 400.0f;
  // KHR_materials_anisotropy: the specular lobe's stretch along a direction rotated from the tangent (radians);
  // its texture's red and green give the direction in tangent space, its blue scales the strength.
  float anisotropyStrength = 0.0f, anisotropyRotation = 0.0f;
  float dispersion = 0.0f;  // KHR_materials_dispersion: 20 / the Abbe number (scene/dispersion.h)
  TextureRef transmissionTexture, clearcoatTexture, clearcoatRoughnessTexture, clearcoatNormalTexture, sheenColorTexture,
      sheenRoughnessTexture, specularTexture, specularColorTexture, iridescenceTexture, iridescenceThicknessTexture,
      anisotropyTexture;
  std::array<const TextureRef*, 15> textureRefs() const {
    return {&baseColorTexture,
            &metallicRoughnessTexture,
            &normalTexture,
            &emissiveTexture,
            &transmissionTexture,
            &clearcoatTexture,
            &clearcoatRoughnessTexture,
            &clearcoatNormalTexture,
            &sheenColorTexture,
            &sheenRoughnessTexture,
            &specularTexture,
            &specularColorTexture,
            &iridescenceTexture,
            &iridescenceThicknessTexture,
            &anisotropyTexture};
  }
  bool textured() const {
    for (const TextureRef* t : textureRefs())
      if (t->present()) return true;
    return false;
  }
  // Back faces the walks cull (glTF 3.9.5): a single-sided material's, except where light must pass through
  // and leave again (transmission: a refracting volume is entered through front faces and left through back ones).
  bool culledFromBehind() const { return !doubleSided && transmission <= 0.0f; }
  bool hasSheen() const { return sheenColor.x > 0.0f || sheenColor.y > 0.0f || sheenColor.z > 0.0f; }
  // A film that changes the Fresnel term somewhere (a zero thickness everywhere is no film).
  bool hasIridescence() const { return iridescence > 0.0f && std::max(iridescenceThicknessMin, iridescenceThicknessMax) > 0.0f; }
  // A stretched lobe: it needs a tangent frame (generated where the file has none).
  bool hasAnisotropy() const { return anisotropyStrength > 0.0f; }
  // Dispersion acts where light refracts into a volume (the extension's rule).
  bool hasDispersion() const { return dispersion > 0.0f && transmission > 0.0f && volumetric; }
  bool isEmissive() const { return emission.x > 0.0f || emission.y > 0.0f || emission.z > 0.0f; }
};

enum class CameraKind { Perspective, Orthographic };

struct Camera {
  CameraKind kind = CameraKind::Perspective;
  glm::vec3 position{0.0f};
  glm::vec3 forward{0.0f, 0.0f, -1.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float yfov = 0.7853982f;           // radians (perspective)
  std::optional<float> aspectRatio;  // width / height, when the file gives one
  float xmag = 1.0f, ymag = 1.0f;    // half extents (orthographic)
  std::string name;
};

// A KHR_lights_punctual light instance in world space. vkmc reads the spec's photometric values as radiometric
// ones, 1:1 (docs/manual/scenes.md): a point or spot light's intensity (cd) is its radiant intensity I in W/sr, a
// directional light's (lx) its irradiance E in W/m^2 at normal incidence.
enum class PunctualKind { Point, Spot, Directional };

struct PunctualLight {
  PunctualKind kind = PunctualKind::Point;
  glm::vec3 position{0.0f};
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // unit, the direction it shines along (the node's -Z)
  glm::vec3 intensity{1.0f};               // color x intensity: I (point, spot) or E (directional)
  float innerConeAngle = 0.0f;             // spot, radians: 0 <= inner < outer <= pi/2
  float outerConeAngle = 0.7853982f;
  std::string name;
};

// An environment light: an equirectangular map of radiance (W m^-2 sr^-1), +Y up, the image's centre along -Z
// (shaders/shared/environment_map.h has the convention). A 1 x 1 map is a constant environment.
struct EnvironmentMap {
  uint32_t width = 0, height = 0;
  std::vector<glm::vec3> radiance;  // row-major from the top row, strength applied
  float rotationDegrees = 0.0f;     // about +Y, counter-clockwise seen from above
  std::string source;               // the file, or "constant"
  static EnvironmentMap constant(const glm::vec3& radiance) { return {1, 1, {radiance}, 0.0f, "constant"}; }
};

struct Aabb {
  glm::vec3 min{std::numeric_limits<float>::infinity()};
  glm::vec3 max{-std::numeric_limits<float>::infinity()};
  void grow(const glm::vec3& p) { min = glm::min(min, p), max = glm::max(max, p); }
  void grow(const Aabb& b) { min = glm::min(min, b.min), max = glm::max(max, b.max); }
  bool valid() const { return min.x <= max.x && min.y <= max.y && min.z <= max.z; }
  glm::vec3 extent() const { return max - min; }
  glm::vec3 center() const { return 0.5f * min + 0.5f * max; }  // min + max could overflow
  // In double: a float extent product overflows for scenes past ~1e19 and underflows below ~1e-19.
  double halfArea() const {
    glm::dvec3 e = glm::max(glm::dvec3(max) - glm::dvec3(min), glm::dvec3(0.0));
    return e.x * e.y + e.y * e.z + e.z * e.x;
  }
};

// A glTF point or line segment in world space (a point: a == b), drawn as a thin ribbon once the camera is known
// (scene/thin_ribbons.h).
struct ThinSegment {
  glm::vec3 a, b;
  glm::vec4 colorA{1.0f}, colorB{1.0f};  // COLOR_0 at each end
  uint32_t material = 0;
};

// What lights the scene besides its own emitters and punctual lights, as the file declares it in its scene's
// extras (`"extras": {"vkmc_world": "lights-only"}`): a model viewer's studio unless it says otherwise. vkmc's own
// scenes and the tests' declare theirs, so that they are measured in the world they were made for.
enum class World {
  Studio,      // undeclared: the built-in studio environment (scene/studio_environment.h), a grey backdrop
  LightsOnly,  // "lights-only": nothing else; the world beyond is black (the lab scenes in scenes/)
  White,       // "white": a uniform environment of radiance 1, a grey backdrop (a furnace's world)
};

struct Scene {
  std::vector<glm::vec3> positions;  // 3 per triangle, world space, counter-clockwise front faces
  std::vector<glm::vec3> normals;    // 3 per triangle, world space (geometric normal where the file has none)
  // Per-corner vertex attributes, parallel to `positions`; each is empty when no primitive in the scene has it,
  // so scenes without textures pay nothing. Primitives lacking one get its default.
  std::vector<glm::vec2> uv0, uv1;  // TEXCOORD_0 / TEXCOORD_1 as stored (default 0,0)
  // World-space unit tangent (re-orthogonalized against the corner's normal) and bitangent sign w = +-1
  // (bitangent = cross(normal, tangent) * w, already flipped for mirroring nodes). Present when some primitive's
  // material has a normalTexture: from TANGENT, else generated (scene/tangent_space.h); primitives whose material
  // has none get TANGENT or an arbitrary perpendicular with w = 1.
  std::vector<glm::vec4> tangents;
  std::vector<glm::vec4> colors;      // COLOR_0, linear RGBA (VEC3: alpha 1; default 1,1,1,1)
  std::vector<uint32_t> materialIds;  // 1 per triangle
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<Camera> cameras;  // camera instances in node order
  Aabb bounds;
  uint64_t degenerateTriangles = 0;       // zero-area triangles skipped
  uint64_t skippedPrimitives = 0;         // primitives of an unknown mode, skipped
  std::vector<ThinSegment> thinSegments;  // points and lines, not yet triangles
  std::vector<std::string> warnings;
  std::string path;
  std::vector<PunctualLight> punctualLights;  // KHR_lights_punctual instances in node order
  std::optional<EnvironmentMap> environment;  // not in glTF: the render sets it (--environment, or the world's)
  World world = World::LightsOnly;            // a file's: what it declares (the studio where nothing); built in code: lights-only

  size_t triangleCount() const { return materialIds.size(); }
  bool hasUv0() const { return !uv0.empty(); }
  bool hasTangents() const { return !tangents.empty(); }
  bool hasColors() const { return !colors.empty(); }
  // One box per triangle: what the BVH builder takes.
  std::vector<Aabb> triangleBounds() const {
    std::vector<Aabb> boxes(triangleCount());
    for (size_t i = 0; i < boxes.size(); ++i)
      for (int k = 0; k < 3; ++k) boxes[i].grow(positions[3 * i + k]);
    return boxes;
  }
};

}  // namespace vkmc
