// glTF loading through tinygltf, with every accessor bounds-checked before it is read.
#include "scene/gltf_loader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <limits>
#include <map>
#include <optional>
#include <string_view>

#include <sys/stat.h>

#include "../shaders/shared/geometry.h"
#include "error.h"
#include "scene/gltf_accessors.h"
#include "scene/gltf_decompress.h"
#include "scene/gltf_extensions.h"
#include "scene/gltf_lights.h"
#include "scene/gltf_material.h"
#include "scene/gltf_nodes.h"
#include "scene/gltf_skin.h"
#include "scene/gltf_primitive.h"
#include "scene/gltf_textures.h"
#include "scene/tangent_space.h"

namespace vkmc {
namespace {

constexpr size_t kMaxNodeVisits = size_t(1) << 22;

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool inRange(const glm::vec3& v) {
  return finite(v) && glm::all(glm::lessThanEqual(glm::abs(v), glm::vec3(gpu::kMaxSceneCoordinate)));
}
std::string coordinateLimit() {
  char buf[16];
  std::snprintf(buf, sizeof(buf), "%g", double(gpu::kMaxSceneCoordinate));
  return buf;
}

// Appends one corner's attribute to a scene array that stays empty until some primitive has the attribute; the
// corners before it then get the default.
template <class T>
void appendCorner(std::vector<T>& dst, const std::vector<T>& src, uint32_t vertex, const T& fallback, size_t cornersBefore) {
  if (src.empty() && dst.empty()) return;
  if (dst.empty() && cornersBefore > 0) dst.assign(cornersBefore, fallback);
  dst.push_back(src.empty() ? fallback : src[vertex]);
}

// EXT_mesh_gpu_instancing: one local transform per instance (translation, rotation, scale, as a node's), applied
// before the node's world transform; a node without the extension has the one identity instance.
std::vector<glm::mat4> instanceTransforms(const tinygltf::Model& model, const tinygltf::Node& node, uint64_t maxElements) {
  auto ext = node.extensions.find("EXT_mesh_gpu_instancing");
  if (ext == node.extensions.end() || !ext->second.Has("attributes")) return {glm::mat4(1.0f)};
  const tinygltf::Value& attributes = ext->second.Get("attributes");
  std::optional<size_t> count;
  FloatAccessor trs[3];
  const char* names[3] = {"TRANSLATION", "ROTATION", "SCALE"};
  const int types[3] = {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4, TINYGLTF_TYPE_VEC3};
  for (int i = 0; i < 3; ++i) {
    if (!attributes.Has(names[i]) || !attributes.Get(names[i]).IsInt()) continue;
    trs[i] = readFloatAccessor(model, attributes.Get(names[i]).GetNumberAsInt(), names[i], maxElements);
    if (trs[i].type != types[i])
      throw Error(std::string("EXT_mesh_gpu_instancing: ") + names[i] + " accessor has the wrong type");
    if (count && *count != trs[i].count()) throw Error("EXT_mesh_gpu_instancing: instance attributes of different counts");
    count = trs[i].count();
  }
  if (!count) return {glm::mat4(1.0f)};
  std::vector<glm::mat4> out(*count);
  for (size_t k = 0; k < *count; ++k) {
    glm::mat4 m(1.0f);
    if (!trs[0].values.empty()) m = glm::translate(m, glm::vec3(trs[0].values[k]));
    if (!trs[1].values.empty()) {
      glm::vec4 r = trs[1].values[k];
      glm::quat q(r.w, r.x, r.y, r.z);
      if (!(glm::dot(r, r) > 0.0f))
        throw Error("EXT_mesh_gpu_instancing: instance " + std::to_string(k) + " has a zero rotation");
      m *= glm::mat4_cast(glm::normalize(q));
    }
    if (!trs[2].values.empty()) m = glm::scale(m, glm::vec3(trs[2].values[k]));
    out[k] = m;
  }
  return out;
}

// Whether a material needs a tangent frame: a normal texture (its own or its clearcoat's), or an anisotropic lobe
// (KHR_materials_anisotropy with a strength: its direction is given in tangent space).
bool needsTangents(const tinygltf::Model& model, int material) {
  if (material < 0 || material >= static_cast<int>(model.materials.size())) return false;
  const tinygltf::Material& m = model.materials[material];
  auto coat = m.extensions.find("KHR_materials_clearcoat");
  auto aniso = m.extensions.find("KHR_materials_anisotropy");
  bool anisotropic = aniso != m.extensions.end() && aniso->second.Has("anisotropyStrength") &&
                     aniso->second.Get("anisotropyStrength").IsNumber() &&
                     aniso->second.Get("anisotropyStrength").GetNumberAsDouble() > 0.0;
  return m.normalTexture.index >= 0 || (coat != m.extensions.end() && coat->second.Has("clearcoatNormalTexture")) || anisotropic;
}

// The texture coordinates the tangents follow: the normal texture's, else the anisotropy texture's, else the first.
int tangentUvSet(const tinygltf::Material& m) {
  if (m.normalTexture.index >= 0) return m.normalTexture.texCoord;
  auto aniso = m.extensions.find("KHR_materials_anisotropy");
  if (aniso == m.extensions.end() || !aniso->second.Has("anisotropyTexture")) return 0;
  const tinygltf::Value& t = aniso->second.Get("anisotropyTexture");
  return t.IsObject() && t.Has("texCoord") && t.Get("texCoord").IsInt() ? t.Get("texCoord").GetNumberAsInt() : 0;
}

class Flattener {
 public:
  Flattener(const tinygltf::Model& model, Scene& scene, uint64_t maxTriangles)
      : model_(model), scene_(scene), maxTriangles_(maxTriangles), maxElements_(3 * maxTriangles + 3) {
    for (const tinygltf::Mesh& mesh : model.meshes)
      for (const tinygltf::Primitive& prim : mesh.primitives) withTangents_ |= needsTangents(model, prim.material);
    if (!model.skins.empty()) nodeWorld_ = worldTransforms(model);  // the joints' default pose
  }

