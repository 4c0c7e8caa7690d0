// tinybvh's builds and GPU conversions; the one translation unit with tinybvh's implementation.
#define TINYBVH_IMPLEMENTATION
#include "tiny_bvh.h"

#include "tinybvh_layouts.h"

#include <chrono>
#include <cstring>

#include "error.h"

namespace vkmc {

namespace {

std::vector<tinybvh::bvhvec4> triangleSoup(const Scene& scene) {
  std::vector<tinybvh::bvhvec4> v(scene.positions.size());
  for (size_t i = 0; i < v.size(); ++i)
    v[i] = tinybvh::bvhvec4(scene.positions[i].x, scene.positions[i].y, scene.positions[i].z, 0);
  if (v.empty()) throw Error("tinybvh: a scene without triangles");
  return v;
}

template <class T>
std::vector<glm::vec4> vec4s(const T* data, size_t bytes) {
  std::vector<glm::vec4> out(bytes / sizeof(glm::vec4));
  std::memcpy(out.data(), data, bytes);
  return out;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

TinybvhAilaLaine buildTinybvhAilaLaine(const Scene& scene, bool hq) {
  std::vector<tinybvh::bvhvec4> soup = triangleSoup(scene);
  const uint32_t triangles = uint32_t(soup.size() / 3);
  tinybvh::BVH_GPU bvh;
  auto start = std::chrono::steady_clock::now();
  hq ? bvh.BuildHQ(soup.data(), triangles) : bvh.Build(soup.data(), triangles);
  TinybvhAilaLaine out;
  out.buildSeconds = secondsSince(start);
  static_assert(sizeof(tinybvh::BVH_GPU::BVHNode) == 4 * sizeof(glm::vec4));
  out.nodes = vec4s(bvh.bvhNode, bvh.usedNodes * sizeof(tinybvh::BVH_GPU::BVHNode));
  out.indices.assign(bvh.bvh.primIdx, bvh.bvh.primIdx + bvh.bvh.idxCount);
  out.vertices = vec4s(soup.data(), soup.size() * sizeof(tinybvh::bvhvec4));
  return out;
}

TinybvhCwbvh buildTinybvhCwbvh(const Scene& scene, bool hq) {
  std::vector<tinybvh::bvhvec4> soup = triangleSoup(scene);
  const uint32_t triangles = uint32_t(soup.size() / 3);
  tinybvh::BVH8_CWBVH bvh;
  auto start = std::chrono::steady_clock::now();
  hq ? bvh.BuildHQ(soup.data(), triangles) : bvh.Build(soup.data(), triangles);
  TinybvhCwbvh out;
  out.buildSeconds = secondsSince(start);
  out.nodes = vec4s(bvh.bvh8Data, bvh.usedBlocks * sizeof(tinybvh::bvhvec4));
  out.triangles = vec4s(bvh.bvh8Tris, bvh.idxCount * 3 * sizeof(tinybvh::bvhvec4));  // uncompressed: 3 per triangle
  return out;
}

}  // namespace vkmc
