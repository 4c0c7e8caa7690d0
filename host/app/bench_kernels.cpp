// Benchmark: each scene is set up once per run (so set-up is measured too), warmed with one sample, then
// timed. Scenes are interleaved run by run so machine noise hits them alike; medians and min-max reported.
#include "app/bench_kernels.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "app/render_job.h"
#include "bvh/bvh.h"
#include "error.h"
#include "render/gpu_scene.h"
#include "render/benchmark_rays.h"
#include "render/ray_tracer.h"
#include "scene/gltf_loader.h"
#include "io/exr.h"
#include "vk/context.h"

namespace vkmc {
namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::vector<std::string> defaultScenes() {
  std::vector<std::string> scenes;
  for (const char* candidate : {"scenes/cornell_box.gltf", "../shared/scenes/DamagedHelmet/DamagedHelmet.gltf",
                                "../shared/scenes/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.gltf"}) {
    if (std::filesystem::exists(candidate)) scenes.emplace_back(candidate);
    else std::fprintf(stderr, "vkmc: note: %s not found, skipped\n", candidate);
  }
  return scenes;
}

struct Samples {
  std::vector<double> load, bvh, upload, pipelines, sps, primary, incoherent, total, tracePrimary, traceDiffuse;
  uint32_t triangles = 0;
  double diffuseRays = 0;
};

// The traversal alone, on the ray arrays of render/benchmark_rays.h (camera rays, then four diffuse bounce rays
// per hit). Returns (primary, diffuse) Mrays/s from the trace kernel's timestamps, medians over runs.
std::pair<std::vector<double>, std::vector<double>> traceBenchmark(vk::Context& ctx, const std::string& path, int width,
                                                                   int height, int runs, double& diffuseRayCount) {
  Scene scene = loadGltf(path);
  std::vector<Aabb> bounds(scene.triangleCount());
  for (size_t i = 0; i < bounds.size(); ++i)
    for (int k = 0; k < 3; ++k) bounds[i].grow(scene.positions[3 * i + k]);
  Bvh bvh = buildBvh(bounds);
  GpuScene gpuScene(ctx, scene, bvh);
  RayTracer tracer(ctx, gpuScene);
  BenchmarkRays rays = makeBenchmarkRays(scene, bvh, tracer, uint32_t(width), uint32_t(height));
  const std::vector<gpu::TestRay>& primary = rays.primary;
  const std::vector<gpu::TestRay>& diffuse = rays.diffuse;
  diffuseRayCount = static_cast<double>(diffuse.size());
  std::vector<double> p, d;
  tracer.trace(primary, false);  // warm-up
  for (int r = 0; r < runs; ++r) {
    double secs = 0;
    tracer.trace(primary, false, &secs);
    p.push_back(secs > 0 ? primary.size() / secs * 1e-6 : 0.0);
    if (!diffuse.empty()) {
      tracer.trace(diffuse, false, &secs);
      d.push_back(secs > 0 ? diffuse.size() / secs * 1e-6 : 0.0);
    }
  }
  return {p, d};
}

}  // namespace

// Specialized against general pipelines, interleaved run by run: time per sample and pipeline set-up time.
int runSpecializationBench(const BenchOptions& o, const std::vector<std::string>& scenes) {
  vk::Context ctx;
  std::printf("device: %s; %dx%d, %d spp per run, %d runs; medians [min-max]\n", ctx.deviceName().c_str(), o.width, o.height, o.spp, o.runs);
  std::printf("%-34s %-12s %14s %22s %12s\n", "scene", "pipelines", "us per sample", "[min-max]", "pipelines s");
  nlohmann::json out = nlohmann::json::array();
  for (const std::string& scene : scenes) {
    std::vector<double> perSample[2], pipes[2];
    for (int run = -1; run < o.runs; ++run)
      for (int general = 0; general < 2; ++general) {
        RenderOptions ro;
        ro.scenePath = scene;
        ro.width = static_cast<uint32_t>(o.width);
        ro.height = static_cast<uint32_t>(o.height);
        ro.spp = static_cast<uint32_t>(o.spp);
        ro.progress = false;
        ro.background = glm::vec3(1.0f);
        ro.specialize = general == 0;
        RenderOutcome r = runRender(ctx, ro);
        if (run < 0) continue;
        perSample[general].push_back(r.stats.seconds / double(r.film.totalSamples()) * 1e6);
        pipes[general].push_back(r.setup.pipelines);
      }
    std::string name = std::filesystem::path(scene).filename().string();
    for (int general = 0; general < 2; ++general) {
      auto [lo, hi] = std::minmax_element(perSample[general].begin(), perSample[general].end());
      std::printf("%-34s %-12s %14.3f %10.3f-%-10.3f %12.3f\n", name.c_str(), general ? "general" : "specialized", median(perSample[general]),
                  *lo, *hi, median(pipes[general]));
    }
    std::printf("%-34s %-12s %14.2fx\n", "", "ratio", median(perSample[1]) / median(perSample[0]));
    out.push_back({{"scene", scene}, {"specialized_us_per_sample", median(perSample[0])}, {"general_us_per_sample", median(perSample[1])},
                   {"specialized_pipeline_seconds", median(pipes[0])}, {"general_pipeline_seconds", median(pipes[1])}});
  }
  if (!o.jsonPath.empty()) writeFileAtomically(o.jsonPath, nlohmann::json{{"device", ctx.deviceName()}, {"results", out}}.dump(2) + "\n");
  return 0;
}

