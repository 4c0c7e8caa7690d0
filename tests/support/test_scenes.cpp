// glTF writer for tests.
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include <stb/stb_image_write.h>
#include <webp/encode.h>

#include "error.h"
#include "lab_world.h"

namespace vkmc::test {

std::filesystem::path makeTempDir(const std::string& tag) {
  std::random_device rd;
  auto dir = std::filesystem::temp_directory_path() / ("vkmc-" + tag + "-" + std::to_string(rd()));
  std::filesystem::create_directories(dir);
  return dir;
}

GltfSpec quadSpec() {
  GltfSpec s;
  s.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  s.indices = {0, 1, 2, 0, 2, 3};
  return s;
}

std::string writeGltf(const std::filesystem::path& dir, const std::string& name, const GltfSpec& spec) {
  std::string bin;
  auto append = [&](const void* p, size_t n) { bin.append(static_cast<const char*>(p), n); };
  append(spec.positions.data(), spec.positions.size() * 4);
  size_t posBytes = bin.size();
  size_t indexBytes = 0;
  if (!spec.indices.empty()) {
    for (uint32_t i : spec.indices) {
      if (spec.indexComponentType == 5121) {
        uint8_t v = static_cast<uint8_t>(i);
        append(&v, 1);
      } else if (spec.indexComponentType == 5123) {
        uint16_t v = static_cast<uint16_t>(i);
        append(&v, 2);
      } else
        append(&i, 4);
    }
    indexBytes = bin.size() - posBytes;
  }
  float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
  for (size_t i = 0; i < spec.positions.size(); ++i) {
    if (!std::isfinite(spec.positions[i])) continue;  // min/max must stay valid JSON
    lo[i % 3] = std::min(lo[i % 3], spec.positions[i]);
    hi[i % 3] = std::max(hi[i % 3], spec.positions[i]);
  }
  size_t vertexCount = spec.positionCountOverride >= 0 ? spec.positionCountOverride : spec.positions.size() / 3;
  std::ostringstream j;
  j << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)";
  j << R"("nodes":[{"mesh":0)" << (spec.nodeExtra.empty() ? "" : "," + spec.nodeExtra) << "}],";
  j << R"("materials":[)" << spec.materialJson << "],";
  j << R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0,"mode":)" << spec.mode;
  if (!spec.indices.empty()) j << R"(,"indices":1)";
  j << "}]}],";
  j << R"("accessors":[{"bufferView":0,"componentType":5126,"type":"VEC3","count":)" << vertexCount << R"(,"min":[)" << lo[0]
    << "," << lo[1] << "," << lo[2] << R"(],"max":[)" << hi[0] << "," << hi[1] << "," << hi[2] << "]}";
  if (!spec.indices.empty())
    j << R"(,{"bufferView":1,"componentType":)" << spec.indexComponentType << R"(,"type":"SCALAR","count":)"
      << spec.indices.size() << "}";
  j << "],";
  j << R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":)" << posBytes << "}";
  if (!spec.indices.empty()) j << R"(,{"buffer":0,"byteOffset":)" << posBytes << R"(,"byteLength":)" << indexBytes << "}";
  j << "],";
  j << R"("buffers":[{"byteLength":)" << bin.size() << R"(,"uri":")" << name << R"(.bin"}]})";
  auto gltf = dir / (name + ".gltf");
  std::ofstream(gltf) << withLabWorld(j.str());
  if (spec.writeBin) std::ofstream(dir / (name + ".bin"), std::ios::binary) << bin;
  return gltf.string();
}

