// Accessor reading with bounds checks by subtraction (fuzzing found heap overflows here before).
#include "scene/gltf_accessors.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "error.h"

namespace vkmc {
namespace {

std::string accessorName(const char* what, int index) { return std::string(what) + " accessor " + std::to_string(index); }

// The `count` elements of `elemSize` bytes at `stride` starting `offset` bytes into buffer view `viewIndex`.
const unsigned char* viewRange(const tinygltf::Model& model, int viewIndex, size_t offset, size_t count, size_t elemSize,
                               size_t& stride, const std::string& name) {
  if (viewIndex < 0 || viewIndex >= static_cast<int>(model.bufferViews.size())) throw Error(name + " has no valid buffer view");
  const tinygltf::BufferView& v = model.bufferViews[viewIndex];
  if (v.buffer < 0 || v.buffer >= static_cast<int>(model.buffers.size())) throw Error(name + " refers to a missing buffer");
  const tinygltf::Buffer& b = model.buffers[v.buffer];
  if (stride == 0) stride = v.byteStride ? v.byteStride : elemSize;
  if (stride < elemSize) throw Error(name + " has a byte stride smaller than its element");
  // Every bound by subtraction from a known size: sums of file-supplied offsets and counts can wrap.
  if (v.byteOffset > b.data.size() || v.byteLength > b.data.size() - v.byteOffset)
    throw Error(name + ": buffer view runs past the end of its buffer");
  if (count > 0 &&
      (offset > v.byteLength || elemSize > v.byteLength - offset || (count - 1) > (v.byteLength - offset - elemSize) / stride))
    throw Error(name + ": accessor runs past the end of its buffer view");
  return b.data.data() + v.byteOffset + offset;
}

// glTF 2.0 section 3.11: signed types map to max(c / (2^(n-1) - 1), -1), unsigned ones to c / (2^n - 1).
float readComponent(const unsigned char* p, int componentType, bool normalized) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      int8_t x;
      std::memcpy(&x, p, 1);
      return normalized ? std::max(x / 127.0f, -1.0f) : float(x);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? *p / 255.0f : float(*p);
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t x;
      std::memcpy(&x, p, 2);
      return normalized ? std::max(x / 32767.0f, -1.0f) : float(x);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t x;
      std::memcpy(&x, p, 2);
      return normalized ? x / 65535.0f : float(x);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      uint32_t x;
      std::memcpy(&x, p, 4);
      return float(x);
    }
    default: {
      float x;
      std::memcpy(&x, p, 4);
      return x;
    }
  }
}

