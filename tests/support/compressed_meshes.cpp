#include "support/compressed_meshes.h"

#include <meshoptimizer.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "error.h"
#include "scene/draco_codec.h"
#include "support/gltf_builder.h"

namespace vkmc::test {
std::string mesh(int position, int indices, int uv) {
  return R"("meshes":[{"primitives":[{"attributes":{"POSITION":)" + std::to_string(position) +
         (uv >= 0 ? R"(,"TEXCOORD_0":)" + std::to_string(uv) : "") + R"(},"indices":)" + std::to_string(indices) + "}]}]";
}

IndexedMesh grid(int n) {
  IndexedMesh m;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      m.positions.insert(m.positions.end(), {float(x), float(y), 0.3f * std::sin(float(x + 2 * y))});
      m.uvs.insert(m.uvs.end(), {float(x) / float(n - 1), float(y) / float(n - 1)});
    }
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      uint32_t a = y * n + x, b = a + 1, c = a + n, d = c + 1;
      m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
    }
  return m;
}

std::string writePlain(const std::filesystem::path& dir, const std::string& name, const IndexedMesh& m) {
  GltfBuilder b;
  int p = b.accessor(m.positions, 5126, "VEC3", m.vertices()), i = b.accessor(m.indices, 5125, "SCALAR", m.indices.size());
  int uv = m.uvs.empty() ? -1 : b.accessor(m.uvs, 5126, "VEC2", m.vertices());
  return b.write(dir, name, kNode + mesh(p, i, uv));
}

std::string writeDraco(const std::filesystem::path& dir, const std::string& name, const IndexedMesh& m, int bits, bool sequential,
                       bool corrupt) {
  DracoEncoded encoded = encodeDracoMesh(m.positions, m.uvs, m.indices, bits, sequential);
  std::vector<char>& bytes = encoded.bytes;
  if (bytes.empty()) throw Error("the Draco encoder wrote nothing for " + name);
  if (corrupt) bytes.resize(bytes.size() / 2);  // truncated
  GltfBuilder b;
  int view = b.view(bytes.data(), bytes.size());
  int p = b.accessor(-1, 5126, "VEC3", m.vertices()), i = b.accessor(-1, 5125, "SCALAR", m.indices.size());
  std::string attributes = R"("POSITION":)" + std::to_string(p), mapping = R"("POSITION":)" + std::to_string(encoded.positionId);
  if (!m.uvs.empty()) {
    attributes += R"(,"TEXCOORD_0":)" + std::to_string(b.accessor(-1, 5126, "VEC2", m.vertices()));
    mapping += R"(,"TEXCOORD_0":)" + std::to_string(encoded.uvId);
  }
  std::string body = R"("extensionsUsed":["KHR_draco_mesh_compression"],"extensionsRequired":["KHR_draco_mesh_compression"],)" +
                     kNode + R"("meshes":[{"primitives":[{"attributes":{)" + attributes + R"(},"indices":)" + std::to_string(i) +
                     R"(,"extensions":{"KHR_draco_mesh_compression":{"bufferView":)" + std::to_string(view) +
                     R"(,"attributes":{)" + mapping + "}}}}]}]";
  return b.write(dir, name, body);
}