std::string writeQuadsGltf(const std::filesystem::path& dir, const std::string& name, const std::vector<QuadSpec>& quads,
                           const std::string& materialsJson, const std::string& rootExtra) {
  std::string bin;
  std::ostringstream nodes, meshes, accessors, views;
  for (size_t q = 0; q < quads.size(); ++q) {
    const QuadSpec& s = quads[q];
    float p[12], lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
    for (int c = 0; c < 3; ++c) {
      p[c] = s.o[c], p[3 + c] = s.o[c] + s.u[c], p[6 + c] = s.o[c] + s.u[c] + s.v[c], p[9 + c] = s.o[c] + s.v[c];
      for (int k = 0; k < 4; ++k) lo[c] = std::min(lo[c], p[3 * k + c]), hi[c] = std::max(hi[c], p[3 * k + c]);
    }
    const float uv[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    const uint32_t idx[6] = {0, 1, 2, 0, 2, 3};
    size_t base = bin.size();
    bin.append(reinterpret_cast<const char*>(p), sizeof(p));
    bin.append(reinterpret_cast<const char*>(uv), sizeof(uv));
    bin.append(reinterpret_cast<const char*>(idx), sizeof(idx));
    size_t a = 3 * q;
    const char* sep = q ? "," : "";
    nodes << sep << R"({"mesh":)" << q << "}";
    meshes << sep << R"({"primitives":[{"attributes":{"POSITION":)" << a << R"(,"TEXCOORD_0":)" << a + 1 << R"(},"indices":)"
           << a + 2 << R"(,"material":)" << s.material << "}]}";
    accessors << sep << R"({"bufferView":)" << a << R"(,"componentType":5126,"type":"VEC3","count":4,"min":[)" << lo[0] << ","
              << lo[1] << "," << lo[2] << R"(],"max":[)" << hi[0] << "," << hi[1] << "," << hi[2] << "]}";
    accessors << R"(,{"bufferView":)" << a + 1 << R"(,"componentType":5126,"type":"VEC2","count":4})";
    accessors << R"(,{"bufferView":)" << a + 2 << R"(,"componentType":5125,"type":"SCALAR","count":6})";
    views << sep << R"({"buffer":0,"byteOffset":)" << base << R"(,"byteLength":48})";
    views << R"(,{"buffer":0,"byteOffset":)" << base + 48 << R"(,"byteLength":32})";
    views << R"(,{"buffer":0,"byteOffset":)" << base + 80 << R"(,"byteLength":24})";
  }
  std::ostringstream j;
  j << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[)";
  for (size_t q = 0; q < quads.size(); ++q) j << (q ? "," : "") << q;
  j << "]}],";
  j << R"("nodes":[)" << nodes.str() << R"(],"meshes":[)" << meshes.str() << R"(],"materials":[)" << materialsJson << "],";
  j << R"("accessors":[)" << accessors.str() << R"(],"bufferViews":[)" << views.str() << "],";
  if (!rootExtra.empty()) j << rootExtra << ",";
  j << R"("buffers":[{"byteLength":)" << bin.size() << R"(,"uri":")" << name << R"(.bin"}]})";
  auto gltf = dir / (name + ".gltf");
  std::ofstream(gltf) << withLabWorld(j.str());
  std::ofstream(dir / (name + ".bin"), std::ios::binary) << bin;
  return gltf.string();
}

std::string writePng(const std::filesystem::path& dir, const std::string& name, int w, int h, const std::vector<uint8_t>& rgba) {
  std::string file = name + ".png";
  if (!stbi_write_png((dir / file).c_str(), w, h, 4, rgba.data(), w * 4)) throw Error("cannot write test PNG " + file);
  return file;
}

std::string writeWebp(const std::filesystem::path& dir, const std::string& name, int w, int h, const std::vector<uint8_t>& rgba) {
  uint8_t* encoded = nullptr;
  const size_t size = WebPEncodeLosslessRGBA(rgba.data(), w, h, w * 4, &encoded);
  std::string file = name + ".webp";
  std::ofstream out(dir / file, std::ios::binary);
  out.write(reinterpret_cast<const char*>(encoded), std::streamsize(size));
  WebPFree(encoded);
  if (size == 0 || !out) throw Error("cannot write test WebP " + file);
  return file;
}

std::string loadError(const std::string& path, const LoadLimits& limits) {
  try {
    loadGltf(path, limits);
  } catch (const Error& e) {
    std::string msg = e.what();
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "not one line: " << msg;
    return msg;
  }
  return "";
}

}  // namespace vkmc::test
