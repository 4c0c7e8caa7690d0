// A primitive's vertex attributes, morph targets and topology, read through the bounds-checked accessors.
#include "scene/gltf_primitive.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "error.h"
#include "scene/gltf_accessors.h"
#include "scene/gltf_skin.h"
#include "scene/tangent_space.h"

namespace vkmc {
namespace {

// Which element is corner k of triangle t (glTF 2.0 section 3.7.2.1; strips alternate their winding so every
// triangle keeps the first one's orientation).
size_t cornerElement(int mode, size_t t, int k) {
  if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) return k == 0 ? t : k == 1 ? t + 1 + t % 2 : t + 2 - t % 2;
  if (mode == TINYGLTF_MODE_TRIANGLE_FAN) return k == 0 ? t + 1 : k == 1 ? t + 2 : 0;
  return 3 * t + k;
}

int attributeAccessor(const std::map<std::string, int>& attributes, const char* name) {
  auto it = attributes.find(name);
  return it == attributes.end() ? -1 : it->second;
}

// An optional attribute of `components` components per vertex; absent (empty) when missing, of another type, or of
// another count than the positions (the file is then read as if it lacked it).
template <class Vec>
std::vector<Vec> readAttribute(const tinygltf::Model& model, const std::map<std::string, int>& attributes, const char* name,
                               std::initializer_list<int> types, size_t vertices, uint64_t maxElements) {
  int index = attributeAccessor(attributes, name);
  if (index < 0) return {};
  FloatAccessor a = readFloatAccessor(model, index, name, maxElements);
  if (a.count() != vertices || std::find(types.begin(), types.end(), a.type) == types.end()) return {};
  std::vector<Vec> out(vertices);
  for (size_t i = 0; i < vertices; ++i) out[i] = Vec(a.values[i]);
  return out;
}

void applyMorphTargets(const tinygltf::Model& model, const tinygltf::Primitive& prim, const PrimitiveRequest& request,
                       PrimitiveData& data) {
  for (size_t target = 0; target < prim.targets.size() && target < request.weights.size(); ++target) {
    float w = static_cast<float>(request.weights[target]);
    if (w == 0.0f || !std::isfinite(w)) continue;
    auto add = [&](const char* name, auto& dst) {
      int index = attributeAccessor(prim.targets[target], name);
      if (index < 0 || dst.empty()) return;
      FloatAccessor delta = readFloatAccessor(model, index, name, request.maxElements);
      if (delta.count() != dst.size())
        throw Error("morph target " + std::to_string(target) + ": " + name + " accessor " + std::to_string(index) + " has " +
                    std::to_string(delta.count()) + " elements for " + std::to_string(dst.size()) + " vertices");
      for (size_t i = 0; i < dst.size(); ++i)
        for (int c = 0; c < 3; ++c) dst[i][c] += w * delta.values[i][c];  // tangent w is not morphed
    };
    add("POSITION", data.positions);
    add("NORMAL", data.normals);
    add("TANGENT", data.tangents);
  }
}

// The vertex of every element: the index accessor's values, or 0..vertices-1 without one; each checked in range.
std::vector<uint32_t> readElements(const tinygltf::Model& model, const tinygltf::Primitive& prim, size_t vertices,
                                   uint64_t maxElements) {
  if (prim.indices < 0) {
    std::vector<uint32_t> identity(vertices);
    for (size_t i = 0; i < vertices; ++i) identity[i] = static_cast<uint32_t>(i);
    return identity;
  }
  std::vector<uint32_t> indices = readIndexAccessor(model, prim.indices, maxElements);
  for (uint32_t vertex : indices)
    if (vertex >= vertices)
      throw Error("index " + std::to_string(vertex) + " out of range (" + std::to_string(vertices) + " vertices)");
  return indices;
}

std::vector<uint32_t> readTriangles(const tinygltf::Model& model, const tinygltf::Primitive& prim, size_t vertices,
                                    uint64_t maxElements) {
  std::vector<uint32_t> elements = readElements(model, prim, vertices, maxElements);
  size_t triangles = triangleCount(prim.mode, elements.size());
  std::vector<uint32_t> out(3 * triangles);
  for (size_t t = 0; t < triangles; ++t)
    for (int k = 0; k < 3; ++k) out[3 * t + k] = elements[cornerElement(prim.mode, t, k)];
  return out;
}

// Segment s's two elements (glTF 2.0 section 3.7.2.1): points repeat theirs, a loop closes on element 0.
std::pair<size_t, size_t> segmentElements(int mode, size_t s, size_t elements) {
  if (mode == TINYGLTF_MODE_POINTS) return {s, s};
  if (mode == TINYGLTF_MODE_LINE) return {2 * s, 2 * s + 1};
  return {s, (s + 1) % elements};  // strip and loop
}

std::vector<uint32_t> readSegments(const tinygltf::Model& model, const tinygltf::Primitive& prim, size_t vertices,
                                   uint64_t maxElements) {
  std::vector<uint32_t> elements = readElements(model, prim, vertices, maxElements);
  size_t segments = segmentCount(prim.mode, elements.size());
  std::vector<uint32_t> out(2 * segments);
  for (size_t s = 0; s < segments; ++s) {
    auto [e0, e1] = segmentElements(prim.mode, s, elements.size());
    out[2 * s] = elements[e0];
    out[2 * s + 1] = elements[e1];
  }
  return out;
}

}  // namespace