  void visit(int nodeIndex, const glm::mat4& parent, int depth) {
    if (nodeIndex < 0 || nodeIndex >= static_cast<int>(model_.nodes.size()))
      throw Error("node " + std::to_string(nodeIndex) + " does not exist");
    if (depth > 256) throw Error("node hierarchy deeper than 256 levels (cyclic?)");
    if (++visits_ > kMaxNodeVisits)
      throw Error("scene too big: more than " + std::to_string(kMaxNodeVisits) + " node instances after instancing");
    const tinygltf::Node& node = model_.nodes[nodeIndex];
    glm::mat4 world = parent * localTransform(node);
    if (node.mesh >= 0) addMesh(nodeIndex, world);
    if (node.camera >= 0) addCamera(node.camera, world);
    addNodePunctualLight(model_, nodeIndex, world, scene_);
    for (int child : node.children) visit(child, world, depth + 1);
  }

  uint64_t nonTrianglePrimitives = 0;

 private:
  // The mesh's primitives in local space, read once per mesh (and per node that overrides its morph weights).
  const std::vector<PrimitiveData>& meshData(int nodeIndex) {
    const tinygltf::Node& node = model_.nodes[nodeIndex];
    const tinygltf::Mesh& mesh = model_.meshes[node.mesh];
    auto key = std::make_pair(node.mesh, node.weights.empty() && node.skin < 0 ? -1 : nodeIndex);
    auto cached = meshes_.find(key);
    if (cached != meshes_.end()) return cached->second;
    std::vector<PrimitiveData> data;
    std::vector<glm::mat4> joints;
    if (node.skin >= 0) joints = jointMatrices(model_, node.skin, nodeWorld_);
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const tinygltf::Primitive& prim = mesh.primitives[p];
      if (!isTriangleMode(prim.mode) && !isPointOrLineMode(prim.mode)) {
        data.emplace_back();
        continue;
      }
      PrimitiveRequest request;
      request.weights = node.weights.empty() ? mesh.weights : node.weights;
      request.generateTangents = isTriangleMode(prim.mode) && needsTangents(model_, prim.material);
      if (request.generateTangents) request.tangentUvSet = tangentUvSet(model_.materials[prim.material]);
      request.maxElements = maxElements_;
      request.joints = node.skin >= 0 ? &joints : nullptr;
      try {
        data.push_back(readPrimitive(model_, prim, request));
      } catch (const Error& e) {
        throw Error("mesh " + std::to_string(node.mesh) + ", primitive " + std::to_string(p) + ": " + e.what());
      }
    }
    return meshes_.emplace(key, std::move(data)).first->second;
  }

