// KHR_draco_mesh_compression and EXT_meshopt_compression: meshes compressed here with the libraries' own encoders
// (no binary models in the repository) decode to their uncompressed originals; malformed data is refused with a
// line naming the extension.
#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "error.h"
#include "scene/draco_codec.h"
#include "scene/gltf_loader.h"
#include "support/compressed_meshes.h"
#include "support/gltf_builder.h"
#include "support/test_scenes.h"

using namespace vkmc;
using namespace vkmc::test;

namespace {
std::filesystem::path dir() {
  static auto d = test::makeTempDir("decompress");
  return d;
}

// The same triangles in the same order with the same winding, positions within `tolerance` (meshopt's index codec
// may rotate a triangle's corners); when quantization made some triangles zero-area, the same count only.
void expectSameTriangles(const Scene& decoded, const Scene& original, float tolerance) {
  ASSERT_EQ(decoded.triangleCount() + decoded.degenerateTriangles, original.triangleCount() + original.degenerateTriangles);
  if (decoded.degenerateTriangles != original.degenerateTriangles) return;
  auto near = [&](const glm::vec3& a, const glm::vec3& b) {
    return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::vec3(tolerance)));
  };
  for (size_t t = 0; t < original.triangleCount(); ++t) {
    bool same = false;
    for (int r = 0; r < 3 && !same; ++r)
      same = near(decoded.positions[3 * t + r], original.positions[3 * t]) &&
             near(decoded.positions[3 * t + (r + 1) % 3], original.positions[3 * t + 1]) &&
             near(decoded.positions[3 * t + (r + 2) % 3], original.positions[3 * t + 2]);
    ASSERT_TRUE(same) << "triangle " << t;
  }
}

float largestExtent(const IndexedMesh& m) {
  float lo = 1e30f, hi = -1e30f;
  for (float x : m.positions) lo = std::min(lo, x), hi = std::max(hi, x);
  return hi - lo;
}

void roundTrip(const std::string& name, const IndexedMesh& m) {
  Scene original = loadGltf(writePlain(dir(), name + "_plain", m));
  // Draco: positions within the 14-bit quantization step; the order of faces and corners kept (sequential).
  Scene draco = loadGltf(writeDraco(dir(), name + "_draco", m, 14, true));
  expectSameTriangles(draco, original, largestExtent(m) / float((1 << 14) - 1));
  ASSERT_EQ(draco.uv0.size(), original.uv0.size());
  for (size_t c = 0; c < draco.uv0.size(); ++c)
    ASSERT_NEAR(glm::length(draco.uv0[c] - original.uv0[c]), 0.0f, 2.0f / float((1 << 14) - 1)) << "corner " << c;
  // Edgebreaker reorders faces: the same count and bounds.
  Scene edgebreaker = loadGltf(writeDraco(dir(), name + "_edgebreaker", m, 14, false));
  EXPECT_EQ(edgebreaker.triangleCount() + edgebreaker.degenerateTriangles, original.triangleCount());
  EXPECT_NEAR(glm::length(edgebreaker.bounds.extent() - original.bounds.extent()), 0.0f, largestExtent(m) / 4096.0f);
  // meshopt is lossless for positions and indices.
  for (std::string path : {writeMeshopt(dir(), name + "_meshopt", m), toGlb(writeMeshopt(dir(), name + "_meshopt_glb", m))}) {
    Scene meshopt = loadGltf(path);
    expectSameTriangles(meshopt, original, 0.0f);
    EXPECT_TRUE(meshopt.warnings.empty()) << meshopt.warnings[0];
    EXPECT_NEAR(meshopt.normals[0].x, 0.6f, 0.02f) << "octahedral filter decoded";
    EXPECT_NEAR(meshopt.normals[0].z, 0.8f, 0.02f);
  }
}
}  // namespace

TEST(GltfDecompress, CompressedGridsDecodeToTheirOriginal) { roundTrip("grid", grid(17)); }

TEST(GltfDecompress, MalformedDataIsRefusedNamingTheExtension) {
  IndexedMesh m = grid(9);
  std::string draco = test::loadError(writeDraco(dir(), "draco_bad", m, 14, true, true));
  EXPECT_NE(draco.find("KHR_draco_mesh_compression: primitive 0 of mesh 0"), std::string::npos) << draco;
  std::string meshopt = test::loadError(writeMeshopt(dir(), "meshopt_bad", m, true));
  EXPECT_NE(meshopt.find("EXT_meshopt_compression: buffer view 0"), std::string::npos) << meshopt;
  // Failing for another reason (an index out of range), the message still names the extension in use.
  IndexedMesh broken = m;
  broken.indices[4] = 1000;
  std::string other = test::loadError(writeMeshopt(dir(), "meshopt_index", broken));
  EXPECT_NE(other.find("index 1000 out of range"), std::string::npos) << other;
  EXPECT_NE(other.find("EXT_meshopt_compression"), std::string::npos) << other;
}

// 2e9 elements of 12 bytes from a 16-byte stream (tinygltf keeps extension integers as int, so larger counts wrap).
TEST(GltfDecompress, DecodedSizesFromTheFileAreBoundedBeforeAllocation) {
  GltfBuilder b;
  unsigned char junk[16] = {};
  size_t offset = b.append(junk, sizeof(junk));
  int view = b.rawView(R"({"buffer":1,"byteLength":12,"byteStride":12,"extensions":{"EXT_meshopt_compression":{"buffer":0,
    "byteOffset":)" + std::to_string(offset) +
                       R"(,"byteLength":16,"byteStride":12,"count":2000000000,"mode":"ATTRIBUTES"}}})");
  int p = b.accessor(view, 5126, "VEC3", 1);
  std::string body = R"("extensionsUsed":["EXT_meshopt_compression"],)" + kNode +
                     R"("meshes":[{"primitives":[{"attributes":{"POSITION":)" + std::to_string(p) + "}}]}]";
  std::string fallback = R"({"byteLength":12,"extensions":{"EXT_meshopt_compression":{"fallback":true}}})";
  auto start = std::chrono::steady_clock::now();
  std::string msg = test::loadError(b.write(dir(), "meshopt_bomb", body, "0", fallback));
  EXPECT_NE(msg.find("EXT_meshopt_compression: buffer view 0: decoded data would pass the loader's limit"), std::string::npos)
      << msg;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

