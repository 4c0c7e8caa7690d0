// Traversal peer on the same device: the same incoherent rays traced by vkmc's closest-hit kernel and by tinybvh's
// GPU traversal kernels (jbikker/tinybvh: its GLSL Aila-Laine walk of BVH_GPU, and its CWBVH walk ported from
// OpenCL), all on lavapipe, interleaved run by run, timed by GPU timestamps alike. Each BVH is built by its own
// library from the same world-space triangles. Rays come from vkmc (bench/benchmark_rays.h: four diffuse bounce rays
// per primary hit) or from a dump (`--rays FILE`, written with `--dump DIR`). Run with tools/tinybvh_baseline.sh.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "analysis/summary_statistics.h"
#include "app/malloc_tuning.h"
#include "bench/benchmark_rays.h"
#include "bench/ray_tracer.h"
#include "error.h"
#include "io/output_files.h"
#include "render/gpu_scene.h"
#include "scene/gltf_loader.h"
#include "spirv/tinybvh_ailalaine_spv.h"
#include "spirv/tinybvh_ailalaine_stats_spv.h"
#include "spirv/tinybvh_cwbvh_spv.h"
#include "spirv/tinybvh_cwbvh_stats_spv.h"
#include "tinybvh_bindings.h"
#include "tinybvh_layouts.h"
#include "tinybvh_tracer.h"
#include "vk/context.h"

using namespace vkmc;

