// Traversal baseline: the same incoherent rays traced by vkmc's closest-hit kernel (on the Vulkan device) and by
// Embree 3's rtcIntersect1 (on the host, the same number of threads as lavapipe's), in one run, side by side.
// Rays come from vkmc (bench/benchmark_rays.h: four diffuse bounce rays per primary hit), or from a dump
// (`--rays FILE`, written with `--dump DIR`). Built only when Debian's libembree-dev is installed; run with
// tools/embree_baseline.sh, which installs it.
#include <embree3/rtcore.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <thread>
#include <vector>

#include "app/malloc_tuning.h"
#include "error.h"
#include "io/exr.h"
#include "io/output_files.h"
#include "bench/benchmark_rays.h"
#include "render/gpu_scene.h"
#include "bench/ray_tracer.h"
#include "scene/gltf_loader.h"
#include "vk/context.h"

using namespace vkmc;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

struct EmbreeScene {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  float tnear = 0.0f;
  // robust: RTC_SCENE_FLAG_ROBUST, Embree's watertight mode (conservative bounds, no accuracy-reducing
  // shortcuts), the guarantee vkmc's walk always gives.
  EmbreeScene(const Scene& s, bool robust) {
    device = rtcNewDevice(nullptr);
    if (!device) throw Error("Embree: rtcNewDevice failed");
    scene = rtcNewScene(device);
    if (robust) {
      rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
      // vkmc takes hits at t > 0; the robust mode reports the surface a ray leaves at t = 0 (7.5% of the Cornell
      // box's rays). The default mode keeps tnear 0: the same answers, and 5-11% faster than with FLT_MIN.
      tnear = FLT_MIN;
    }
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    size_t n = s.triangleCount();
    auto* v = static_cast<float*>(
        rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * n));
    auto* idx = static_cast<uint32_t*>(
        rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), n));
    for (size_t i = 0; i < 3 * n; ++i) {
      v[3 * i] = s.positions[i].x, v[3 * i + 1] = s.positions[i].y, v[3 * i + 2] = s.positions[i].z;
      idx[i] = static_cast<uint32_t>(i);
    }
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene);
  }
  ~EmbreeScene() {
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
  }
};

