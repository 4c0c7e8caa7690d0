// Single-sided faces the camera looks through, found by walking camera rays on the host and removed.
#include "bvh/seen_through_faces.h"

#include <algorithm>
#include <atomic>
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

// Per input triangle, what a camera ray that meets it from behind does: stops (two-sided and transmissive faces, as
// in the kernels), passes (a single-sided emitter: culled there, but kept in the scene) or passes and removes it.
enum class FromBehind : uint8_t { Stops, Passes, Removes };
std::vector<FromBehind> fromBehindRule(const Scene& scene) {
  std::vector<FromBehind> rule(scene.triangleCount(), FromBehind::Stops);
  for (size_t i = 0; i < rule.size(); ++i) {
    const Material& m = scene.materials[scene.materialIds[i]];
    if (m.culledFromBehind()) rule[i] = m.isEmissive() ? FromBehind::Passes : FromBehind::Removes;
  }
  return rule;
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

// Marks in `seen` the removable triangles one ray meets from behind before it stops.
void markAlongRay(const Bvh& bvh, std::span<const glm::vec3> ordered, const std::vector<FromBehind>& rule, Ray ray,
                  std::vector<Pending>& pending, std::vector<std::atomic<uint8_t>>& seen) {
  pending.clear();
  float stop = walkHost(bvh, ordered, ray.origin, ray.dir, std::numeric_limits<float>::infinity(),
                        [&](uint32_t tri, float t, bool fromBehind, float tMax) {
                          uint32_t input = bvh.triangleOrder[tri];
                          if (!fromBehind || rule[input] == FromBehind::Stops) return t;  // the ray stops here
                          if (rule[input] == FromBehind::Removes) pending.push_back({input, t});
                          return tMax;
                        });
  for (const Pending& p : pending)
    if (p.t < stop) seen[p.triangle].store(1, std::memory_order_relaxed);
}

}  // namespace

SeenThrough removeSeenThroughFaces(Scene& scene, const Camera& camera, uint32_t width, uint32_t height) {
  SeenThrough out;
  const std::vector<FromBehind> rule = fromBehindRule(scene);
  if (std::find(rule.begin(), rule.end(), FromBehind::Removes) == rule.end()) return out;
  const Bvh bvh = buildBvh(scene.triangleBounds());
  std::vector<glm::vec3> ordered(scene.positions.size());
  for (size_t i = 0; i < bvh.triangleOrder.size(); ++i)
    for (int k = 0; k < 3; ++k) ordered[3 * i + k] = scene.positions[3 * bvh.triangleOrder[i] + k];
  // The image's field of view (its rig), sampled on a grid no wider than kSeenThroughRaysAcross.
  const CameraRig rig = makeCameraRig(camera, width, height);
  const float scale = std::min(1.0f, float(kSeenThroughRaysAcross) / float(std::max(width, height)));
  const uint32_t gridW = std::max(1u, uint32_t(std::lround(float(width) * scale)));
  const uint32_t gridH = std::max(1u, uint32_t(std::lround(float(height) * scale)));
  // Rows split among the threads; the marks are idempotent, so relaxed stores to one array suffice.
  const uint32_t threads = std::clamp(std::min(std::thread::hardware_concurrency(), gridH), 1u, 16u);
  std::vector<std::atomic<uint8_t>> seen(rule.size());
  std::vector<std::thread> workers;
  for (uint32_t w = 0; w < threads; ++w)
    workers.emplace_back([&, w] {
      std::vector<Pending> pending;
      for (uint32_t y = w; y < gridH; y += threads)
        for (uint32_t x = 0; x < gridW; ++x)
          markAlongRay(bvh, ordered, rule, pixelCentreRay(rig, x, y, gridW, gridH), pending, seen);
    });
  for (std::thread& t : workers) t.join();
  std::vector<uint8_t> drop(seen.size());
  for (size_t i = 0; i < seen.size(); ++i) drop[i] = seen[i].load(std::memory_order_relaxed);
  out.rays = uint64_t(gridW) * gridH;
  const uint64_t removed = uint64_t(std::count(drop.begin(), drop.end(), 1));
  // A scene the eye sees only from behind would be left empty: it is kept whole (what the camera sees of it, the
  // backdrop through culled faces, is the same; an empty scene has no BVH).
  if (removed == 0 || removed == rule.size()) return out;
  out.triangles = removed;
  dropTriangles(scene, drop);
  return out;
}

}  // namespace vkmc
