// The loaded scene as plain data: world-space triangles, materials, cameras. No Vulkan here.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vkmc {

struct Material {
  glm::vec3 baseColor{1.0f};
  float alpha = 1.0f;
  glm::vec3 emission{0.0f};  // emissiveFactor x KHR_materials_emissive_strength, W m^-2 sr^-1
  float metallic = 1.0f;
  float roughness = 1.0f;
  float specular = 1.0f;  // KHR_materials_specular specularFactor
  bool doubleSided = false;
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
// ones, 1:1 (README, Lights): a point or spot light's intensity (cd) is its radiant intensity I in W/sr, a
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

struct Scene {
  std::vector<glm::vec3> positions;   // 3 per triangle, world space, counter-clockwise front faces
  std::vector<glm::vec3> normals;     // 3 per triangle, world space (geometric normal where the file has none)
  std::vector<uint32_t> materialIds;  // 1 per triangle
  std::vector<Material> materials;
  std::vector<Camera> cameras;  // camera instances in node order
  Aabb bounds;
  uint64_t degenerateTriangles = 0;  // zero-area triangles skipped
  uint64_t skippedPrimitives = 0;    // non-triangle primitives skipped
  std::vector<std::string> warnings;
  std::string path;
  bool usesTextures = false;                  // some material references a texture (ignored for now)
  std::vector<PunctualLight> punctualLights;  // KHR_lights_punctual instances in node order
  std::optional<EnvironmentMap> environment;  // not in glTF: the render sets it (--environment, or the default)

  size_t triangleCount() const { return materialIds.size(); }
  // One box per triangle: what the BVH builder takes.
  std::vector<Aabb> triangleBounds() const {
    std::vector<Aabb> boxes(triangleCount());
    for (size_t i = 0; i < boxes.size(); ++i)
      for (int k = 0; k < 3; ++k) boxes[i].grow(positions[3 * i + k]);
    return boxes;
  }
};

}  // namespace vkmc