// gltfpack's instancing: EXPONENTIAL-filtered float translations and QUATERNION-filtered normalized short rotations
// (KHR_mesh_quantization), decoded and drawn per instance.
TEST(GltfDecompress, FilteredInstanceTransforms) {
  GltfBuilder b;
  IndexedMesh quad{{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, {0, 1, 2, 0, 2, 3}};
  int p = b.accessor(quad.positions, 5126, "VEC3", 4), i = b.accessor(quad.indices, 5125, "SCALAR", 6);
  std::vector<float> translations = {0, 0, 0, 0, 5, 0, 0, 0};  // xyz + pad: the exponential filter works per 4 bytes
  std::vector<float> rotations = {0, 0, 0, 1, 0, 0, 0.70710678f, 0.70710678f};  // identity, 90 degrees about z
  std::vector<uint32_t> exp(4 * 2);
  meshopt_encodeFilterExp(exp.data(), 2, 16, 15, translations.data());
  std::vector<int16_t> quat(4 * 2);
  meshopt_encodeFilterQuat(quat.data(), 2, 8, 12, rotations.data());
  auto compressed = [&](const void* data, size_t stride, const char* filter, size_t fallbackOffset) {
    std::vector<unsigned char> out(meshopt_encodeVertexBufferBound(2, stride));
    out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), data, 2, stride));
    size_t offset = b.append(out.data(), out.size());
    return b.rawView(R"({"buffer":1,"byteOffset":)" + std::to_string(fallbackOffset) + R"(,"byteLength":)" +
                     std::to_string(2 * stride) + R"(,"byteStride":)" + std::to_string(stride) +
                     R"(,"extensions":{"EXT_meshopt_compression":{"buffer":0,"byteOffset":)" + std::to_string(offset) +
                     R"(,"byteLength":)" + std::to_string(out.size()) + R"(,"byteStride":)" + std::to_string(stride) +
                     R"(,"count":2,"mode":"ATTRIBUTES","filter":")" + filter + R"("}}})");
  };
  int t = b.accessor(compressed(exp.data(), 16, "EXPONENTIAL", 0), 5126, "VEC3", 2);
  int r = b.accessor(compressed(quat.data(), 8, "QUATERNION", 32), 5122, "VEC4", 2, R"("normalized":true)");
  std::string body = R"("extensionsUsed":["EXT_meshopt_compression","KHR_mesh_quantization","EXT_mesh_gpu_instancing"],
    "nodes":[{"mesh":0,"extensions":{"EXT_mesh_gpu_instancing":{"attributes":{"TRANSLATION":)" +
                     std::to_string(t) + R"(,"ROTATION":)" + std::to_string(r) + "}}}}]," + mesh(p, i);
  std::string fallback = R"({"byteLength":48,"extensions":{"EXT_meshopt_compression":{"fallback":true}}})";
  Scene s = loadGltf(b.write(dir(), "instances_filtered", body, "0", fallback));
  ASSERT_EQ(s.triangleCount(), 4u);
  EXPECT_NEAR(glm::length(s.positions[1] - glm::vec3(1, 0, 0)), 0.0f, 1e-4f) << "instance 0: identity";
  EXPECT_NEAR(glm::length(s.positions[7] - glm::vec3(5, 1, 0)), 0.0f, 1e-3f) << "instance 1: +x turned to +y, then +5 x";
}

// The shared models (when present): their geometry compressed both ways decodes to what the plain file gives, and
// normal-mapped ones get unit tangents perpendicular to their normals.
TEST(GltfDecompress, SharedModelsRoundTrip) {
  int found = 0;
  for (const char* model : {"DamagedHelmet/DamagedHelmet.gltf", "SimpleMeshes/SimpleMeshes.gltf", "Box/Box.gltf"}) {
    std::string path = std::string(VKMC_SHARED_SCENES) + "/" + model;
    if (!std::filesystem::exists(path)) continue;
    ++found;
    Scene scene = loadGltf(path);
    if (std::string(model).find("DamagedHelmet") != std::string::npos) {  // normal-mapped, with TEXCOORD_0
      EXPECT_EQ(scene.tangents.size(), scene.positions.size());
      EXPECT_EQ(scene.uv0.size(), scene.positions.size());
    }
    for (size_t c = 0; c < scene.tangents.size(); ++c) {
      ASSERT_NEAR(glm::length(glm::vec3(scene.tangents[c])), 1.0f, 1e-4f) << model;
      ASSERT_NEAR(glm::dot(glm::vec3(scene.tangents[c]), scene.normals[c]), 0.0f, 1e-4f) << model;
    }
    IndexedMesh soup;  // the flattened triangles, as a mesh of their own
    for (const glm::vec3& p : scene.positions) soup.positions.insert(soup.positions.end(), {p.x, p.y, p.z});
    for (uint32_t i = 0; i < scene.positions.size(); ++i) soup.indices.push_back(i);
    roundTrip(std::filesystem::path(model).stem().string(), soup);
  }
  if (found == 0) GTEST_SKIP() << "no shared models under " << VKMC_SHARED_SCENES;
}
