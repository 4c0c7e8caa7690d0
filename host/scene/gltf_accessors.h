// Bounds-checked glTF accessor reading: every component type, glTF's normalization rules and sparse accessors.
// Every offset and count in a file is untrusted: each bound is checked by subtraction from a known size.
#pragma once
#include <tiny_gltf.h>

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace vkmc {

size_t componentSize(int componentType);  // bytes; 0 for an invalid type
size_t componentCount(int type);          // SCALAR 1 .. VEC4 4; 0 for matrices and invalid types

// A dense accessor's elements in place (no sparse substitution).
struct AccessorView {
  const unsigned char* data = nullptr;
  size_t count = 0;
  size_t stride = 0;
  int componentType = 0;
  int type = 0;
  bool normalized = false;
};

// Throws vkmc::Error ("<what> accessor N ...") when the accessor or its view runs past its buffer, is sparse or
// has no buffer view. Vectors and MAT4.
AccessorView viewAccessor(const tinygltf::Model& model, int index, const char* what);

// An accessor's elements as floats, up to 4 components each (missing ones 0), normalized per glTF 2.0 section
// 3.11 when the accessor is `normalized`, sparse substitutions applied; an accessor without a buffer view reads
// as zeros. Elements past maxElements are refused (a view-less accessor's count is not bounded by any data).
struct FloatAccessor {
  std::vector<glm::vec4> values;
  int componentType = 0;
  int type = 0;
  bool normalized = false;
  size_t count() const { return values.size(); }
};
FloatAccessor readFloatAccessor(const tinygltf::Model& model, int index, const char* what, uint64_t maxElements);

// An index accessor (unsigned byte, short or int scalars; sparse allowed).
std::vector<uint32_t> readIndexAccessor(const tinygltf::Model& model, int index, uint64_t maxElements);

}  // namespace vkmc