  void addMesh(int nodeIndex, const glm::mat4& nodeWorld) {
    int meshIndex = model_.nodes[nodeIndex].mesh;
    if (meshIndex >= static_cast<int>(model_.meshes.size())) throw Error("mesh " + std::to_string(meshIndex) + " does not exist");
    const std::vector<PrimitiveData>& data = meshData(nodeIndex);
    const tinygltf::Mesh& mesh = model_.meshes[meshIndex];
    // A skinned mesh is in world space already: its node's transform is not applied (glTF 2.0 section 3.7.3).
    const glm::mat4 placement = model_.nodes[nodeIndex].skin >= 0 ? glm::mat4(1.0f) : nodeWorld;
    for (const glm::mat4& instance : instanceTransforms(model_, model_.nodes[nodeIndex], maxElements_)) {
      glm::mat4 world = placement * instance;
      for (size_t p = 0; p < mesh.primitives.size(); ++p) {
        const tinygltf::Primitive& prim = mesh.primitives[p];
        if (!isTriangleMode(prim.mode) && !isPointOrLineMode(prim.mode)) {
          ++nonTrianglePrimitives;
          continue;
        }
        int materialIndex = prim.material;
        if (materialIndex >= static_cast<int>(model_.materials.size()))
          throw Error("primitive refers to missing material " + std::to_string(materialIndex));
        uint32_t materialId = materialIndex < 0 ? static_cast<uint32_t>(scene_.materials.size() - 1)  // default material
                                                : static_cast<uint32_t>(materialIndex);
        if (isPointOrLineMode(prim.mode))
          addSegments(data[p], world, materialId);
        else
          addPrimitive(data[p], world, materialId);
      }
    }
  }

  void addPrimitive(const PrimitiveData& data, const glm::mat4& world, uint32_t materialId) {
    glm::mat3 linear(world);
    glm::mat3 normalMatrix = glm::transpose(glm::inverse(linear));
    bool flip = glm::determinant(linear) < 0.0f;  // mirroring swaps the winding and the bitangent's handedness
    size_t triangles = data.triangles.size() / 3;
    if (scene_.triangleCount() + 2 * scene_.thinSegments.size() + triangles > maxTriangles_)
      throw Error("scene too big: more than " + std::to_string(maxTriangles_) +
                  " triangles after instancing (what the device's buffers and this machine's memory hold)");
    for (size_t t = 0; t < triangles; ++t) {
      uint32_t idx[3] = {data.triangles[3 * t], data.triangles[3 * t + 1], data.triangles[3 * t + 2]};
      if (flip) std::swap(idx[1], idx[2]);
      glm::vec3 p[3], n[3];
      for (int k = 0; k < 3; ++k) {
        glm::vec3 local = data.positions[idx[k]];
        if (!finite(local)) throw Error("vertex " + std::to_string(idx[k]) + " has a NaN or infinite position");
        p[k] = glm::vec3(world * glm::vec4(local, 1.0f));
        if (!finite(p[k])) throw Error("vertex " + std::to_string(idx[k]) + " is not finite after its node transform");
        if (!inRange(p[k]))
          throw Error("vertex " + std::to_string(idx[k]) + " lies beyond +-" + coordinateLimit() +
                      " after its node transform (float ray tests overflow there; scale the scene down)");
      }
      // Degenerate exactly when the GPU's own normal and area would be (the same shared function): its
      // scaled cross product must have a normal length and its area must be a normal float. Huge triangles
      // (a ground plane of 3e9) are not degenerate; a plain float cross would overflow for them.
      glm::vec4 c = gpu::scaledTriangleCross(p[0], p[1], p[2]);
      float area = 0.5f * glm::length(glm::vec3(c)) * c.w * c.w;
      if (!(glm::dot(glm::vec3(c), glm::vec3(c)) >= std::numeric_limits<float>::min()) ||
          !(area >= std::numeric_limits<float>::min()) || !std::isfinite(area)) {
        ++scene_.degenerateTriangles;
        continue;
      }
      glm::vec3 geometric = glm::normalize(glm::vec3(c));
      for (int k = 0; k < 3; ++k) {
        glm::vec3 nk = data.normals.empty() ? geometric : normalMatrix * data.normals[idx[k]];
        float nl = glm::length(nk);
        n[k] = (nl > 0.0f && std::isfinite(nl)) ? nk / nl : geometric;
        size_t corners = scene_.positions.size();
        appendCorner(scene_.uv0, data.uv0, idx[k], glm::vec2(0.0f), corners);
        appendCorner(scene_.uv1, data.uv1, idx[k], glm::vec2(0.0f), corners);
        appendCorner(scene_.colors, data.colors, idx[k], glm::vec4(1.0f), corners);
        // The corner's own tangent when generated per corner (a flip swapped corners 1 and 2).
        size_t corner = 3 * t + (flip && k > 0 ? 3 - k : k);
        if (withTangents_)
          scene_.tangents.push_back(worldTangent(data, data.tangentsPerCorner ? corner : idx[k], linear, n[k], flip));
        scene_.positions.push_back(p[k]);
        scene_.normals.push_back(n[k]);
        scene_.bounds.grow(p[k]);
      }
      scene_.materialIds.push_back(materialId);
    }
  }

