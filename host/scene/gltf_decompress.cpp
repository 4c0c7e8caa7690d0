// Draco (libdraco) and meshopt (libmeshoptimizer) decoding into the tinygltf model; every size from the file is
// untrusted and bounded before anything is allocated for it.
#include "scene/gltf_decompress.h"

#include <meshoptimizer.h>

#include <cstring>
#include <nlohmann/json.hpp>

#include "error.h"
#include "scene/draco_codec.h"
#include "scene/gltf_accessors.h"

namespace vkmc {
namespace {

constexpr const char* kMeshopt = "EXT_meshopt_compression";
constexpr const char* kDraco = "KHR_draco_mesh_compression";

// A non-negative integer member of an extension object, or `fallback` when absent.
uint64_t unsignedMember(const tinygltf::Value& v, const char* key, uint64_t fallback, const std::string& where) {
  if (!v.Has(key)) return fallback;
  const tinygltf::Value& m = v.Get(key);
  if (!m.IsNumber() || m.GetNumberAsDouble() < 0.0 || m.GetNumberAsDouble() > 9.0e15)
    throw Error(where + ": " + key + " is not a non-negative integer");
  return static_cast<uint64_t>(m.GetNumberAsDouble());
}

std::string stringMember(const tinygltf::Value& v, const char* key, const std::string& fallback) {
  return v.Has(key) && v.Get(key).IsString() ? v.Get(key).Get<std::string>() : fallback;
}

class Budget {
 public:
  explicit Budget(uint64_t bytes) : left_(bytes) {}
  // Refuses `count` elements of `size` bytes when their product overflows or passes what is left.
  size_t take(uint64_t count, uint64_t size, const std::string& where) {
    if (size != 0 && count > left_ / size)
      throw Error(where + ": decoded data would pass the loader's limit of " + std::to_string(left_) + " more bytes");
    left_ -= count * size;
    return static_cast<size_t>(count * size);
  }
  uint64_t left() const { return left_; }