std::string writeMeshopt(const std::filesystem::path& dir, const std::string& name, const IndexedMesh& m, bool corrupt) {
  GltfBuilder b;
  size_t n = m.vertices();
  auto compressedView = [&](const std::vector<unsigned char>& data, size_t fallbackOffset, size_t stride, size_t count,
                            const char* mode, const char* filter) {
    size_t offset = b.append(data.data(), data.size());
    std::string ext = R"({"buffer":0,"byteOffset":)" + std::to_string(offset) + R"(,"byteLength":)" +
                      std::to_string(corrupt ? 4 : data.size()) + R"(,"byteStride":)" + std::to_string(stride) + R"(,"count":)" +
                      std::to_string(count) + R"(,"mode":")" + mode + R"(","filter":")" + filter + "\"}";
    return b.rawView(R"({"buffer":1,"byteOffset":)" + std::to_string(fallbackOffset) + R"(,"byteLength":)" +
                     std::to_string(count * stride) +
                     (std::string(mode) == "ATTRIBUTES" ? R"(,"byteStride":)" + std::to_string(stride) : "") +
                     R"(,"extensions":{"EXT_meshopt_compression":)" + ext + "}}");
  };
  std::vector<unsigned char> vb(meshopt_encodeVertexBufferBound(n, 12));
  vb.resize(meshopt_encodeVertexBuffer(vb.data(), vb.size(), m.positions.data(), n, 12));
  std::vector<unsigned char> ib(meshopt_encodeIndexBufferBound(m.indices.size(), n));
  ib.resize(meshopt_encodeIndexBuffer(ib.data(), ib.size(), m.indices.data(), m.indices.size()));
  std::vector<float> up;  // a tilted unit normal per vertex (x, y, z, w)
  for (size_t v = 0; v < n; ++v) up.insert(up.end(), {0.6f, 0.0f, 0.8f, 0.0f});
  std::vector<int8_t> oct(4 * n);
  meshopt_encodeFilterOct(oct.data(), n, 4, 8, up.data());
  std::vector<unsigned char> nb(meshopt_encodeVertexBufferBound(n, 4));
  nb.resize(meshopt_encodeVertexBuffer(nb.data(), nb.size(), oct.data(), n, 4));
  int pv = compressedView(vb, 0, 12, n, "ATTRIBUTES", "NONE");
  int iv = compressedView(ib, 12 * n, 4, m.indices.size(), "TRIANGLES", "NONE");
  int nv = compressedView(nb, 12 * n + 4 * m.indices.size(), 4, n, "ATTRIBUTES", "OCTAHEDRAL");
  int p = b.accessor(pv, 5126, "VEC3", n), i = b.accessor(iv, 5125, "SCALAR", m.indices.size());
  int normal = b.accessor(nv, 5120, "VEC3", n, R"("normalized":true)");
  size_t fallbackBytes = 12 * n + 4 * m.indices.size() + 4 * n;
  std::string body = R"("extensionsUsed":["EXT_meshopt_compression","KHR_mesh_quantization"],
    "extensionsRequired":["EXT_meshopt_compression","KHR_mesh_quantization"],)" +
                     kNode + R"("meshes":[{"primitives":[{"attributes":{"POSITION":)" + std::to_string(p) + R"(,"NORMAL":)" +
                     std::to_string(normal) + R"(},"indices":)" + std::to_string(i) + "}]}]";
  std::string fallback =
      R"({"byteLength":)" + std::to_string(fallbackBytes) + R"(,"extensions":{"EXT_meshopt_compression":{"fallback":true}}})";
  return b.write(dir, name, body, "0", fallback);
}

std::string toGlb(const std::string& gltfPath) {
  std::ifstream in(gltfPath);
  nlohmann::json doc = nlohmann::json::parse(in);
  std::filesystem::path binPath = std::filesystem::path(gltfPath).parent_path() / doc["buffers"][0]["uri"].get<std::string>();
  doc["buffers"][0].erase("uri");
  std::ifstream binIn(binPath, std::ios::binary);
  std::string bin((std::istreambuf_iterator<char>(binIn)), std::istreambuf_iterator<char>());
  std::string json = doc.dump();
  while (json.size() % 4) json += ' ';
  while (bin.size() % 4) bin += '\0';
  std::string glb;
  auto word = [&](uint32_t w) { glb.append(reinterpret_cast<const char*>(&w), 4); };
  word(0x46546C67u), word(2), word(uint32_t(12 + 8 + json.size() + 8 + bin.size()));
  word(uint32_t(json.size())), word(0x4E4F534Au), glb += json;
  word(uint32_t(bin.size())), word(0x004E4942u), glb += bin;
  std::string path = gltfPath.substr(0, gltfPath.size() - 5) + ".glb";
  std::ofstream(path, std::ios::binary) << glb;
  return path;
}

}  // namespace vkmc::test
