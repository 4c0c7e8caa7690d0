// glTF loading through tinygltf, with every accessor bounds-checked before it is read.
#include "scene/gltf_loader.h"

#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <limits>
#include <string_view>

#include <sys/stat.h>

#include "../shaders/shared/geometry.h"
#include "error.h"
#include "scene/gltf_extensions.h"
#include "scene/gltf_lights.h"

namespace vkmc {
namespace {

// Textures are not used yet; skipping the decode keeps loading fast (DamagedHelmet has 5 large JPEGs).
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

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

struct AccessorView {
  const unsigned char* data = nullptr;
  size_t count = 0;
  size_t stride = 0;
  int componentType = 0;
  int type = 0;
};

size_t componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

size_t componentCount(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    default: return 0;
  }
}

AccessorView viewAccessor(const tinygltf::Model& model, int index, const char* what) {
  std::string name = std::string(what) + " accessor " + std::to_string(index);
  if (index < 0 || index >= static_cast<int>(model.accessors.size())) throw Error(name + " does not exist");
  const tinygltf::Accessor& a = model.accessors[index];
  if (a.sparse.isSparse) throw Error(name + " is sparse (not supported)");
  size_t elemSize = componentSize(a.componentType) * componentCount(a.type);
  if (elemSize == 0) throw Error(name + " has an invalid type");
  if (a.bufferView < 0 || a.bufferView >= static_cast<int>(model.bufferViews.size()))
    throw Error(name + " has no valid buffer view");
  const tinygltf::BufferView& v = model.bufferViews[a.bufferView];
  if (v.buffer < 0 || v.buffer >= static_cast<int>(model.buffers.size())) throw Error(name + " refers to a missing buffer");
  const tinygltf::Buffer& b = model.buffers[v.buffer];
  size_t stride = v.byteStride ? v.byteStride : elemSize;
  if (stride < elemSize) throw Error(name + " has a byte stride smaller than its element");
  // Every bound by subtraction from a known size: sums of file-supplied offsets and counts can wrap.
  if (v.byteOffset > b.data.size() || v.byteLength > b.data.size() - v.byteOffset)
    throw Error(name + ": buffer view runs past the end of its buffer");
  if (a.count > 0 && (a.byteOffset > v.byteLength || elemSize > v.byteLength - a.byteOffset ||
                      (a.count - 1) > (v.byteLength - a.byteOffset - elemSize) / stride))
    throw Error(name + ": accessor runs past the end of its buffer view");
  AccessorView out;
  out.data = b.data.data() + v.byteOffset + a.byteOffset;
  out.count = a.count;
  out.stride = stride;
  out.componentType = a.componentType;
  out.type = a.type;
  return out;
}

// Triangle lists, strips and fans (glTF 2.0 section 3.7.2.1): how many triangles a primitive of `elements`
// vertices makes, and which element is corner k of triangle t (strips alternate their winding so every
// triangle keeps the first one's orientation).
bool isTriangleMode(int mode) {
  return mode == -1 || mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
         mode == TINYGLTF_MODE_TRIANGLE_FAN;
}
size_t triangleCount(int mode, size_t elements) {
  if (mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN) return elements >= 3 ? elements - 2 : 0;
  return elements / 3;
}
size_t cornerElement(int mode, size_t t, int k) {
  if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) return k == 0 ? t : k == 1 ? t + 1 + t % 2 : t + 2 - t % 2;
  if (mode == TINYGLTF_MODE_TRIANGLE_FAN) return k == 0 ? t + 1 : k == 1 ? t + 2 : 0;
  return 3 * t + k;
}

glm::vec3 readVec3(const AccessorView& v, size_t i) {
  glm::vec3 r;
  std::memcpy(&r, v.data + i * v.stride, sizeof(r));
  return r;
}

uint32_t readIndex(const AccessorView& v, size_t i) {
  const unsigned char* p = v.data + i * v.stride;
  switch (v.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t x;
      std::memcpy(&x, p, 2);
      return x;
    }
    default: {
      uint32_t x;
      std::memcpy(&x, p, 4);
      return x;
    }
  }
}