namespace {

struct Options {
  std::vector<std::string> scenes;
  std::string raysPath, dumpDir, jsonPath;
  int runs = 5, width = 256, height = 256;
  bool hq = false, walkStats = false;
};

// A tinybvh kernel with what the report says about it.
struct Peer {
  std::string label;
  double buildSeconds = 0;
  size_t nodeBytes = 0;
  std::unique_ptr<TinybvhTracer> tracer, counting;  // counting: the walk-stats variant, with --walk-stats
  std::vector<double> mrays;
  std::vector<glm::vec4> hits;
};

// Hit or miss alike, and t within 1e-4 relative where both hit (as vkmc-embree-baseline judges); the rays that
// differ, by how; and, of the rays both hit, those that hit the same triangle (vkmc's hits name triangles in its
// BVH's order).
struct Agreement {
  size_t agree = 0, nearer = 0, farther = 0, extraHits = 0, misses = 0, bothHit = 0, sameTriangle = 0;
};

Agreement compare(const std::vector<glm::vec4>& vkmc, const Bvh& bvh, const std::vector<glm::vec4>& peer) {
  Agreement a;
  for (size_t i = 0; i < vkmc.size(); ++i) {
    uint32_t vkTri = glm::floatBitsToUint(vkmc[i].w);
    bool vkHit = vkTri != gpu::kMissPrimitive, peerHit = peer[i].x < gpu::kTinybvhFar;
    if (vkHit != peerHit) {
      ++(peerHit ? a.extraHits : a.misses);
      continue;
    }
    if (!vkHit) {
      ++a.agree;
      continue;
    }
    ++a.bothHit;
    a.sameTriangle += bvh.triangleOrder[vkTri] == glm::floatBitsToUint(peer[i].w);
    if (std::abs(vkmc[i].x - peer[i].x) <= 1e-4f * std::max(1.0f, peer[i].x))
      ++a.agree;
    else
      ++(peer[i].x < vkmc[i].x ? a.nearer : a.farther);
  }
  return a;
}

std::vector<Peer> makePeers(vk::Context& ctx, const Scene& scene, const Options& o) {
  std::vector<Peer> peers;
  {
    TinybvhAilaLaine al = buildTinybvhAilaLaine(scene, o.hq);
    Peer p{"tinybvh BVH_GPU", al.buildSeconds, al.nodes.size() * sizeof(glm::vec4)};
    p.tracer = std::make_unique<TinybvhTracer>(ctx, "tinybvh_ailalaine", kSpirv_tinybvh_ailalaine, 32u, al.nodes, al.indices,
                                               al.vertices);
    if (o.walkStats)
      p.counting = std::make_unique<TinybvhTracer>(ctx, "tinybvh_ailalaine_stats", kSpirv_tinybvh_ailalaine_stats, 32u, al.nodes,
                                                   al.indices, al.vertices, true);
    peers.push_back(std::move(p));
  }
  {
    TinybvhCwbvh cw = buildTinybvhCwbvh(scene, o.hq);
    Peer p{"tinybvh CWBVH", cw.buildSeconds, cw.nodes.size() * sizeof(glm::vec4)};
    p.tracer = std::make_unique<TinybvhTracer>(ctx, "tinybvh_cwbvh", kSpirv_tinybvh_cwbvh, 64u, cw.nodes,
                                               std::span<const uint32_t>(), cw.triangles);
    if (o.walkStats)
      p.counting = std::make_unique<TinybvhTracer>(ctx, "tinybvh_cwbvh_stats", kSpirv_tinybvh_cwbvh_stats, 64u, cw.nodes,
                                                   std::span<const uint32_t>(), cw.triangles, true);
    peers.push_back(std::move(p));
  }
  return peers;
}

// One more, untimed trace of each counting variant: steps per ray, and what a subgroup pays (its slowest lane).
void printWalkStats(vk::Context& ctx, const GpuScene& gpuScene, const std::vector<gpu::TestRay>& rays, std::vector<Peer>& peers,
                    nlohmann::json& out) {
  RayTracer counting(ctx, gpuScene, false, true);
  counting.trace(rays, false);
  RayTracer::WalkStats v = counting.walkStats();
  std::printf("  walk per ray, vkmc: %.2f iterations (%.2f node steps, %.2f triangle tests); slowest lane of %u: %.2f\n",
              v.iterations, v.nodeSteps, v.triangleTests, ctx.subgroupSize(), v.slowestLaneIterations);
  out["vkmc_walk_per_ray"] = {{"iterations", v.iterations},
                              {"node_steps", v.nodeSteps},
                              {"triangle_tests", v.triangleTests},
                              {"slowest_lane_iterations", v.slowestLaneIterations}};
  for (size_t k = 0; k < peers.size(); ++k) {
    peers[k].counting->trace(rays);
    TinybvhTracer::WalkStats w = peers[k].counting->walkStats();
    std::printf("  walk per ray, %s: %.2f iterations (%.2f triangle tests); slowest lane of %u: %.2f (%.2f triangle tests)\n",
                peers[k].label.c_str(), w.iterations, w.triangleTests, ctx.subgroupSize(), w.slowestLaneIterations,
                w.slowestLaneTriangleTests);
    out["tinybvh"][k]["walk_per_ray"] = {{"iterations", w.iterations},
                                         {"triangle_tests", w.triangleTests},
                                         {"slowest_lane_iterations", w.slowestLaneIterations},
                                         {"slowest_lane_triangle_tests", w.slowestLaneTriangleTests}};
  }
}

// A warm-up, then `runs` rounds of vkmc's kernel and each peer in turn, so the machine's swings hit all alike.
// Returns vkmc's Mrays/s per round (the peers keep theirs) and leaves every kernel's last hits.
std::vector<double> timeInterleaved(RayTracer& tracer, std::vector<Peer>& peers, const std::vector<gpu::TestRay>& rays, int runs,
                                    std::vector<glm::vec4>& hits) {
  hits = tracer.trace(rays, false);
  for (Peer& p : peers) p.hits = p.tracer->trace(rays);
  std::vector<double> vk;
  for (int r = 0; r < runs; ++r) {
    double secs = 0;
    hits = tracer.trace(rays, false, &secs);
    vk.push_back(rays.size() / secs * 1e-6);
    for (Peer& p : peers) {
      p.hits = p.tracer->trace(rays, &secs);
      p.mrays.push_back(rays.size() / secs * 1e-6);
    }
  }
  return vk;
}

// A table row and a JSON record per tinybvh kernel: speed against vkmc's, agreement with its hits, build, size.
void reportPeers(const std::vector<Peer>& peers, const std::vector<glm::vec4>& hits, const Bvh& bvh, double vkmcMrays,
                 nlohmann::json& out) {
  for (const Peer& p : peers) {
    Agreement a = compare(hits, bvh, p.hits);
    double ratio = median(p.mrays) / vkmcMrays, agree = double(a.agree) / double(hits.size());
    double sameTriangle = a.bothHit ? double(a.sameTriangle) / double(a.bothHit) : 1.0;
    std::printf("%-34s %9s %9s  %-16s %8.2f %7.2fx %8.4f%% %8.4f%% %9.1f %9.1f\n", "", "", "", p.label.c_str(), median(p.mrays),
                ratio, 100.0 * agree, 100.0 * sameTriangle, p.buildSeconds * 1e3, p.nodeBytes / 1024.0);
    if (a.agree != hits.size())
      std::printf("%-64s rays that differ: %zu hit nearer, %zu farther, %zu hit where vkmc misses, %zu miss where it hits\n", "",
                  a.nearer, a.farther, a.extraHits, a.misses);
    out["tinybvh"].push_back(
        {{"kernel", p.label},
         {"mrays_per_second", median(p.mrays)},
         {"ratio_to_vkmc", ratio},
         {"agreement", agree},
         {"differ", {{"nearer", a.nearer}, {"farther", a.farther}, {"extra_hits", a.extraHits}, {"misses", a.misses}}},
         {"same_triangle", sameTriangle},
         {"build_seconds", p.buildSeconds},
         {"node_bytes", p.nodeBytes}});
  }
}

nlohmann::json runScene(vk::Context& ctx, const std::string& path, const Options& o) {
  Scene scene = loadGltf(path);
  std::vector<Aabb> bounds = scene.triangleBounds();
  auto start = std::chrono::steady_clock::now();
  Bvh bvh = buildBvh(bounds);
  double vkmcBuild = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  GpuScene gpuScene(ctx, scene, bvh);
  RayTracer tracer(ctx, gpuScene);
  std::vector<gpu::TestRay> rays = o.raysPath.empty()
                                       ? makeBenchmarkRays(scene, bvh, tracer, uint32_t(o.width), uint32_t(o.height)).diffuse
                                       : readRays(o.raysPath);
  if (rays.empty()) throw Error(path + ": no rays to trace");
  std::string name = std::filesystem::path(path).stem().string();
  if (!o.dumpDir.empty()) writeRays((std::filesystem::path(o.dumpDir) / (name + ".rays")).string(), rays);
  std::vector<Peer> peers = makePeers(ctx, scene, o);
  std::vector<glm::vec4> hits;
  double vk = median(timeInterleaved(tracer, peers, rays, o.runs, hits));

  std::printf("%-34s %9zu %9zu  %-16s %8.2f %8s %9s %9s %9.1f\n", std::filesystem::path(path).filename().c_str(),
              scene.triangleCount(), rays.size(), "vkmc", vk, "", "", "", vkmcBuild * 1e3);
  nlohmann::json out{{"scene", path},
                     {"triangles", scene.triangleCount()},
                     {"rays", rays.size()},
                     {"vkmc_mrays_per_second", vk},
                     {"vkmc_build_seconds", vkmcBuild},
                     {"vkmc_deep_walks", tracer.deepWalks()},
                     {"tinybvh", nlohmann::json::array()}};
  reportPeers(peers, hits, bvh, vk, out);
  if (o.walkStats) printWalkStats(ctx, gpuScene, rays, peers, out);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  vkmc::tuneMallocByReexecuting(argv);  // as vkmc itself runs (app/malloc_tuning.h): both walks under it
  CLI::App app{"vkmc traversal against tinybvh's GPU traversal kernels, on the same device and rays"};
  Options o;
  app.add_option("scenes", o.scenes, "glTF scenes (default: Cornell box, DamagedHelmet, MetalRoughSpheresNoTextures)");
  app.add_option("--rays", o.raysPath, "trace these dumped rays (one scene) instead of making them");
  app.add_option("--dump", o.dumpDir, "write each scene's diffuse rays to DIR/<scene>.rays");
  app.add_option("--runs", o.runs, "timed runs (medians reported)")->check(CLI::Range(1, 1000));
  app.add_option("--width", o.width, "primary rays: width")->check(CLI::Range(1, 8192));
  app.add_option("--height", o.height, "primary rays: height")->check(CLI::Range(1, 8192));
  app.add_flag("--hq", o.hq, "build tinybvh's BVHs with BuildHQ (SBVH, as its GPU speed tests do) instead of Build");
  app.add_option("--json", o.jsonPath, "write the results as JSON");
  app.add_flag("--walk-stats", o.walkStats,
               "also count each kernel's walk steps per ray (one more, untimed trace with counting kernel variants)");
  CLI11_PARSE(app, argc, argv);
  try {
    if (o.scenes.empty())
      for (const char* c : {"scenes/cornell_box.gltf", "../shared/scenes/DamagedHelmet/DamagedHelmet.gltf",
                            "../shared/scenes/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.gltf"})
        if (std::filesystem::exists(c)) o.scenes.emplace_back(c);
    if (o.scenes.empty()) throw Error("no scenes");
    if (!o.raysPath.empty() && o.scenes.size() != 1) throw Error("--rays needs exactly one scene");
    vk::Context ctx;
    std::printf("%s: vkmc's trace kernel and tinybvh's (%s build), GPU timestamps, medians of %d interleaved runs\n",
                ctx.deviceName().c_str(), o.hq ? "BuildHQ" : "Build", o.runs);
    std::printf("%-34s %9s %9s  %-16s %8s %8s %9s %9s %9s %9s\n", "scene", "triangles", "rays", "kernel", "Mrays/s", "vs vkmc",
                "agree", "same tri", "build ms", "nodes KiB");
    nlohmann::json results = nlohmann::json::array();
    for (const std::string& path : o.scenes) results.push_back(runScene(ctx, path, o));
    if (!o.jsonPath.empty())
      writeFileAtomically(
          o.jsonPath,
          nlohmann::json{
              {"device", ctx.deviceName()}, {"tinybvh_build", o.hq ? "BuildHQ" : "Build"}, {"runs", o.runs}, {"results", results}}
                  .dump(2) +
              "\n");
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vkmc-tinybvh-baseline: %s\n", e.what());
    return 1;
  }
}