  // Points and lines in world space; each becomes a two-triangle ribbon at render time, counted here.
  void addSegments(const PrimitiveData& data, const glm::mat4& world, uint32_t materialId) {
    size_t segments = data.segments.size() / 2;
    if (scene_.triangleCount() + 2 * (scene_.thinSegments.size() + segments) > maxTriangles_)
      throw Error("scene too big: more than " + std::to_string(maxTriangles_) +
                  " triangles after instancing, points and lines counted as 2 each");
    for (size_t s = 0; s < segments; ++s) {
      ThinSegment seg;
      glm::vec3* ends[2] = {&seg.a, &seg.b};
      glm::vec4* colors[2] = {&seg.colorA, &seg.colorB};
      for (int k = 0; k < 2; ++k) {
        uint32_t v = data.segments[2 * s + k];
        glm::vec3 local = data.positions[v];
        if (!finite(local)) throw Error("vertex " + std::to_string(v) + " has a NaN or infinite position");
        *ends[k] = glm::vec3(world * glm::vec4(local, 1.0f));
        if (!finite(*ends[k]) || !inRange(*ends[k]))
          throw Error("vertex " + std::to_string(v) + " lies beyond +-" + coordinateLimit() + " after its node transform");
        if (!data.colors.empty()) *colors[k] = data.colors[v];
        scene_.bounds.grow(*ends[k]);
      }
      seg.material = materialId;
      scene_.thinSegments.push_back(seg);
    }
  }

  // The tangent by the node's linear part, Gram-Schmidt against the corner's world normal.
  // `index`: the vertex, or the corner for tangents generated per corner.
  static glm::vec4 worldTangent(const PrimitiveData& data, size_t index, const glm::mat3& linear, const glm::vec3& n, bool flip) {
    glm::vec4 local = data.tangents.empty() ? glm::vec4(0.0f, 0.0f, 0.0f, 1.0f) : data.tangents[index];
    glm::vec3 t = linear * glm::vec3(local);
    t -= n * glm::dot(n, t);
    float tl = glm::length(t);
    t = (tl > 1e-20f && std::isfinite(tl)) ? t / tl : anyPerpendicular(n);
    float w = (local.w < 0.0f ? -1.0f : 1.0f) * (flip ? -1.0f : 1.0f);
    return glm::vec4(t, w);
  }