glm::mat4 localTransform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = static_cast<float>(node.matrix[i]);
    return m;
  }
  glm::mat4 m(1.0f);
  if (node.translation.size() == 3)
    m = glm::translate(m, glm::vec3(node.translation[0], node.translation[1], node.translation[2]));
  if (node.rotation.size() == 4) {
    glm::quat q(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]), static_cast<float>(node.rotation[1]),
                static_cast<float>(node.rotation[2]));
    m *= glm::mat4_cast(glm::normalize(q));
  }
  if (node.scale.size() == 3) m = glm::scale(m, glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
  return m;
}

double extensionNumber(const tinygltf::ExtensionMap& ext, const char* extension, const char* key, double fallback) {
  auto it = ext.find(extension);
  if (it == ext.end() || !it->second.Has(key)) return fallback;
  const tinygltf::Value& v = it->second.Get(key);
  return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
}

Material convertMaterial(const tinygltf::Material& m, int index, bool& usesTextures, std::vector<std::string>& warnings) {
  Material out;
  const auto& pbr = m.pbrMetallicRoughness;
  std::string name = "material " + std::to_string(index);
  if (pbr.baseColorFactor.size() == 4) {
    out.baseColor = glm::vec3(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]);
    out.alpha = static_cast<float>(pbr.baseColorFactor[3]);
  }
  out.metallic = static_cast<float>(pbr.metallicFactor);
  out.roughness = static_cast<float>(pbr.roughnessFactor);
  if (m.emissiveFactor.size() == 3) out.emission = glm::vec3(m.emissiveFactor[0], m.emissiveFactor[1], m.emissiveFactor[2]);
  double strength = extensionNumber(m.extensions, "KHR_materials_emissive_strength", "emissiveStrength", 1.0);
  out.specular = static_cast<float>(extensionNumber(m.extensions, "KHR_materials_specular", "specularFactor", 1.0));
  if (auto spec = m.extensions.find("KHR_materials_specular"); spec != m.extensions.end()) {
    // specularFactor is used; a specular colour or texture is not yet (the materials issue).
    const tinygltf::Value& v = spec->second;
    bool colour = false;
    if (v.Has("specularColorFactor") && v.Get("specularColorFactor").IsArray())
      for (int c = 0; c < 3 && c < int(v.Get("specularColorFactor").ArrayLen()); ++c)
        colour |=
            v.Get("specularColorFactor").Get(c).IsNumber() && v.Get("specularColorFactor").Get(c).GetNumberAsDouble() != 1.0;
    if (colour || v.Has("specularTexture") || v.Has("specularColorTexture"))
      warnings.push_back(name +
                         ": KHR_materials_specular's specularColorFactor and textures are ignored (specularFactor is used)");
  }
  if (!std::isfinite(strength) || strength < 0.0) throw Error(name + ": emissiveStrength is not a finite non-negative number");
  out.emission *= static_cast<float>(strength);
  out.doubleSided = m.doubleSided;
  if (!finite(out.baseColor) || !finite(out.emission) || !std::isfinite(out.alpha) || !std::isfinite(out.metallic) ||
      !std::isfinite(out.roughness) || !std::isfinite(out.specular))
    throw Error(name + ": a factor is NaN or infinite");
  if (glm::any(glm::lessThan(out.emission, glm::vec3(0.0f))) || glm::any(glm::lessThan(out.baseColor, glm::vec3(0.0f))))
    throw Error(name + ": negative color or emission factor");
  usesTextures = usesTextures || pbr.baseColorTexture.index >= 0 || pbr.metallicRoughnessTexture.index >= 0 ||
                 m.normalTexture.index >= 0 || m.emissiveTexture.index >= 0 || m.occlusionTexture.index >= 0;
  return out;
}

class Flattener {
 public:
  Flattener(const tinygltf::Model& model, Scene& scene, uint64_t maxTriangles)
      : model_(model), scene_(scene), maxTriangles_(maxTriangles) {}

