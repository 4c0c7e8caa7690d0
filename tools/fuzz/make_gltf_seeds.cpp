// Writes glTF seeds for gltf_fuzzer that the repository's scenes do not cover: Draco and meshopt meshes (written by
// the libraries' own encoders) and textures whose images are embedded (PNG, JPEG and WebP in buffer views, a PNG
// as a data: URI, EXT_texture_webp with its PNG fallback), and the same images as files for image_fuzzer.
// Usage: vkmc-fuzz-seeds GLTF_FOLDER IMAGE_FOLDER (tools/fuzz.sh).
#include <stb/stb_image_write.h>
#include <webp/encode.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/compressed_meshes.h"
#include "support/gltf_builder.h"

using namespace vkmc::test;

namespace {

// A 4x4 RGBA gradient, the texels every image seed holds.
std::vector<unsigned char> texels() {
  std::vector<unsigned char> rgba;
  for (int i = 0; i < 16; ++i) rgba.insert(rgba.end(), {(unsigned char)(16 * i), (unsigned char)(255 - 16 * i), 128, 255});
  return rgba;
}

void collect(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
}

std::string encoded(const char* format) {
  const std::vector<unsigned char> rgba = texels();
  std::string bytes;
  if (std::string(format) == "png") stbi_write_png_to_func(collect, &bytes, 4, 4, 4, rgba.data(), 16);
  if (std::string(format) == "jpeg") stbi_write_jpg_to_func(collect, &bytes, 4, 4, 4, rgba.data(), 90);
  if (std::string(format) == "webp") {
    uint8_t* out = nullptr;
    size_t size = WebPEncodeLosslessRGBA(rgba.data(), 4, 4, 16, &out);
    bytes.assign(reinterpret_cast<const char*>(out), size);
    WebPFree(out);
  }
  return bytes;
}

std::string base64(const std::string& bytes) {
  const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const size_t chunk = std::min<size_t>(3, bytes.size() - i);
    uint32_t n = 0;
    for (size_t k = 0; k < 3; ++k) n = n << 8 | (k < chunk ? uint32_t((unsigned char)bytes[i + k]) : 0u);
    out += digits[(n >> 18) & 63];
    out += digits[(n >> 12) & 63];
    out += chunk > 1 ? digits[(n >> 6) & 63] : '=';
    out += chunk > 2 ? digits[n & 63] : '=';
  }
  return out;
}

// A textured grid whose base colour and emission come from `images` (JSON image objects) through `textures`.
std::string texturedGrid(const std::filesystem::path& dir, const std::string& name, GltfBuilder& b, const std::string& images,
                         const std::string& textures, const std::string& extensions = "") {
  const IndexedMesh m = grid(4);
  int p = b.accessor(m.positions, 5126, "VEC3", m.vertices()), i = b.accessor(m.indices, 5125, "SCALAR", m.indices.size());
  int uv = b.accessor(m.uvs, 5126, "VEC2", m.vertices());
  const std::string body = extensions + R"("nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":)" +
                           std::to_string(p) + R"(,"TEXCOORD_0":)" + std::to_string(uv) + R"(},"indices":)" + std::to_string(i) +
                           R"(,"material":0}]}],"materials":[{"pbrMetallicRoughness":{"baseColorTexture":
      {"index":0}},"emissiveTexture":{"index":1},"emissiveFactor":[1,1,1]}],"images":[)" +
                           images + R"(],"textures":[)" + textures + "]";
  return toGlb(b.write(dir, name, body));
}

std::string viewImage(GltfBuilder& b, const char* format, const char* mime) {
  const std::string bytes = encoded(format);
  return R"({"bufferView":)" + std::to_string(b.view(bytes.data(), bytes.size())) + R"(,"mimeType":")" + mime + "\"}";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: vkmc-fuzz-seeds GLTF_FOLDER IMAGE_FOLDER\n");
    return 2;
  }
  const std::filesystem::path dir = argv[1], imageDir = argv[2];
  std::filesystem::create_directories(dir);
  std::filesystem::create_directories(imageDir);
  for (const char* format : {"png", "jpeg", "webp"})
    std::ofstream(imageDir / (std::string("seed.") + format), std::ios::binary) << encoded(format);
  const IndexedMesh m = grid(5);
  toGlb(writeDraco(dir, "draco", m, 14, true));
  toGlb(writeDraco(dir, "draco_edgebreaker", m, 11, false));
  toGlb(writeMeshopt(dir, "meshopt", m));
  {
    GltfBuilder b;
    const std::string png = viewImage(b, "png", "image/png"), jpeg = viewImage(b, "jpeg", "image/jpeg");
    texturedGrid(dir, "embedded_png_jpeg", b, png + "," + jpeg, R"({"source":0},{"source":1})");
  }
  {
    GltfBuilder b;
    const std::string webp = viewImage(b, "webp", "image/webp"), png = viewImage(b, "png", "image/png");
    texturedGrid(dir, "embedded_webp", b, webp + "," + png,
                 R"({"source":1,"extensions":{"EXT_texture_webp":{"source":0}}},{"source":0})",
                 R"("extensionsUsed":["EXT_texture_webp"],)");
  }
  {
    GltfBuilder b;
    const std::string uri = R"({"uri":"data:image/png;base64,)" + base64(encoded("png")) + "\"}";
    texturedGrid(dir, "data_uri_png", b, uri, R"({"source":0},{"source":0})");
  }
  return 0;
}