 private:
  uint64_t left_;
};

int addBuffer(tinygltf::Model& model, std::vector<unsigned char>&& data) {
  tinygltf::Buffer b;
  b.data = std::move(data);
  model.buffers.push_back(std::move(b));
  return static_cast<int>(model.buffers.size() - 1);
}

// EXT_meshopt_compression: one buffer view, decoded per its mode and filter.
void decodeMeshoptView(tinygltf::Model& model, size_t viewIndex, Budget& budget) {
  tinygltf::BufferView& view = model.bufferViews[viewIndex];
  const std::string where = std::string(kMeshopt) + ": buffer view " + std::to_string(viewIndex);
  const tinygltf::Value& ext = view.extensions.at(kMeshopt);
  uint64_t source = unsignedMember(ext, "buffer", ~uint64_t(0), where);
  uint64_t offset = unsignedMember(ext, "byteOffset", 0, where), length = unsignedMember(ext, "byteLength", 0, where);
  uint64_t stride = unsignedMember(ext, "byteStride", 0, where), count = unsignedMember(ext, "count", 0, where);
  std::string mode = stringMember(ext, "mode", ""), filter = stringMember(ext, "filter", "NONE");
  if (source >= model.buffers.size()) throw Error(where + ": buffer " + std::to_string(source) + " does not exist");
  const std::vector<unsigned char>& src = model.buffers[source].data;
  if (offset > src.size() || length > src.size() - offset) throw Error(where + ": compressed range runs past its buffer");
  bool attributes = mode == "ATTRIBUTES";
  if (attributes ? (stride == 0 || stride % 4 != 0 || stride > 256) : (stride != 2 && stride != 4))
    throw Error(where + ": byteStride " + std::to_string(stride) + " is invalid for mode " + mode);
  if (mode == "TRIANGLES" && count % 3 != 0) throw Error(where + ": TRIANGLES count is not a multiple of 3");
  std::vector<unsigned char> out(budget.take(count, stride, where));
  const unsigned char* data = src.data() + offset;
  int rc = attributes            ? meshopt_decodeVertexBuffer(out.data(), count, stride, data, length)
           : mode == "TRIANGLES" ? meshopt_decodeIndexBuffer(out.data(), count, stride, data, length)
           : mode == "INDICES"   ? meshopt_decodeIndexSequence(out.data(), count, stride, data, length)
                                 : (throw Error(where + ": unknown mode '" + mode + "'"), 0);
  if (rc != 0) throw Error(where + ": the compressed data is malformed (meshopt error " + std::to_string(rc) + ")");
  if (filter != "NONE" && !attributes) throw Error(where + ": filter " + filter + " on index data");
  if (filter == "OCTAHEDRAL") {
    if (stride != 4 && stride != 8) throw Error(where + ": OCTAHEDRAL filter needs byteStride 4 or 8");
    meshopt_decodeFilterOct(out.data(), count, stride);
  } else if (filter == "QUATERNION") {
    if (stride != 8) throw Error(where + ": QUATERNION filter needs byteStride 8");
    meshopt_decodeFilterQuat(out.data(), count, stride);
  } else if (filter == "EXPONENTIAL") {
    meshopt_decodeFilterExp(out.data(), count, stride);
  } else if (filter != "NONE") {
    throw Error(where + ": unknown filter '" + filter + "'");
  }
  int buffer = addBuffer(model, std::move(out));
  tinygltf::BufferView& decoded = model.bufferViews[viewIndex];  // addBuffer does not touch views
  decoded.buffer = buffer;
  decoded.byteOffset = 0;
  decoded.byteLength = static_cast<size_t>(count * stride);
  if (attributes) decoded.byteStride = static_cast<size_t>(stride);
  decoded.extensions.erase(kMeshopt);
}

// A new tightly packed view and accessor over `data`.
int addAccessor(tinygltf::Model& model, std::vector<unsigned char>&& data, int componentType, int type, size_t count) {
  tinygltf::BufferView view;
  view.byteLength = data.size();
  view.buffer = addBuffer(model, std::move(data));
  model.bufferViews.push_back(view);
  tinygltf::Accessor a;
  a.bufferView = static_cast<int>(model.bufferViews.size() - 1);
  a.byteOffset = 0;
  a.normalized = false;
  a.componentType = componentType;
  a.type = type;
  a.count = count;
  a.sparse.isSparse = false;
  model.accessors.push_back(a);
  return static_cast<int>(model.accessors.size() - 1);
}

// KHR_draco_mesh_compression: the primitive's attributes and indices replaced by decoded float attributes and
// 32-bit indices (the accessors' declared types give the component counts).
void decodeDracoPrimitive(tinygltf::Model& model, tinygltf::Primitive& prim, const std::string& where,
                          const DecompressLimits& limits, Budget& budget) {
  const tinygltf::Value& ext = prim.extensions.at(kDraco);
  uint64_t viewIndex = unsignedMember(ext, "bufferView", ~uint64_t(0), where);
  if (viewIndex >= model.bufferViews.size()) throw Error(where + ": bufferView " + std::to_string(viewIndex) + " does not exist");
  const tinygltf::BufferView& view = model.bufferViews[viewIndex];
  if (view.buffer < 0 || view.buffer >= static_cast<int>(model.buffers.size()))
    throw Error(where + ": its buffer does not exist");
  const std::vector<unsigned char>& src = model.buffers[view.buffer].data;
  if (view.byteOffset > src.size() || view.byteLength > src.size() - view.byteOffset)
    throw Error(where + ": its buffer view runs past its buffer");
  if (prim.mode != -1 && prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != TINYGLTF_MODE_TRIANGLE_STRIP)
    throw Error(where + ": Draco primitives must be triangles or triangle strips");
  if (!ext.Has("attributes") || !ext.Get("attributes").IsObject()) throw Error(where + ": no attributes object");
  const tinygltf::Value& mapping = ext.Get("attributes");
  std::vector<std::pair<std::string, int>> compressed;  // semantic, glTF type
  std::vector<DracoAttributeRequest> requests;
  for (const auto& [semantic, accessor] : prim.attributes) {
    if (!mapping.Has(semantic)) continue;  // not compressed: the accessor stays as it is
    uint64_t id = unsignedMember(mapping, semantic.c_str(), 0, where);
    if (accessor < 0 || accessor >= static_cast<int>(model.accessors.size()))
      throw Error(where + ": " + semantic + " accessor does not exist");
    int type = model.accessors[accessor].type;
    int components = static_cast<int>(componentCount(type));
    if (components == 0 || id > 0xFFFFFFFFu) throw Error(where + ": " + semantic + " has an invalid type or Draco id");
    compressed.emplace_back(semantic, type);
    requests.push_back({static_cast<uint32_t>(id), components});
  }
  DracoDecoded mesh =
      decodeDracoMesh(src.data() + view.byteOffset, view.byteLength, requests, limits.maxTriangles, budget.left());
  if (!mesh.error.empty()) throw Error(where + ": " + mesh.error);
  std::vector<unsigned char> indices(budget.take(mesh.indices.size(), 4, where));
  std::memcpy(indices.data(), mesh.indices.data(), indices.size());
  prim.indices =
      addAccessor(model, std::move(indices), TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, mesh.indices.size());
  prim.mode = TINYGLTF_MODE_TRIANGLES;  // Draco's faces are a triangle list whatever the primitive declared
  for (size_t i = 0; i < compressed.size(); ++i) {
    std::vector<unsigned char> values(budget.take(mesh.attributes[i].size(), 4, where));
    std::memcpy(values.data(), mesh.attributes[i].data(), values.size());
    prim.attributes[compressed[i].first] =
        addAccessor(model, std::move(values), TINYGLTF_COMPONENT_TYPE_FLOAT, compressed[i].second, mesh.points);
  }
  prim.extensions.erase(kDraco);
}

}  // namespace

void decompressModel(tinygltf::Model& model, const DecompressLimits& limits) {
  Budget budget(limits.maxDecodedBytes);
  for (size_t v = 0; v < model.bufferViews.size(); ++v)
    if (model.bufferViews[v].extensions.count(kMeshopt)) decodeMeshoptView(model, v, budget);
  for (size_t m = 0; m < model.meshes.size(); ++m)
    for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
      tinygltf::Primitive& prim = model.meshes[m].primitives[p];
      if (!prim.extensions.count(kDraco)) continue;
      std::string where = std::string(kDraco) + ": primitive " + std::to_string(p) + " of mesh " + std::to_string(m);
      decodeDracoPrimitive(model, prim, where, limits, budget);
    }
}