// Closest hits of all rays with rtcIntersect1 on `threads` threads (interleaved chunks); returns seconds.
double traceEmbree(const EmbreeScene& es, const std::vector<gpu::TestRay>& rays, unsigned threads, std::vector<float>& t) {
  t.assign(rays.size(), INFINITY);
  std::atomic<size_t> next{0};
  const size_t chunk = 256;
  auto work = [&] {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (size_t begin; (begin = next.fetch_add(chunk)) < rays.size();) {
      for (size_t i = begin; i < std::min(rays.size(), begin + chunk); ++i) {
        const gpu::TestRay& r = rays[i];
        RTCRayHit rh{};
        rh.ray.org_x = r.origin.x, rh.ray.org_y = r.origin.y, rh.ray.org_z = r.origin.z;
        rh.ray.dir_x = r.direction.x, rh.ray.dir_y = r.direction.y, rh.ray.dir_z = r.direction.z;
        rh.ray.tnear = es.tnear;
        rh.ray.tfar = r.origin.w;
        rh.ray.mask = 0xffffffffu;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(es.scene, &context, &rh);
        if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) t[i] = rh.ray.tfar;
      }
    }
  };
  auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> pool;
  for (unsigned k = 1; k < threads; ++k) pool.emplace_back(work);
  work();
  for (std::thread& th : pool) th.join();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  vkmc::tuneMallocByReexecuting(argv);  // as vkmc itself runs (app/malloc_tuning.h): both walks under it
  CLI::App app{"vkmc traversal against Embree 3 rtcIntersect1 on the same rays"};
  std::vector<std::string> scenes;
  std::string raysPath, dumpDir, jsonPath;
  int runs = 5, width = 256, height = 256;
  unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  app.add_option("scenes", scenes, "glTF scenes (default: Cornell box, DamagedHelmet, MetalRoughSpheresNoTextures)");
  app.add_option("--rays", raysPath, "trace these dumped rays (one scene) instead of making them");
  app.add_option("--dump", dumpDir, "write each scene's diffuse rays to DIR/<scene>.rays");
  app.add_option("--runs", runs, "timed runs (medians reported)")->check(CLI::Range(1, 1000));
  app.add_option("--width", width, "primary rays: width")->check(CLI::Range(1, 8192));
  app.add_option("--height", height, "primary rays: height")->check(CLI::Range(1, 8192));
  app.add_option("--threads", threads, "Embree threads (default: all cores, as lavapipe uses)")->check(CLI::Range(1, 1024));
  app.add_option("--json", jsonPath, "write the results as JSON");
  bool walkStats = false;
  app.add_flag("--walk-stats", walkStats,
               "also count vkmc's walk steps per ray (one more, untimed trace with a counting kernel variant)");
  CLI11_PARSE(app, argc, argv);
  try {
    if (scenes.empty())
      for (const char* c : {"scenes/cornell_box.gltf", "../shared/scenes/DamagedHelmet/DamagedHelmet.gltf",
                            "../shared/scenes/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.gltf"})
        if (std::filesystem::exists(c)) scenes.emplace_back(c);
    if (scenes.empty()) throw Error("no scenes");
    if (!raysPath.empty() && scenes.size() != 1) throw Error("--rays needs exactly one scene");
    vk::Context ctx;
    std::printf("vkmc: %s (GPU timestamps of the trace kernel); Embree %d.%d.%d rtcIntersect1 on %u threads (wall time)\n",
                ctx.deviceName().c_str(), RTC_VERSION_MAJOR, RTC_VERSION_MINOR, RTC_VERSION_PATCH, threads);
    std::printf("%-34s %9s %9s %12s %12s %8s %10s %10s %14s %8s %10s\n", "scene", "triangles", "rays", "vkmc Mray/s",
                "Embree Mray/s", "ratio", "agree", "deep walks", "robust Mray/s", "ratio", "agree");
    nlohmann::json out = nlohmann::json::array();
    for (const std::string& path : scenes) {
      Scene scene = loadGltf(path);
      std::vector<Aabb> bounds = scene.triangleBounds();
      Bvh bvh = buildBvh(bounds);
      GpuScene gpuScene(ctx, scene, bvh);
      RayTracer tracer(ctx, gpuScene);
      std::vector<gpu::TestRay> rays = raysPath.empty()
                                           ? makeBenchmarkRays(scene, bvh, tracer, uint32_t(width), uint32_t(height)).diffuse
                                           : readRays(raysPath);
      if (rays.empty()) throw Error(path + ": no rays to trace");
      std::string name = std::filesystem::path(path).stem().string();
      if (!dumpDir.empty()) writeRays((std::filesystem::path(dumpDir) / (name + ".rays")).string(), rays);
      EmbreeScene embree(scene, false), robust(scene, true);
      std::vector<float> tEmbree, tRobust;
      std::vector<glm::vec4> hits = tracer.trace(rays, false);  // warm-up of all three
      traceEmbree(embree, rays, threads, tEmbree);
      traceEmbree(robust, rays, threads, tRobust);
      std::vector<double> vk, em, rb;
      for (int r = 0; r < runs; ++r) {  // interleaved, so noise hits all alike
        double secs = 0;
        hits = tracer.trace(rays, false, &secs);
        vk.push_back(rays.size() / secs * 1e-6);
        em.push_back(rays.size() / traceEmbree(embree, rays, threads, tEmbree) * 1e-6);
        rb.push_back(rays.size() / traceEmbree(robust, rays, threads, tRobust) * 1e-6);
      }
      // Same answer: hit or miss alike, and t within 1e-4 relative where both hit.
      auto agreement = [&](const std::vector<float>& tPeer) {
        size_t agree = 0;
        for (size_t i = 0; i < rays.size(); ++i) {
          bool vkHit = glm::floatBitsToUint(hits[i].w) != gpu::kMissPrimitive, peerHit = std::isfinite(tPeer[i]);
          agree += vkHit == peerHit && (!vkHit || std::abs(hits[i].x - tPeer[i]) <= 1e-4f * std::max(1.0f, tPeer[i]));
        }
        return double(agree) / double(rays.size());
      };
      double ratio = median(vk) / median(em);
      double robustRatio = median(vk) / median(rb);
      // Deep walks: rays whose walk outgrew the register stack and ran again in the trace kernel's deep pass.
      std::printf("%-34s %9zu %9zu %12.2f %12.2f %7.2fx %9.4f%% %10u %14.2f %7.2fx %9.4f%%\n",
                  std::filesystem::path(path).filename().c_str(), scene.triangleCount(), rays.size(), median(vk), median(em),
                  ratio, 100.0 * agreement(tEmbree), tracer.deepWalks(), median(rb), robustRatio, 100.0 * agreement(tRobust));
      out.push_back({{"scene", path},
                     {"rays", rays.size()},
                     {"vkmc_mrays_per_second", median(vk)},
                     {"embree_mrays_per_second", median(em)},
                     {"ratio", ratio},
                     {"embree_robust_mrays_per_second", median(rb)},
                     {"robust_ratio", robustRatio},
                     {"agreement", agreement(tEmbree)},
                     {"robust_agreement", agreement(tRobust)},
                     {"deep_walks", tracer.deepWalks()}});
      if (walkStats) {
        RayTracer counting(ctx, gpuScene, false, true);
        counting.trace(rays, false);
        RayTracer::WalkStats w = counting.walkStats();
        std::printf("  walk per ray: %.2f iterations (%.2f node steps, %.2f triangle tests); slowest lane of %u: %.2f\n",
                    w.iterations, w.nodeSteps, w.triangleTests, ctx.subgroupSize(), w.slowestLaneIterations);
        out.back()["walk_per_ray"] = {{"iterations", w.iterations},
                                      {"node_steps", w.nodeSteps},
                                      {"triangle_tests", w.triangleTests},
                                      {"slowest_lane_iterations", w.slowestLaneIterations}};
      }
    }
    if (!jsonPath.empty())
      writeFileAtomically(
          jsonPath, nlohmann::json{{"device", ctx.deviceName()}, {"embree_threads", threads}, {"results", out}}.dump(2) + "\n");
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vkmc-embree-baseline: %s\n", e.what());
    return 1;
  }
}
