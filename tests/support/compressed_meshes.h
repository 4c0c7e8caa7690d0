// Meshes written compressed with the libraries' own encoders (KHR_draco_mesh_compression, EXT_meshopt_compression),
// for the decompression tests and the fuzzer's seeds (no binary models in the repository).
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace vkmc::test {

struct IndexedMesh {
  std::vector<float> positions;  // xyz per vertex
  std::vector<uint32_t> indices;
  std::vector<float> uvs;  // uv per vertex, or empty
  size_t vertices() const { return positions.size() / 3; }
};

// glTF members: one node drawing mesh 0, and mesh 0 as one primitive over accessors (uv < 0: no TEXCOORD_0).
inline const std::string kNode = R"("nodes":[{"mesh":0}],)";
std::string mesh(int position, int indices, int uv = -1);

// An n x n grid of vertices over a bumpy surface.
IndexedMesh grid(int n);
// dir/name.gltf with an external dir/name.bin; each returns the .gltf's path.
std::string writePlain(const std::filesystem::path& dir, const std::string& name, const IndexedMesh& m);
// Draco-encoded, positions quantized to `bits`; sequential encoding keeps the face order, edgebreaker does not.
// `corrupt` truncates the Draco data.
std::string writeDraco(const std::filesystem::path& dir, const std::string& name, const IndexedMesh& m, int bits, bool sequential,
                       bool corrupt = false);
// meshopt-encoded positions (ATTRIBUTES), indices (TRIANGLES) and octahedral-filtered byte normals, with a
// fallback buffer that has no data, as gltfpack writes them. `corrupt` shortens the compressed views.
std::string writeMeshopt(const std::filesystem::path& dir, const std::string& name, const IndexedMesh& m, bool corrupt = false);
// The .gltf (one external buffer 0) as a .glb beside it, with buffer 0 in its BIN chunk; returns the .glb's path.
std::string toGlb(const std::string& gltfPath);

}  // namespace vkmc::test