  void addCamera(int cameraIndex, const glm::mat4& world) {
    if (cameraIndex >= static_cast<int>(model_.cameras.size()))
      throw Error("camera " + std::to_string(cameraIndex) + " does not exist");
    const tinygltf::Camera& c = model_.cameras[cameraIndex];
    Camera cam;
    cam.name = c.name;
    std::string name = "camera " + std::to_string(cameraIndex);
    cam.position = glm::vec3(world[3]);
    glm::dvec3 forward = -glm::dvec3(glm::vec3(world[2])), up = glm::dvec3(glm::vec3(world[1]));
    // A basis needs two independent axes: parallel or zero Y and Z columns would give NaN everywhere.
    double sine = glm::length(glm::cross(forward, up)) / (glm::length(forward) * glm::length(up));
    if (!(sine > 1e-6)) throw Error(name + ": its node transform's Y and Z axes are parallel or zero (no view basis)");
    cam.forward = glm::vec3(glm::normalize(forward));
    cam.up = glm::vec3(glm::normalize(up));
    if (!inRange(cam.position)) throw Error(name + ": position beyond +-" + coordinateLimit() + " or not finite");
    if (c.type == "orthographic") {
      cam.kind = CameraKind::Orthographic;
      cam.xmag = static_cast<float>(c.orthographic.xmag);
      cam.ymag = static_cast<float>(c.orthographic.ymag);
      if (!(cam.xmag > 0.0f && cam.xmag <= gpu::kMaxSceneCoordinate) ||
          !(cam.ymag > 0.0f && cam.ymag <= gpu::kMaxSceneCoordinate))
        throw Error(name + ": orthographic magnification not a positive number within " + coordinateLimit());
      cam.aspectRatio = cam.xmag / cam.ymag;
    } else {
      cam.yfov = static_cast<float>(c.perspective.yfov);
      if (!(cam.yfov > 0.0f && cam.yfov < 3.14f)) throw Error("perspective camera with yfov outside (0, pi)");
      if (c.perspective.aspectRatio != 0.0 && !(c.perspective.aspectRatio > 0.0 && c.perspective.aspectRatio < 1e30))
        throw Error(name + ": aspectRatio " + std::to_string(c.perspective.aspectRatio) + " is not a positive number");
      if (c.perspective.aspectRatio > 0.0) cam.aspectRatio = static_cast<float>(c.perspective.aspectRatio);
    }
    if (!finite(cam.position) || !finite(cam.forward) || !finite(cam.up)) throw Error("camera transform is not finite");
    scene_.cameras.push_back(cam);
  }

  const tinygltf::Model& model_;
  Scene& scene_;
  uint64_t maxTriangles_, maxElements_;
  bool withTangents_ = false;  // some primitive's material needs tangents (needsTangents)
  std::map<std::pair<int, int>, std::vector<PrimitiveData>> meshes_;
  std::vector<glm::mat4> nodeWorld_;  // every node's world transform, for skins only
  size_t visits_ = 0;
};

// Triangles the node graph instances, from accessor counts alone and memoized per node (linear in the nodes
// however exponential the instancing), so that an instancing bomb is refused before anything is allocated for it;
// flattening checks again as it reads. Invalid references and cycles are left to flattening, which names them.
class InstanceCounter {
 public:
  explicit InstanceCounter(const tinygltf::Model& model) : model_(model), memo_(model.nodes.size(), kUnknown) {}

  uint64_t trianglesUnder(int nodeIndex, int depth = 0) {
    if (nodeIndex < 0 || nodeIndex >= static_cast<int>(model_.nodes.size()) || depth > 256) return 0;
    uint64_t& memo = memo_[nodeIndex];
    if (memo == kVisiting) return 0;  // a cycle
    if (memo != kUnknown) return memo;
    memo = kVisiting;
    const tinygltf::Node& node = model_.nodes[nodeIndex];
    uint64_t total = 0;
    if (node.mesh >= 0 && node.mesh < static_cast<int>(model_.meshes.size())) {
      uint64_t meshTriangles = 0;
      for (const tinygltf::Primitive& prim : model_.meshes[node.mesh].primitives) {
        bool lines = isPointOrLineMode(prim.mode);
        if (!isTriangleMode(prim.mode) && !lines) continue;
        auto pos = prim.attributes.find("POSITION");
        int accessor = prim.indices >= 0 ? prim.indices : pos == prim.attributes.end() ? -1 : pos->second;
        if (accessor >= 0 && accessor < static_cast<int>(model_.accessors.size())) {
          size_t elements = model_.accessors[accessor].count;
          meshTriangles = saturatingAdd(meshTriangles, lines ? saturatingMultiply(2, segmentCount(prim.mode, elements))
                                                             : uint64_t(triangleCount(prim.mode, elements)));
        }
      }
      total = saturatingMultiply(meshTriangles, instanceCount(node));
    }
    for (int child : node.children) total = saturatingAdd(total, trianglesUnder(child, depth + 1));
    memo_[nodeIndex] = total;
    return total;
  }