  void visit(int nodeIndex, const glm::mat4& parent, int depth) {
    if (nodeIndex < 0 || nodeIndex >= static_cast<int>(model_.nodes.size()))
      throw Error("node " + std::to_string(nodeIndex) + " does not exist");
    if (depth > 256) throw Error("node hierarchy deeper than 256 levels (cyclic?)");
    if (++visits_ > kMaxNodeVisits)
      throw Error("scene too big: more than " + std::to_string(kMaxNodeVisits) + " node instances after instancing");
    const tinygltf::Node& node = model_.nodes[nodeIndex];
    glm::mat4 world = parent * localTransform(node);
    if (node.mesh >= 0) addMesh(node.mesh, world);
    if (node.camera >= 0) addCamera(node.camera, world);
    addNodePunctualLight(model_, nodeIndex, world, scene_);
    for (int child : node.children) visit(child, world, depth + 1);
  }

  uint64_t nonTrianglePrimitives = 0;

 private:
  void addMesh(int meshIndex, const glm::mat4& world) {
    if (meshIndex >= static_cast<int>(model_.meshes.size())) throw Error("mesh " + std::to_string(meshIndex) + " does not exist");
    glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(world)));
    bool flip = glm::determinant(glm::mat3(world)) < 0.0f;  // mirroring swaps the winding
    for (const tinygltf::Primitive& prim : model_.meshes[meshIndex].primitives) {
      if (!isTriangleMode(prim.mode)) {
        ++nonTrianglePrimitives;
        continue;
      }
      auto pos = prim.attributes.find("POSITION");
      if (pos == prim.attributes.end()) throw Error("mesh " + std::to_string(meshIndex) + ": primitive without POSITION");
      AccessorView positions = viewAccessor(model_, pos->second, "POSITION");
      if (positions.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || positions.type != TINYGLTF_TYPE_VEC3)
        throw Error("POSITION accessor " + std::to_string(pos->second) + " is not float VEC3");
      std::optional<AccessorView> normals;
      if (auto n = prim.attributes.find("NORMAL"); n != prim.attributes.end()) {
        normals = viewAccessor(model_, n->second, "NORMAL");
        if (normals->componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || normals->type != TINYGLTF_TYPE_VEC3 ||
            normals->count != positions.count)
          normals.reset();
      }
      std::optional<AccessorView> indices;
      if (prim.indices >= 0) {
        indices = viewAccessor(model_, prim.indices, "index");
        int ct = indices->componentType;
        if (indices->type != TINYGLTF_TYPE_SCALAR ||
            (ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
             ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
          throw Error("index accessor " + std::to_string(prim.indices) + " is not an unsigned integer scalar");
      }
      int materialIndex = prim.material;
      if (materialIndex >= static_cast<int>(model_.materials.size()))
        throw Error("primitive refers to missing material " + std::to_string(materialIndex));
      uint32_t materialId = materialIndex < 0 ? static_cast<uint32_t>(scene_.materials.size() - 1)  // default material
                                              : static_cast<uint32_t>(materialIndex);
      size_t triangles = triangleCount(prim.mode, indices ? indices->count : positions.count);
      if (scene_.triangleCount() + triangles > maxTriangles_)
        throw Error("scene too big: more than " + std::to_string(maxTriangles_) +
                    " triangles after instancing (what the device's buffers and this machine's memory hold)");
      for (size_t t = 0; t < triangles; ++t) {
        uint32_t idx[3];
        for (int k = 0; k < 3; ++k) {
          size_t element = cornerElement(prim.mode, t, k);
          size_t vertex = indices ? readIndex(*indices, element) : element;
          if (vertex >= positions.count)
            throw Error("index " + std::to_string(vertex) + " out of range (" + std::to_string(positions.count) + " vertices)");
          idx[k] = static_cast<uint32_t>(vertex);
        }
        if (flip) std::swap(idx[1], idx[2]);
        glm::vec3 p[3], n[3];
        for (int k = 0; k < 3; ++k) {
          glm::vec3 local = readVec3(positions, idx[k]);
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
          glm::vec3 nk = normals ? normalMatrix * readVec3(*normals, idx[k]) : geometric;
          float nl = glm::length(nk);
          n[k] = (nl > 0.0f && std::isfinite(nl)) ? nk / nl : geometric;
          scene_.positions.push_back(p[k]);
          scene_.normals.push_back(n[k]);
          scene_.bounds.grow(p[k]);
        }
        scene_.materialIds.push_back(materialId);
      }
    }
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
  uint64_t maxTriangles_;
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
    if (node.mesh >= 0 && node.mesh < static_cast<int>(model_.meshes.size()))
      for (const tinygltf::Primitive& prim : model_.meshes[node.mesh].primitives) {
        if (!isTriangleMode(prim.mode)) continue;
        auto pos = prim.attributes.find("POSITION");
        int accessor = prim.indices >= 0 ? prim.indices : pos == prim.attributes.end() ? -1 : pos->second;
        if (accessor >= 0 && accessor < static_cast<int>(model_.accessors.size()))
          total = saturatingAdd(total, triangleCount(prim.mode, model_.accessors[accessor].count));
      }
    for (int child : node.children) total = saturatingAdd(total, trianglesUnder(child, depth + 1));
    memo_[nodeIndex] = total;
    return total;
  }

  static uint64_t saturatingAdd(uint64_t a, uint64_t b) { return std::min(a + std::min(b, kSaturated), kSaturated); }

 private:
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

}  // namespace

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
  try {
    std::string_view json =
        binary ? glbJsonChunk(bytes) : std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    GltfJsonFacts facts = scanGltfJson(json, limits.input);
    extensionWarnings = checkExtensions(facts.extensionsUsed, facts.extensionsRequired);
    uint64_t largestBuffer = facts.largestBuffer;
    // Buffers must match their declared byteLength exactly (tinygltf checks after reading); images are not
    // decoded yet, so anything beyond the largest buffer or 256 MiB is refused before it is read.
    SafeFs safeFs{std::min(limits.input.maxExternalFileBytes, std::max<uint64_t>(largestBuffer, uint64_t(1) << 28))};
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skipImage, nullptr);
    loader.SetFsCallbacks({safeFileExists, noExpansion, safeReadWholeFile, noWrite, &safeFs});
    std::string err, warn;
    bool ok = binary
                  ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), static_cast<unsigned>(bytes.size()), baseDir)
                  : loader.LoadASCIIFromString(&model, &err, &warn, json.data(), static_cast<unsigned>(json.size()), baseDir);
    if (!ok) throw Error(err.empty() ? "unknown error" : err);
  } catch (const Error& e) {
    std::string reason = e.what();
    while (!reason.empty() && (reason.back() == '\n' || reason.back() == ' ')) reason.pop_back();
    for (char& c : reason)
      if (c == '\n') c = ';';
    throw Error("cannot load '" + path + "': " + reason);
  }

  Scene scene;
  scene.path = path;
  bool usesTextures = false;
  for (size_t i = 0; i < model.materials.size(); ++i)
    scene.materials.push_back(convertMaterial(model.materials[i], static_cast<int>(i), usesTextures, scene.warnings));
  Material fallback;  // glTF default material: white, fully metallic and rough (Lambert here)
  scene.materials.push_back(fallback);
  if (usesTextures) scene.warnings.push_back("textures are not supported yet and were ignored");
  scene.usesTextures = usesTextures;
  scene.warnings.insert(scene.warnings.end(), extensionWarnings.begin(), extensionWarnings.end());

  std::vector<int> roots;
  if (!model.scenes.empty()) {
    int sceneIndex =
        model.defaultScene >= 0 && model.defaultScene < static_cast<int>(model.scenes.size()) ? model.defaultScene : 0;
    roots = model.scenes[sceneIndex].nodes;
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
    scene.warnings.push_back(std::to_string(scene.skippedPrimitives) + " non-triangle primitive(s) skipped");
  if (scene.degenerateTriangles > 0)
    scene.warnings.push_back(std::to_string(scene.degenerateTriangles) + " zero-area triangle(s) skipped");
  if (scene.triangleCount() == 0) throw Error("scene '" + path + "' has no triangles");
  return scene;
}

}  // namespace vkmc