bool isPointOrLineMode(int mode) {
  return mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE || mode == TINYGLTF_MODE_LINE_LOOP ||
         mode == TINYGLTF_MODE_LINE_STRIP;
}

size_t segmentCount(int mode, size_t elements) {
  if (mode == TINYGLTF_MODE_POINTS) return elements;
  if (mode == TINYGLTF_MODE_LINE) return elements / 2;
  if (mode == TINYGLTF_MODE_LINE_STRIP) return elements >= 2 ? elements - 1 : 0;
  // A loop: one more, back to the start; two elements close on themselves (one segment, not the same one twice).
  return elements > 2 ? elements : elements == 2 ? 1 : 0;
}

bool isTriangleMode(int mode) {
  return mode == -1 || mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
         mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

size_t triangleCount(int mode, size_t elements) {
  if (mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN) return elements >= 3 ? elements - 2 : 0;
  return elements / 3;
}

PrimitiveData readPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& prim, const PrimitiveRequest& request) {
  int pos = attributeAccessor(prim.attributes, "POSITION");
  if (pos < 0) throw Error("primitive without POSITION");
  FloatAccessor positions = readFloatAccessor(model, pos, "POSITION", request.maxElements);
  // Float, or the integer types KHR_mesh_quantization allows (read by the same normalization rules).
  if (positions.type != TINYGLTF_TYPE_VEC3 || positions.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    throw Error("POSITION accessor " + std::to_string(pos) + " is not a float or quantized VEC3");
  PrimitiveData data;
  const size_t n = positions.count();
  data.positions.resize(n);
  for (size_t i = 0; i < n; ++i) data.positions[i] = glm::vec3(positions.values[i]);
  const uint64_t limit = request.maxElements;
  data.normals = readAttribute<glm::vec3>(model, prim.attributes, "NORMAL", {TINYGLTF_TYPE_VEC3}, n, limit);
  data.uv0 = readAttribute<glm::vec2>(model, prim.attributes, "TEXCOORD_0", {TINYGLTF_TYPE_VEC2}, n, limit);
  data.uv1 = readAttribute<glm::vec2>(model, prim.attributes, "TEXCOORD_1", {TINYGLTF_TYPE_VEC2}, n, limit);
  data.tangents = readAttribute<glm::vec4>(model, prim.attributes, "TANGENT", {TINYGLTF_TYPE_VEC4}, n, limit);
  data.colors = readAttribute<glm::vec4>(model, prim.attributes, "COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, n, limit);
  int colorAccessor = attributeAccessor(prim.attributes, "COLOR_0");
  if (!data.colors.empty() && model.accessors[colorAccessor].type == TINYGLTF_TYPE_VEC3)
    for (glm::vec4& c : data.colors) c.w = 1.0f;
  applyMorphTargets(model, prim, request, data);
  std::vector<bool> mirrored;  // per vertex, by the skin
  if (request.joints) {
    // Every set of four influences, JOINTS_n with WEIGHTS_n, set after set. Joint indices are unsigned bytes or
    // shorts; anything else (a float past a uint's range) reads as no joint.
    for (uint32_t set = 0;; ++set) {
      const std::string joints = "JOINTS_" + std::to_string(set), weights = "WEIGHTS_" + std::to_string(set);
      if (set > 0 && attributeAccessor(prim.attributes, joints.c_str()) < 0 &&
          attributeAccessor(prim.attributes, weights.c_str()) < 0)
        break;
      const size_t before = data.joints.size();
      for (const glm::vec4& j :
           readAttribute<glm::vec4>(model, prim.attributes, joints.c_str(), {TINYGLTF_TYPE_VEC4}, n, limit)) {
        glm::uvec4 index(UINT32_MAX);
        for (int k = 0; k < 4; ++k)
          if (j[k] >= 0.0f && j[k] < 65536.0f) index[k] = uint32_t(j[k]);
        data.joints.push_back(index);
      }
      const std::vector<glm::vec4> w =
          readAttribute<glm::vec4>(model, prim.attributes, weights.c_str(), {TINYGLTF_TYPE_VEC4}, n, limit);
      if (data.joints.size() - before != n || w.size() != n)
        throw Error("a skinned mesh's primitive lacks " + joints + " and " + weights + " for every vertex");
      data.weights.insert(data.weights.end(), w.begin(), w.end());
    }
    mirrored = applySkin(data, *request.joints);
  }
  if (isPointOrLineMode(prim.mode)) {
    data.segments = readSegments(model, prim, n, limit);
    return data;
  }
  data.triangles = readTriangles(model, prim, n, limit);
  // A triangle most of whose corners a skin mirrors keeps its facing by swapping its winding (as a node's
  // mirroring transform does, gltf_loader.cpp).
  for (size_t t = 0; !mirrored.empty() && t < data.triangles.size() / 3; ++t) {
    uint32_t* c = &data.triangles[3 * t];
    if (int(mirrored[c[0]]) + int(mirrored[c[1]]) + int(mirrored[c[2]]) >= 2) std::swap(c[1], c[2]);
  }
  if (request.generateTangents && data.tangents.empty()) {
    data.tangents =
        generateTangents(data.positions, data.normals, request.tangentUvSet == 1 ? data.uv1 : data.uv0, data.triangles);
    data.tangentsPerCorner = true;
  }
  return data;
}

}  // namespace vkmc