  static uint64_t saturatingAdd(uint64_t a, uint64_t b) { return std::min(a + std::min(b, kSaturated), kSaturated); }
  static uint64_t saturatingMultiply(uint64_t a, uint64_t b) {
    return a == 0 || b == 0 ? 0 : b > kSaturated / a ? kSaturated : std::min(a * b, kSaturated);
  }

 private:
  // EXT_mesh_gpu_instancing's instance count (its accessors' largest count), 1 without the extension.
  uint64_t instanceCount(const tinygltf::Node& node) const {
    auto ext = node.extensions.find("EXT_mesh_gpu_instancing");
    if (ext == node.extensions.end() || !ext->second.Has("attributes")) return 1;
    const tinygltf::Value& attributes = ext->second.Get("attributes");
    uint64_t count = 0;
    for (const char* name : {"TRANSLATION", "ROTATION", "SCALE"})
      if (attributes.Has(name) && attributes.Get(name).IsInt()) {
        int a = attributes.Get(name).GetNumberAsInt();
        if (a >= 0 && a < static_cast<int>(model_.accessors.size())) count = std::max<uint64_t>(count, model_.accessors[a].count);
      }
    return count == 0 ? 1 : count;
  }

  static constexpr uint64_t kSaturated = uint64_t(1) << 62;
  static constexpr uint64_t kUnknown = ~uint64_t(0), kVisiting = kUnknown - 1;
  const tinygltf::Model& model_;
  std::vector<uint64_t> memo_;
};

// tinygltf's file access, made safe for untrusted URIs: no blocking opens (its FileExists opens the file, which
// waits forever on a FIFO), only regular files, no file larger than `maxBytes`, nothing written.
struct SafeFs {
  uint64_t maxBytes = 0;
};

bool safeFileExists(const std::string& path, void*) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0;
}
std::string noExpansion(const std::string& path, void*) { return path; }
bool safeReadWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  try {
    *out = readRegularFile(path, static_cast<SafeFs*>(user)->maxBytes, "URI file");
    return true;
  } catch (const Error& e) {
    if (err) *err = e.what();
    return false;
  }
}
bool noWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) { return false; }

// Errors in files that use a geometry-compression extension name it, so users know where to look.
std::string usedCompressionNote(const std::vector<std::string>& used, const std::vector<std::string>& required) {
  std::string names;
  for (const char* name : {"KHR_draco_mesh_compression", "EXT_meshopt_compression", "KHR_mesh_quantization"})
    if (std::find(used.begin(), used.end(), name) != used.end() ||
        std::find(required.begin(), required.end(), name) != required.end())
      names += (names.empty() ? "" : ", ") + std::string(name);
  return names;
}
std::string noteUnlessNamed(const std::string& message, const std::string& names) {
  for (const char* name : {"KHR_draco_mesh_compression", "EXT_meshopt_compression", "KHR_mesh_quantization"})
    if (message.find(name) != std::string::npos) return "";
  return names.empty() ? "" : " (the file uses " + names + ")";
}

Scene flattenModel(const tinygltf::Model& model, const std::string& path, const LoadLimits& limits,
                   const std::vector<std::string>& extensionWarnings);

}  // namespace

namespace {

// As tinygltf decodes a uri (its urldecode): %XX escapes, and '+' as a space.
std::string percentDecoded(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
      continue;
    }
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

}  // namespace

