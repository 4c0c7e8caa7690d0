// Accessor reading: glTF's normalization rules for every component type, sparse accessors, and the bounds checks
// on untrusted offsets and counts.
#include "scene/gltf_accessors.h"

#include <gtest/gtest.h>

#include <cstring>

#include "error.h"

using namespace vkmc;

namespace {

// A model with one buffer holding `bytes` and one view over all of it.
tinygltf::Model modelWith(const std::vector<unsigned char>& bytes) {
  tinygltf::Model m;
  m.buffers.emplace_back().data = bytes;
  tinygltf::BufferView& v = m.bufferViews.emplace_back();
  v.buffer = 0;
  v.byteLength = bytes.size();
  return m;
}

tinygltf::Accessor& addAccessor(tinygltf::Model& m, int view, int componentType, int type, size_t count, bool normalized) {
  tinygltf::Accessor& a = m.accessors.emplace_back();
  a.bufferView = view;
  a.byteOffset = 0;
  a.componentType = componentType;
  a.type = type;
  a.count = count;
  a.normalized = normalized;
  a.sparse.isSparse = false;
  return a;
}

template <class T>
std::vector<unsigned char> bytesOf(std::initializer_list<T> values) {
  std::vector<unsigned char> out(values.size() * sizeof(T));
  std::memcpy(out.data(), std::data(values), out.size());
  return out;
}

std::string errorOf(const tinygltf::Model& m, int accessor, uint64_t maxElements = 1000) {
  try {
    readFloatAccessor(m, accessor, "TEST", maxElements);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

struct NormalizationRow {
  const char* name;
  int componentType;
  std::vector<unsigned char> bytes;  // two components
  bool normalized;
  float expected[2];
};
void PrintTo(const NormalizationRow& r, std::ostream* os) { *os << r.name; }

class Normalization : public ::testing::TestWithParam<NormalizationRow> {};

}  // namespace

// glTF 2.0 section 3.11: signed c -> max(c / (2^(n-1) - 1), -1), unsigned c -> c / (2^n - 1); plain integers
// (KHR_mesh_quantization without `normalized`) read as their value.
TEST_P(Normalization, ComponentsReadAsTheSpecSays) {
  const NormalizationRow& r = GetParam();
  tinygltf::Model m = modelWith(r.bytes);
  addAccessor(m, 0, r.componentType, TINYGLTF_TYPE_VEC2, 1, r.normalized);
  FloatAccessor a = readFloatAccessor(m, 0, "TEST", 10);
  ASSERT_EQ(a.count(), 1u);
  EXPECT_FLOAT_EQ(a.values[0].x, r.expected[0]);
  EXPECT_FLOAT_EQ(a.values[0].y, r.expected[1]);
  EXPECT_EQ(a.values[0].z, 0.0f);
}

INSTANTIATE_TEST_SUITE_P(
    GltfAccessors, Normalization,
    ::testing::Values(NormalizationRow{"byte_norm", 5120, bytesOf<int8_t>({-128, 127}), true, {-1.0f, 1.0f}},
                      NormalizationRow{"byte_plain", 5120, bytesOf<int8_t>({-64, 3}), false, {-64.0f, 3.0f}},
                      NormalizationRow{"ubyte_norm", 5121, bytesOf<uint8_t>({255, 51}), true, {1.0f, 0.2f}},
                      NormalizationRow{"ubyte_plain", 5121, bytesOf<uint8_t>({200, 0}), false, {200.0f, 0.0f}},
                      NormalizationRow{"short_norm", 5122, bytesOf<int16_t>({-32768, 32767}), true, {-1.0f, 1.0f}},
                      NormalizationRow{"short_plain", 5122, bytesOf<int16_t>({-1000, 7}), false, {-1000.0f, 7.0f}},
                      NormalizationRow{"ushort_norm", 5123, bytesOf<uint16_t>({65535, 0}), true, {1.0f, 0.0f}},
                      NormalizationRow{"ushort_plain", 5123, bytesOf<uint16_t>({1000, 65535}), false, {1000.0f, 65535.0f}},
                      NormalizationRow{"float", 5126, bytesOf<float>({0.25f, -3.5f}), false, {0.25f, -3.5f}}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(GltfAccessors, SparseValuesReplaceTheDenseOnes) {
  // Dense: 4 floats 1..4; sparse: element 2 becomes 30 (u8 indices), then a view-less accessor of zeros with element
  // 0 set.
  std::vector<unsigned char> bytes = bytesOf<float>({1, 2, 3, 4, 30});
  bytes.push_back(2);
  tinygltf::Model m = modelWith(bytes);
  m.bufferViews[0].byteLength = 16;
  auto addView = [&](size_t offset, size_t length) {
    tinygltf::BufferView& v = m.bufferViews.emplace_back();
    v.buffer = 0, v.byteOffset = offset, v.byteLength = length;
  };
  addView(16, 4);  // values
  addView(20, 1);  // indices
  for (int view : {0, -1}) {
    tinygltf::Accessor& a = addAccessor(m, view, 5126, TINYGLTF_TYPE_SCALAR, 4, false);
    a.sparse.isSparse = true;
    a.sparse.count = 1;
    a.sparse.indices = {0, 2, 5121};
    a.sparse.values = {1, 0};
  }
  FloatAccessor dense = readFloatAccessor(m, 0, "TEST", 10), zeros = readFloatAccessor(m, 1, "TEST", 10);
  EXPECT_EQ(dense.values[0].x, 1.0f);
  EXPECT_EQ(dense.values[2].x, 30.0f);
  EXPECT_EQ(dense.values[3].x, 4.0f);
  EXPECT_EQ(zeros.values[2].x, 30.0f);
  EXPECT_EQ(zeros.values[1].x, 0.0f);

  m.bufferViews[2].byteOffset = 19;  // the index is now the float 30's top byte (0x41 = 65): out of range
  EXPECT_NE(errorOf(m, 0).find("sparse index 65 out of range"), std::string::npos) << errorOf(m, 0);
  m.accessors[0].sparse.indices.byteOffset = 1;  // past the end of its 1-byte view
  EXPECT_NE(errorOf(m, 0).find("runs past the end"), std::string::npos) << errorOf(m, 0);
  m.accessors[0].sparse.indices.byteOffset = 0;
  m.bufferViews[2].byteOffset = 20;
  m.accessors[0].sparse.count = 5;  // more substitutions than elements
  EXPECT_NE(errorOf(m, 0).find("sparse count out of range"), std::string::npos) << errorOf(m, 0);
  m.accessors[0].sparse.count = -1;
  EXPECT_NE(errorOf(m, 0).find("sparse count out of range"), std::string::npos) << errorOf(m, 0);
}

TEST(GltfAccessors, UntrustedOffsetsAndCountsAreRefused) {
  tinygltf::Model m = modelWith(bytesOf<float>({1, 2, 3}));
  addAccessor(m, 0, 5126, TINYGLTF_TYPE_VEC3, 1, false);
  EXPECT_EQ(errorOf(m, 0), "");
  m.accessors[0].count = 2;
  EXPECT_NE(errorOf(m, 0).find("runs past the end of its buffer view"), std::string::npos);
  m.accessors[0].count = 1;
  m.accessors[0].byteOffset = ~size_t(0) - 3;  // would wrap if added
  EXPECT_NE(errorOf(m, 0).find("runs past the end"), std::string::npos);
  m.accessors[0].byteOffset = 0;
  m.bufferViews[0].byteOffset = ~size_t(0) - 3;
  EXPECT_NE(errorOf(m, 0).find("buffer view runs past the end of its buffer"), std::string::npos);
  // A view-less accessor has no data bounding its count: the loader's element limit does.
  addAccessor(m, -1, 5126, TINYGLTF_TYPE_VEC3, size_t(1) << 40, false);
  EXPECT_NE(errorOf(m, 1, 1000).find("more than the loader's limit"), std::string::npos) << errorOf(m, 1, 1000);
  EXPECT_NE(errorOf(m, 7).find("does not exist"), std::string::npos);
  addAccessor(m, 0, 5126, TINYGLTF_TYPE_VEC3, 1, true);  // normalized floats are invalid
  EXPECT_NE(errorOf(m, 2).find("normalized"), std::string::npos);
}

TEST(GltfAccessors, IndicesOfEveryWidthAndSparse) {
  tinygltf::Model m = modelWith(bytesOf<uint16_t>({7, 65535, 3, 0}));
  addAccessor(m, 0, 5123, TINYGLTF_TYPE_SCALAR, 3, false);
  EXPECT_EQ(readIndexAccessor(m, 0, 10), (std::vector<uint32_t>{7, 65535, 3}));
  addAccessor(m, 0, 5126, TINYGLTF_TYPE_SCALAR, 1, false);
  EXPECT_THROW(readIndexAccessor(m, 1, 10), Error);  // float indices
}
