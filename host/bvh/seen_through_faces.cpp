// Single-sided faces the camera looks through, found by walking camera rays on the host and removed.
#include "bvh/seen_through_faces.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <thread>

#include "bvh/bvh.h"
#include "scene/camera_rig.h"

namespace vkmc {
namespace {

struct Ray {
  glm::vec3 origin, dir;
};

// The ray through pixel (x + 0.5, y + 0.5) of a width x height grid, as the camera kernel makes it unjittered.
Ray pixelCentreRay(const CameraRig& rig, uint32_t x, uint32_t y, uint32_t width, uint32_t height) {
  glm::vec2 screen(2.0f * (float(x) + 0.5f) / float(width) - 1.0f, 1.0f - 2.0f * (float(y) + 0.5f) / float(height));
  if (rig.orthographic) return {rig.origin + screen.x * rig.right + screen.y * rig.up, rig.forward};
  return {rig.origin, glm::normalize(rig.forward + screen.x * rig.right + screen.y * rig.up)};
}

// Per input triangle: may a ray pass it from behind and have it removed (single-sided, not emissive)?
std::vector<uint8_t> passableFromBehind(const Scene& scene) {
  std::vector<uint8_t> passable(scene.triangleCount(), 0);
  for (size_t i = 0; i < passable.size(); ++i) {
    const Material& m = scene.materials[scene.materialIds[i]];
    passable[i] = m.culledFromBehind() && !m.isEmissive();
  }
  return passable;
}

// Keeps the triangles not marked in `drop`, every per-corner array with them.
void dropTriangles(Scene& scene, const std::vector<uint8_t>& drop) {
  auto compactCorners = [&](auto& corners) {
    if (corners.empty()) return;
    size_t out = 0;
    for (size_t tri = 0; tri < drop.size(); ++tri)
      if (!drop[tri])
        for (int k = 0; k < 3; ++k) corners[out++] = corners[3 * tri + k];
    corners.resize(out);
  };
  compactCorners(scene.positions), compactCorners(scene.normals), compactCorners(scene.uv0), compactCorners(scene.uv1);
  compactCorners(scene.tangents), compactCorners(scene.colors);
  size_t out = 0;
  for (size_t tri = 0; tri < drop.size(); ++tri)
    if (!drop[tri]) scene.materialIds[out++] = scene.materialIds[tri];
  scene.materialIds.resize(out);
}

struct Pending {
  uint32_t triangle;
  float t;
};

// Marks in `seen` the passable triangles one ray meets from behind before it stops.
void markAlongRay(const Bvh& bvh, std::span<const glm::vec3> ordered, const std::vector<uint8_t>& passable, Ray ray,
                  std::vector<Pending>& pending, std::vector<uint8_t>& seen) {
  pending.clear();
  float stop = walkHost(bvh, ordered, ray.origin, ray.dir, std::numeric_limits<float>::infinity(),
                        [&](uint32_t tri, float t, bool fromBehind, float tMax) {
                          uint32_t input = bvh.triangleOrder[tri];
                          if (!(fromBehind && passable[input])) return t;  // the ray stops here
                          pending.push_back({input, t});
                          return tMax;
                        });
  for (const Pending& p : pending)
    if (p.t < stop) seen[p.triangle] = 1;
}

}  // namespace

SeenThrough removeSeenThroughFaces(Scene& scene, const Camera& camera, uint32_t width, uint32_t height) {
  SeenThrough out;
  const std::vector<uint8_t> passable = passableFromBehind(scene);
  if (std::find(passable.begin(), passable.end(), 1) == passable.end()) return out;
  const Bvh bvh = buildBvh(scene.triangleBounds());
  std::vector<glm::vec3> ordered(scene.positions.size());
  for (size_t i = 0; i < bvh.triangleOrder.size(); ++i)
    for (int k = 0; k < 3; ++k) ordered[3 * i + k] = scene.positions[3 * bvh.triangleOrder[i] + k];
  const float scale = std::min(1.0f, float(kSeenThroughRaysAcross) / float(std::max(width, height)));
  const uint32_t gridW = std::max(1u, uint32_t(std::lround(float(width) * scale)));
  const uint32_t gridH = std::max(1u, uint32_t(std::lround(float(height) * scale)));
  const CameraRig rig = makeCameraRig(camera, gridW, gridH);
  // Rows split among the threads, each marking its own copy (the walks are independent).
  const uint32_t threads = std::clamp(std::thread::hardware_concurrency(), 1u, 16u);
  std::vector<std::vector<uint8_t>> seen(threads, std::vector<uint8_t>(passable.size(), 0));
  std::vector<std::thread> workers;
  for (uint32_t w = 0; w < threads; ++w)
    workers.emplace_back([&, w] {
      std::vector<Pending> pending;
      for (uint32_t y = w; y < gridH; y += threads)
        for (uint32_t x = 0; x < gridW; ++x)
          markAlongRay(bvh, ordered, passable, pixelCentreRay(rig, x, y, gridW, gridH), pending, seen[w]);
    });
  for (std::thread& t : workers) t.join();
  for (uint32_t w = 1; w < threads; ++w)
    for (size_t i = 0; i < passable.size(); ++i) seen[0][i] |= seen[w][i];
  out.rays = uint64_t(gridW) * gridH;
  out.triangles = uint64_t(std::count(seen[0].begin(), seen[0].end(), 1));
  if (out.triangles > 0) dropTriangles(scene, seen[0]);
  return out;
}

}  // namespace vkmc