std::vector<std::string> gltfInputFiles(const std::string& path, const LoadLimits& limits) {
  namespace fs = std::filesystem;
  std::vector<std::string> files = {path};
  try {
    std::vector<unsigned char> bytes = readRegularFile(path, limits.input.maxSceneFileBytes, "scene");
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    std::string_view json =
        ext == ".glb" ? glbJsonChunk(bytes) : std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    // Where tinygltf reads it: its base folder and the uri joined as strings (an absolute uri stays inside the
    // folder), or where that file is missing, the uri relative to the working folder.
    const std::string base = fs::path(path).parent_path().empty() ? "." : fs::path(path).parent_path().string();
    for (const std::string& uri : scanGltfJson(json, limits.input).externalUris) {
      const std::string decoded = percentDecoded(uri), beside = fs::path(base + "/" + decoded).lexically_normal().string();
      std::error_code ec;
      files.push_back(fs::exists(beside, ec) ? beside : decoded);
    }
  } catch (const Error&) {
    // The load itself names what is wrong with the file.
  }
  return files;
}

Scene loadGltf(const std::string& path, const LoadLimits& limits) {
  namespace fs = std::filesystem;
  std::vector<unsigned char> bytes = readRegularFile(path, limits.input.maxSceneFileBytes, "scene");
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::string baseDir = fs::path(path).parent_path().string();
  return loadGltfFromMemory(bytes, ext == ".glb", baseDir.empty() ? "." : baseDir, path, limits);
}

Scene loadGltfFromMemory(const std::vector<unsigned char>& bytes, bool binary, const std::string& baseDir,
                         const std::string& path, const LoadLimits& limits) {
  tinygltf::Model model;
  std::vector<std::string> extensionWarnings;
  std::string compressionNote;
  ImageDecoder imageDecoder;
  imageDecoder.limits.maxTotalTexels = limits.maxTextureTexels;
  imageDecoder.limits.maxDimension = std::min(imageDecoder.limits.maxDimension, limits.maxTextureSide);
  try {
    std::string_view json =
        binary ? glbJsonChunk(bytes) : std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    GltfJsonFacts facts = scanGltfJson(json, limits.input);
    extensionWarnings = checkExtensions(facts.extensionsUsed, facts.extensionsRequired);
    compressionNote = usedCompressionNote(facts.extensionsUsed, facts.extensionsRequired);
    // tinygltf refuses parts of valid Draco and meshopt files (gltf_decompress.h says which).
    std::string rewritten = compressionNote.empty() ? "" : prepareCompressedJson(json);
    std::vector<unsigned char> rewrittenGlb;
    if (!rewritten.empty()) {
      if (binary) {
        rewrittenGlb = replaceGlbJson(bytes, rewritten);
        json = glbJsonChunk(rewrittenGlb);
      } else {
        json = rewritten;
      }
    }
    const std::vector<unsigned char>& glb = rewrittenGlb.empty() ? bytes : rewrittenGlb;
    uint64_t largestBuffer = facts.largestBuffer;
    // Buffers must match their declared byteLength exactly (tinygltf checks after reading); an image file
    // beyond the largest buffer or 256 MiB is refused before it is read, its decoded size by the image decoder.
    SafeFs safeFs{std::min(limits.input.maxExternalFileBytes, std::max<uint64_t>(largestBuffer, uint64_t(1) << 28))};
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(decodeGltfImage, &imageDecoder);
    loader.SetFsCallbacks({safeFileExists, noExpansion, safeReadWholeFile, noWrite, &safeFs});
    std::string err, warn;
    bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, glb.data(), static_cast<unsigned>(glb.size()), baseDir)
                     : loader.LoadASCIIFromString(&model, &err, &warn, json.data(), static_cast<unsigned>(json.size()), baseDir);
    if (!ok) throw Error(err.empty() ? "unknown error" : err);
    decompressModel(model, DecompressLimits{limits.input.maxExternalFileBytes, limits.maxTriangles});
  } catch (const Error& e) {
    std::string reason = e.what() + noteUnlessNamed(e.what(), compressionNote);
    while (!reason.empty() && (reason.back() == '\n' || reason.back() == ' ')) reason.pop_back();
    for (char& c : reason)
      if (c == '\n') c = ';';
    throw Error("cannot load '" + path + "': " + reason);
  }

  // Images the decoder could not read are warned about with the extensions (their textures are ignored).
  extensionWarnings.insert(extensionWarnings.end(), imageDecoder.failures.begin(), imageDecoder.failures.end());
  try {
    return flattenModel(model, path, limits, extensionWarnings);
  } catch (const Error& e) {
    throw Error(e.what() + noteUnlessNamed(e.what(), compressionNote));
  }
}

