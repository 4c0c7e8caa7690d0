#include "bench/benchmark_rays.h"

#include <cstring>
#include <fstream>

#include "../shaders/shared/geometry.h"
#include "../shaders/shared/rng.h"
#include "../shaders/shared/sampling.h"
#include "error.h"
#include "io/exr.h"
#include "io/output_files.h"
#include "bench/ray_tracer.h"
#include "scene/framing.h"
#include "scene/camera_rig.h"

namespace vkmc {

BenchmarkRays makeBenchmarkRays(const Scene& scene, const Bvh& bvh, RayTracer& tracer, uint32_t width, uint32_t height) {
  Camera cam = scene.cameras.empty() ? autoCamera(framingBounds(scene).bounds, float(width) / float(height)) : scene.cameras[0];
  CameraRig rig = makeCameraRig(cam, width, height);
  BenchmarkRays rays;
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      glm::vec2 s(2.0f * (x + 0.5f) / width - 1.0f, 1.0f - 2.0f * (y + 0.5f) / height);
      glm::vec3 o = rig.origin, d = rig.forward;
      if (rig.orthographic)
        o += s.x * rig.right + s.y * rig.up;
      else
        d = glm::normalize(rig.forward + s.x * rig.right + s.y * rig.up);
      rays.primary.push_back({glm::vec4(o, 3e38f), glm::vec4(d, 0.0f)});
    }
  std::vector<glm::vec4> hits = tracer.trace(rays.primary, false);
  for (size_t i = 0; i < hits.size(); ++i) {
    uint32_t tri = glm::floatBitsToUint(hits[i].w);
    if (tri == gpu::kMissPrimitive) continue;
    const glm::vec3* v = &scene.positions[3 * bvh.triangleOrder[tri]];
    glm::vec3 b(1.0f - hits[i].y - hits[i].z, hits[i].y, hits[i].z);
    glm::vec3 p = b.x * v[0] + b.y * v[1] + b.z * v[2];
    glm::vec3 n = glm::normalize(glm::vec3(gpu::scaledTriangleCross(v[0], v[1], v[2])));
    if (glm::dot(n, glm::vec3(rays.primary[i].direction)) > 0.0f) n = -n;
    for (uint32_t k = 0; k < 4; ++k) {
      uint32_t key = gpu::pathKey(99u, static_cast<uint32_t>(i), k);
      glm::vec3 w =
          gpu::basisFromNormal(n) * gpu::sampleCosineHemisphere(glm::vec2(gpu::randomUnit(key, 0), gpu::randomUnit(key, 1)));
      glm::vec3 o = gpu::offsetRayOrigin(p, gpu::barycentricError(b, v[0], v[1], v[2]), n, w);
      rays.diffuse.push_back({glm::vec4(o, 3e38f), glm::vec4(w, 0.0f)});
    }
  }
  return rays;
}

namespace {
constexpr char kRayMagic[8] = {'V', 'K', 'M', 'C', 'R', 'A', 'Y', 'S'};
}

void writeRays(const std::string& path, const std::vector<gpu::TestRay>& rays) {
  std::string bytes(kRayMagic, sizeof(kRayMagic));
  uint32_t n = static_cast<uint32_t>(rays.size());
  bytes.append(reinterpret_cast<const char*>(&n), sizeof(n));
  bytes.append(reinterpret_cast<const char*>(rays.data()), rays.size() * sizeof(gpu::TestRay));
  writeFileAtomically(path, bytes);
}

std::vector<gpu::TestRay> readRays(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open ray file " + path);
  char magic[8];
  uint32_t n = 0;
  if (!in.read(magic, 8) || std::memcmp(magic, kRayMagic, 8) != 0 || !in.read(reinterpret_cast<char*>(&n), 4))
    throw Error(path + " is not a vkmc ray dump");
  if (n > (1u << 28)) throw Error(path + ": implausible ray count " + std::to_string(n));
  std::vector<gpu::TestRay> rays(n);
  if (!in.read(reinterpret_cast<char*>(rays.data()), std::streamsize(n) * sizeof(gpu::TestRay)))
    throw Error(path + " is truncated");
  return rays;
}

}  // namespace vkmc