std::string prepareCompressedJson(std::string_view json) {
  nlohmann::json doc = nlohmann::json::parse(json.begin(), json.end(), nullptr, false);
  if (!doc.is_object()) return "";
  bool changed = false;
  if (doc.contains("buffers") && doc["buffers"].is_array())
    for (nlohmann::json& b : doc["buffers"]) {
      if (!b.is_object() || b.contains("uri") || !b.contains("extensions") || !b["extensions"].is_object()) continue;
      const nlohmann::json& ext = b["extensions"];
      if (!ext.contains(kMeshopt) || !ext[kMeshopt].is_object()) continue;
      const nlohmann::json& fallback = ext[kMeshopt];
      if (!fallback.contains("fallback") || fallback["fallback"] != true) continue;
      b["uri"] = "data:application/octet-stream;base64,AA==";  // one zero byte: no view can read through it
      b["byteLength"] = 1;
      changed = true;
    }
  if (doc.contains("meshes") && doc["meshes"].is_array())
    for (nlohmann::json& mesh : doc["meshes"]) {
      if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
      for (nlohmann::json& prim : mesh["primitives"])
        if (prim.is_object() && prim.contains("indices") && prim.contains("extensions") && prim["extensions"].is_object() &&
            prim["extensions"].contains(kDraco)) {
          prim.erase("indices");  // decoding replaces them
          changed = true;
        }
    }
  return changed ? doc.dump() : "";
}

}  // namespace vkmc