namespace {

// The scene's extras.vkmc_world (scene.h's World); anything else there is named in a warning and the studio lights it.
World declaredWorld(const tinygltf::Value& extras, std::vector<std::string>& warnings) {
  if (!extras.IsObject() || !extras.Has("vkmc_world")) return World::Studio;
  const tinygltf::Value& v = extras.Get("vkmc_world");
  const std::string name = v.IsString() ? v.Get<std::string>() : "";
  if (name == "lights-only") return World::LightsOnly;
  if (name == "white") return World::White;
  if (name != "studio")
    warnings.push_back("the scene's extras.vkmc_world is not studio, lights-only or white: the studio environment lights it");
  return World::Studio;
}

Scene flattenModel(const tinygltf::Model& model, const std::string& path, const LoadLimits& limits,
                   const std::vector<std::string>& extensionWarnings) {
  Scene scene;
  scene.path = path;
  scene.textures = convertTextures(model, scene.warnings);
  std::vector<Texture> baked;  // after the file's own, so that no material can refer to them by index
  for (size_t i = 0; i < model.materials.size(); ++i)
    scene.materials.push_back(convertMaterial(model.materials[i], static_cast<int>(i), scene.textures, baked, scene.warnings));
  scene.textures.insert(scene.textures.end(), std::make_move_iterator(baked.begin()), std::make_move_iterator(baked.end()));
  Material fallback;  // glTF default material: white, fully metallic and rough (Lambert here)
  scene.materials.push_back(fallback);
  scene.warnings.insert(scene.warnings.end(), extensionWarnings.begin(), extensionWarnings.end());

  std::vector<int> roots;
  scene.world = World::Studio;
  if (!model.scenes.empty()) {
    int sceneIndex =
        model.defaultScene >= 0 && model.defaultScene < static_cast<int>(model.scenes.size()) ? model.defaultScene : 0;
    roots = model.scenes[sceneIndex].nodes;
    scene.world = declaredWorld(model.scenes[sceneIndex].extras, scene.warnings);
  } else {
    std::vector<bool> isChild(model.nodes.size(), false);
    for (const auto& n : model.nodes)
      for (int c : n.children)
        if (c >= 0 && c < static_cast<int>(isChild.size())) isChild[c] = true;
    for (size_t i = 0; i < model.nodes.size(); ++i)
      if (!isChild[i]) roots.push_back(static_cast<int>(i));
  }
  InstanceCounter counter(model);
  uint64_t instanced = 0;
  for (int root : roots) instanced = InstanceCounter::saturatingAdd(instanced, counter.trianglesUnder(root));
  if (instanced > limits.maxTriangles)
    throw Error("scene too big: more than " + std::to_string(limits.maxTriangles) + " triangles after instancing (" +
                std::to_string(instanced) + " instanced; the limit is what the device's buffers and this machine's memory hold)");
  Flattener flattener(model, scene, limits.maxTriangles);
  for (int root : roots) flattener.visit(root, glm::mat4(1.0f), 0);
  scene.skippedPrimitives = flattener.nonTrianglePrimitives;
  if (scene.skippedPrimitives > 0)
    scene.warnings.push_back(std::to_string(scene.skippedPrimitives) + " primitive(s) of an unknown mode skipped");
  if (scene.degenerateTriangles > 0)
    scene.warnings.push_back(std::to_string(scene.degenerateTriangles) + " zero-area triangle(s) skipped");
  if (scene.triangleCount() == 0)
    throw Error("scene '" + path + "' has no triangles" +
                std::string(scene.thinSegments.empty() ? "" : " (points and lines alone are not drawn)"));
  return scene;
}

}  // namespace

}  // namespace vkmc