uint32_t readUnsigned(const unsigned char* p, int componentType) {
  switch (componentType) {
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

bool isIndexType(int ct) {
  return ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
         ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

// Calls write(element, data) for every element: the dense part first, then each sparse substitution. With
// `checkOnly`, checks every bound and the element limit without writing (callers allocate only after that).
template <class Write>
void forEachElement(const tinygltf::Model& model, int index, const char* what, uint64_t maxElements, size_t elemSize,
                    bool checkOnly, Write&& write) {
  std::string name = accessorName(what, index);
  const tinygltf::Accessor& a = model.accessors[index];
  if (a.bufferView >= 0) {
    size_t stride = 0;
    const unsigned char* data = viewRange(model, a.bufferView, a.byteOffset, a.count, elemSize, stride, name);
    if (a.count > maxElements) throw Error(name + ": " + std::to_string(a.count) + " elements, more than the loader's limit");
    for (size_t i = 0; i < a.count && !checkOnly; ++i) write(i, data + i * stride);
  } else if (a.count > maxElements) {  // no data bounds a view-less accessor's count
    throw Error(name + ": " + std::to_string(a.count) + " elements, more than the loader's limit");
  }
  if (!a.sparse.isSparse) return;
  const auto& s = a.sparse;
  if (s.count < 0 || static_cast<size_t>(s.count) > a.count) throw Error(name + ": sparse count out of range");
  if (s.indices.byteOffset < 0 || s.values.byteOffset < 0) throw Error(name + ": negative sparse byte offset");
  if (!isIndexType(s.indices.componentType)) throw Error(name + ": sparse indices are not unsigned integers");
  size_t indexStride = componentSize(s.indices.componentType), valueStride = elemSize;
  const unsigned char* indices = viewRange(model, s.indices.bufferView, size_t(s.indices.byteOffset), size_t(s.count),
                                           indexStride, indexStride, name + " (sparse indices)");
  const unsigned char* values = viewRange(model, s.values.bufferView, size_t(s.values.byteOffset), size_t(s.count), elemSize,
                                          valueStride, name + " (sparse values)");
  for (size_t i = 0; i < size_t(s.count) && !checkOnly; ++i) {
    uint32_t target = readUnsigned(indices + i * indexStride, s.indices.componentType);
    if (target >= a.count) throw Error(name + ": sparse index " + std::to_string(target) + " out of range");
    write(target, values + i * elemSize);
  }
}

const tinygltf::Accessor& accessorAt(const tinygltf::Model& model, int index, const char* what) {
  if (index < 0 || index >= static_cast<int>(model.accessors.size())) throw Error(accessorName(what, index) + " does not exist");
  return model.accessors[index];
}

}  // namespace

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
  std::string name = accessorName(what, index);
  const tinygltf::Accessor& a = accessorAt(model, index, what);
  if (a.sparse.isSparse) throw Error(name + " is sparse (not supported here)");
  // Vectors, and MAT4 for skins' inverse bind matrices (float columns have no padding).
  size_t elemSize = componentSize(a.componentType) * (a.type == TINYGLTF_TYPE_MAT4 ? 16 : componentCount(a.type));
  if (elemSize == 0) throw Error(name + " has an invalid type");
  AccessorView out;
  out.data = viewRange(model, a.bufferView, a.byteOffset, a.count, elemSize, out.stride, name);
  out.count = a.count;
  out.componentType = a.componentType;
  out.type = a.type;
  out.normalized = a.normalized;
  return out;
}

FloatAccessor readFloatAccessor(const tinygltf::Model& model, int index, const char* what, uint64_t maxElements) {
  const tinygltf::Accessor& a = accessorAt(model, index, what);
  size_t size = componentSize(a.componentType), components = componentCount(a.type);
  if (size == 0 || components == 0) throw Error(accessorName(what, index) + " has an invalid type");
  if (a.normalized && size == 4) throw Error(accessorName(what, index) + " is normalized but not of a byte or short type");
  FloatAccessor out;
  out.componentType = a.componentType;
  out.type = a.type;
  out.normalized = a.normalized;
  auto write = [&](size_t i, const unsigned char* p) {
    for (size_t c = 0; c < components; ++c) out.values[i][c] = readComponent(p + c * size, a.componentType, a.normalized);
  };
  forEachElement(model, index, what, maxElements, size * components, true, write);
  out.values.assign(a.count, glm::vec4(0.0f));
  forEachElement(model, index, what, maxElements, size * components, false, write);
  return out;
}

std::vector<uint32_t> readIndexAccessor(const tinygltf::Model& model, int index, uint64_t maxElements) {
  const tinygltf::Accessor& a = accessorAt(model, index, "index");
  if (a.type != TINYGLTF_TYPE_SCALAR || !isIndexType(a.componentType))
    throw Error("index accessor " + std::to_string(index) + " is not an unsigned integer scalar");
  std::vector<uint32_t> out;
  auto write = [&](size_t i, const unsigned char* p) { out[i] = readUnsigned(p, a.componentType); };
  forEachElement(model, index, "index", maxElements, componentSize(a.componentType), true, write);
  out.assign(a.count, 0);
  forEachElement(model, index, "index", maxElements, componentSize(a.componentType), false, write);
  return out;
}

}  // namespace vkmc