int runBenchKernels(const BenchOptions& o) {
  if (o.runs < 1 || o.runs > 1000) throw Error("--runs must be between 1 and 1000");
  if (o.spp < 1 || o.width < 1 || o.height < 1 || o.width > 8192 || o.height > 8192) throw Error("bad --spp, --width or --height");
  std::vector<std::string> scenes = o.scenes.empty() ? defaultScenes() : o.scenes;
  if (scenes.empty()) throw Error("no scenes to benchmark");
  if (o.specialization) return runSpecializationBench(o, scenes);
  vk::Context ctx;
  std::vector<Samples> samples(scenes.size());
  // Round 0 warms caches (Mesa's shader cache, the page cache, the allocator) and is not counted, except that
  // its pipeline time is reported as the first-use figure.
  std::vector<double> firstPipelines(scenes.size(), 0.0);
  for (int run = -1; run < o.runs; ++run) {
    for (size_t i = 0; i < scenes.size(); ++i) {
      RenderOptions ro;
      ro.scenePath = scenes[i];
      ro.width = static_cast<uint32_t>(o.width);
      ro.height = static_cast<uint32_t>(o.height);
      ro.spp = static_cast<uint32_t>(o.spp);
      ro.progress = false;
      ro.background = glm::vec3(1.0f);  // so scenes without emitters still bounce rays
      RenderOutcome r = runRender(ctx, ro);
      if (run < 0) {
        firstPipelines[i] = r.setup.pipelines;
        continue;
      }
      Samples& s = samples[i];
      s.triangles = r.sceneInfo.triangles;
      s.load.push_back(r.setup.load);
      s.bvh.push_back(r.setup.bvh);
      s.upload.push_back(r.setup.upload);
      s.pipelines.push_back(r.setup.pipelines);
      const RenderStats& st = r.stats;
      s.sps.push_back(double(r.film.totalSamples()) / st.seconds);
      s.primary.push_back(st.primarySeconds > 0 ? st.primaryRays / st.primarySeconds * 1e-6 : 0.0);
      s.incoherent.push_back(st.incoherentSeconds > 0 ? st.extensionRays / st.incoherentSeconds * 1e-6 : 0.0);
      s.total.push_back(st.rays() / st.seconds * 1e-6);
      auto [tp, td] = traceBenchmark(ctx, scenes[i], o.width, o.height, 1, s.diffuseRays);
      s.tracePrimary.insert(s.tracePrimary.end(), tp.begin(), tp.end());
      s.traceDiffuse.insert(s.traceDiffuse.end(), td.begin(), td.end());
    }
  }
  std::printf("device: %s; %dx%d, %d spp per run, %d runs, medians [min-max]\n", ctx.deviceName().c_str(), o.width, o.height,
              o.spp, o.runs);
  std::printf("%-34s %9s %7s %7s %8s %7s | %10s %9s %9s %9s | %9s %9s\n", "scene", "triangles", "load s", "bvh s",
              "upload s", "pipes s", "samples/s", "primary", "bounces", "total", "trace 1st", "trace dif");
  std::printf("%-34s %9s %7s %7s %8s %7s | %10s %9s %9s %9s | %9s %9s\n", "", "", "", "", "", "", "", "Mrays/s",
              "Mrays/s", "Mrays/s", "Mrays/s", "Mrays/s");
  nlohmann::json out = nlohmann::json::array();
  for (size_t i = 0; i < scenes.size(); ++i) {
    const Samples& s = samples[i];
    auto range = [](const std::vector<double>& v) {
      auto [lo, hi] = std::minmax_element(v.begin(), v.end());
      return std::make_pair(*lo, *hi);
    };
    std::string name = std::filesystem::path(scenes[i]).filename().string();
    std::printf("%-34s %9u %7.3f %7.3f %8.3f %7.3f | %10.0f %9.2f %9.2f %9.2f | %9.2f %9.2f  [dif %.2f-%.2f]\n",
                name.c_str(), s.triangles, median(s.load), median(s.bvh), median(s.upload), median(s.pipelines),
                median(s.sps), median(s.primary), median(s.incoherent), median(s.total), median(s.tracePrimary),
                median(s.traceDiffuse), s.traceDiffuse.empty() ? 0.0 : range(s.traceDiffuse).first,
                s.traceDiffuse.empty() ? 0.0 : range(s.traceDiffuse).second);
    out.push_back({{"scene", scenes[i]},
                   {"triangles", s.triangles},
                   {"load_seconds", median(s.load)},
                   {"bvh_seconds", median(s.bvh)},
                   {"upload_seconds", median(s.upload)},
                   {"pipeline_seconds", median(s.pipelines)},
                   {"samples_per_second", median(s.sps)},
                   {"primary_mrays_per_second", median(s.primary)},
                   {"incoherent_mrays_per_second", median(s.incoherent)},
                   {"total_mrays_per_second", median(s.total)},
                   {"trace_primary_mrays_per_second", median(s.tracePrimary)},
                   {"trace_diffuse_mrays_per_second", median(s.traceDiffuse)},
                   {"trace_diffuse_rays", s.diffuseRays},
                   {"pipeline_seconds_first_use", firstPipelines[i]}});
  }
  std::printf("primary/bounces: wavefront intersection stages (GPU time); total: all rays over render wall time;\n"
              "trace 1st/dif: the traversal kernel alone on camera rays and on 4 cosine bounce rays per primary hit.\n"
              "pipelines: creation plus first-dispatch compile, median of warm runs; first use in this process: %.3f s\n"
              "(Mesa's on-disk shader cache may make even that warm; clear ~/.cache/mesa_shader_cache for a cold figure).\n",
              firstPipelines.front());
  if (!o.jsonPath.empty())
    writeFileAtomically(o.jsonPath, nlohmann::json{{"device", ctx.deviceName()}, {"results", out}}.dump(2) + "\n");
  return 0;
}

}  // namespace vkmc
