// Benchmark: each scene is set up once per run (so set-up is measured too), warmed with one sample, then
// timed. Scenes are interleaved run by run so machine noise hits them alike; medians and min-max reported.
#include "app/bench_kernels.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "analysis/summary_statistics.h"
#include "app/render_job.h"
#include "bvh/bvh.h"
#include "error.h"
#include "render/gpu_scene.h"
#include "bench/benchmark_rays.h"
#include "bench/ray_tracer.h"
#include "scene/gltf_loader.h"
#include "io/exr.h"
#include "io/output_files.h"
#include "vk/context.h"

namespace vkmc {
namespace {

std::vector<std::string> defaultScenes() {
  std::vector<std::string> scenes;
  for (const char* candidate : {"scenes/cornell_box.gltf", "../shared/scenes/DamagedHelmet/DamagedHelmet.gltf",
                                "../shared/scenes/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.gltf"}) {
    if (std::filesystem::exists(candidate))
      scenes.emplace_back(candidate);
    else
      std::fprintf(stderr, "vkmc: note: %s not found, skipped\n", candidate);
  }
  return scenes;
}

// Per kernel of the wavefront: GPU seconds per frame (one run's render), the items it processed, and a
// memory-traffic estimate from the bytes of path state, queues, hits and film each item reads and writes
// (BVH node and triangle fetches of the traversal kernels are not in it: they depend on the walk).
struct KernelSamples {
  std::vector<double> seconds;
  double items = 0;  // per frame (deterministic: the same every run)
  double bytesPerItem = 0;
};

struct Samples {
  std::vector<double> load, bvh, upload, pipelines, sps, primary, incoherent, total, tracePrimary, traceDiffuse,
      traceDiffuseBinary, gpu;
  uint32_t triangles = 0;
  double diffuseRays = 0;
  std::map<std::string, KernelSamples> kernels;
  std::vector<uint64_t> pathsByBounce, shadowRaysByBounce;
  uint64_t cameraRays = 0;
  bool megakernel = false;  // no queues: no occupancy to report
};

// Items and bytes per item of each kernel (sizes from shared/layout.h): a path-state read is 80 B, a queue
// entry 4, a hit 16, a shadow ray 48, a film pixel 32 (read and written).
void recordKernels(Samples& s, const RenderStats& st, uint64_t samples) {
  const double tracedPaths = double(st.cameraRays + st.extensionRays);
  struct Row {
    const char* name;
    double items, bytesPerItem;
  };
  const Row rows[] = {
      {"camera_rays", double(st.cameraRays), 80 + 4},
      {"intersect_primary", double(st.cameraRays), 4 + 80 + 16},
      {"intersect", double(st.extensionRays), 4 + 80 + 16},
      // queue, path, hit, triangle info, 3 vertices, material; path and queue written; its shadow rays written
      {"shade", tracedPaths, 4 + 80 + 16 + 16 + 48 + 48 + 80 + 4 + 48 * double(st.shadowRays) / std::max(1.0, tracedPaths)},
      {"shadow", double(st.shadowRays), 48 + 2 * 16},
      {"accumulate", double(samples), 80 + 2 * 32},
      // every ray of the pass; the path slot's radiance is its only state traffic
      {"megakernel", double(st.rays()), 16.0 * double(st.cameraRays) / std::max<double>(1.0, double(st.rays()))},
      {"prepare_bounce", 0, 0},
      {"prepare_shadow", 0, 0}};
  for (const Row& r : rows) {
    auto it = st.stageSeconds.find(r.name);
    if (it == st.stageSeconds.end()) continue;
    KernelSamples& k = s.kernels[r.name];
    k.seconds.push_back(it->second);
    k.items = r.items;
    k.bytesPerItem = r.bytesPerItem;
  }
  s.gpu.push_back(st.gpuSeconds);
  s.pathsByBounce = st.pathsByBounce;
  s.shadowRaysByBounce = st.shadowRaysByBounce;
  s.cameraRays = st.cameraRays;
  s.megakernel = st.stageSeconds.count("megakernel") > 0;
}

// The per-kernel table of one scene, and its JSON.
nlohmann::json printKernels(const std::string& name, const Samples& s) {
  double gpu = median(s.gpu);
  // Shares of the kernels' own time (the command buffers' time also holds the barriers between them).
  double kernelSeconds = 0.0;
  for (const auto& [kernel, k] : s.kernels) kernelSeconds += median(k.seconds);
  std::printf("\n%s: GPU %.1f ms per frame (median); per kernel:\n", name.c_str(), gpu * 1e3);
  std::printf("  %-18s %10s %7s %12s %10s %12s\n", "kernel", "ms/frame", "share", "items/frame", "Mitems/s", "est. GB/s");
  nlohmann::json kernels = nlohmann::json::array();
  for (const auto& [kernel, k] : s.kernels) {
    double secs = median(k.seconds);
    double rate = secs > 0 ? k.items / secs * 1e-6 : 0.0, gbps = secs > 0 ? k.items * k.bytesPerItem / secs * 1e-9 : 0.0;
    std::printf("  %-18s %10.3f %6.1f%% %12.0f %10.2f %12.2f\n", kernel.c_str(), secs * 1e3,
                100.0 * secs / std::max(kernelSeconds, 1e-12), k.items, rate, gbps);
    kernels.push_back({{"kernel", kernel},
                       {"seconds_per_frame", secs},
                       {"share", secs / std::max(kernelSeconds, 1e-12)},
                       {"items_per_frame", k.items},
                       {"mitems_per_second", rate},
                       {"estimated_state_bytes_per_item", k.bytesPerItem},
                       {"estimated_gb_per_second", gbps}});
  }
  if (s.megakernel) {
    std::printf("  (megakernel: no queues between stages, so no occupancy per bounce)\n");
    return {{"gpu_seconds_per_frame", gpu}, {"kernels", kernels}};
  }
  // Queue occupancy: paths alive at each bounce, as a share of the camera paths.
  size_t last = 0;
  for (size_t b = 0; b < s.pathsByBounce.size(); ++b)
    if (s.pathsByBounce[b]) last = b;
  std::printf("  paths alive per bounce (%% of camera paths):");
  for (size_t b = 0; b <= last && b < 16; ++b)
    std::printf(" %.1f", 100.0 * s.pathsByBounce[b] / std::max<uint64_t>(1, s.cameraRays));
  std::printf("%s\n  shadow rays per bounce (per camera path):", last >= 16 ? " ..." : "");
  for (size_t b = 0; b <= last && b < 16; ++b)
    std::printf(" %.2f", double(s.shadowRaysByBounce[b]) / std::max<uint64_t>(1, s.cameraRays));
  std::printf("%s\n", last >= 16 ? " ..." : "");
  return {{"gpu_seconds_per_frame", gpu},
          {"kernels", kernels},
          {"paths_by_bounce", s.pathsByBounce},
          {"shadow_rays_by_bounce", s.shadowRaysByBounce}};
}

// The traversal alone, on the ray arrays of bench/benchmark_rays.h (camera rays, then four diffuse bounce rays
// per hit), through the 4-wide BVH and, interleaved, the binary one. Mrays/s from the trace kernel's timestamps.
struct TraceRates {
  std::vector<double> primary, diffuse, diffuseBinary;
};
TraceRates traceBenchmark(vk::Context& ctx, const std::string& path, int width, int height, int runs, double& diffuseRayCount) {
  Scene scene = loadGltf(path, deviceLoadLimits(ctx));
  std::vector<Aabb> bounds = scene.triangleBounds();
  Bvh bvh = buildBvh(bounds);
  GpuScene gpuScene(ctx, scene, bvh, false, true);
  RayTracer tracer(ctx, gpuScene), binaryTracer(ctx, gpuScene, true);
  BenchmarkRays rays = makeBenchmarkRays(scene, bvh, tracer, uint32_t(width), uint32_t(height));
  const std::vector<gpu::TestRay>& primary = rays.primary;
  const std::vector<gpu::TestRay>& diffuse = rays.diffuse;
  diffuseRayCount = static_cast<double>(diffuse.size());
  TraceRates rates;
  tracer.trace(primary, false);  // warm-up
  binaryTracer.trace(primary, false);
  auto rate = [](size_t n, double secs) { return secs > 0 ? double(n) / secs * 1e-6 : 0.0; };
  for (int r = 0; r < runs; ++r) {
    double secs = 0;
    tracer.trace(primary, false, &secs);
    rates.primary.push_back(rate(primary.size(), secs));
    if (diffuse.empty()) continue;
    tracer.trace(diffuse, false, &secs);
    rates.diffuse.push_back(rate(diffuse.size(), secs));
    binaryTracer.trace(diffuse, false, &secs);
    rates.diffuseBinary.push_back(rate(diffuse.size(), secs));
  }
  return rates;
}

}  // namespace

// BVH quality: SAH cost of the binned build (the renderer's) against a full sweep build, with build times.
int runSahBench(const BenchOptions& o, const std::vector<std::string>& scenes) {
  std::printf("%-34s %9s %12s %10s %12s %10s %8s\n", "scene", "triangles", "SAH binned", "build s", "SAH sweep", "build s",
              "binned/");
  std::printf("%-34s %9s %12s %10s %12s %10s %8s\n", "", "", "", "", "", "(1 thread)", "sweep");
  nlohmann::json out = nlohmann::json::array();
  uint32_t binnedThreads = 0;
  for (const std::string& path : scenes) {
    Scene scene = loadGltf(path);
    std::vector<Aabb> bounds = scene.triangleBounds();
    std::vector<double> binnedSeconds;
    Bvh binned;
    for (int r = 0; r < o.runs; ++r) {
      binned = buildBvh(bounds);
      binnedSeconds.push_back(binned.stats.buildSeconds);
      binnedThreads = binned.stats.buildThreads;
    }
    BvhOptions sweepOptions;
    sweepOptions.fullSweep = true;
    sweepOptions.threads = 1;
    Bvh sweep = buildBvh(bounds, sweepOptions);
    double ratio = binned.stats.sahCost / sweep.stats.sahCost;
    std::printf("%-34s %9zu %12.3f %10.3f %12.3f %10.3f %8.4f\n", std::filesystem::path(path).filename().c_str(), bounds.size(),
                binned.stats.sahCost, median(binnedSeconds), sweep.stats.sahCost, sweep.stats.buildSeconds, ratio);
    out.push_back({{"scene", path},
                   {"triangles", bounds.size()},
                   {"sah_binned", binned.stats.sahCost},
                   {"binned_build_seconds", median(binnedSeconds)},
                   {"binned_build_threads", binnedThreads},
                   {"sah_sweep", sweep.stats.sahCost},
                   {"sweep_build_seconds", sweep.stats.buildSeconds},
                   {"ratio", ratio}});
  }
  std::printf(
      "SAH cost: expected traversal steps plus triangle tests per ray (cost 1 each); build s: median of --runs, "
      "binned on %u threads.\n",
      binnedThreads);
  if (!o.jsonPath.empty()) writeFileAtomically(o.jsonPath, nlohmann::json{{"results", out}}.dump(2) + "\n");
  return 0;
}

// Specialized against general pipelines, interleaved run by run: time per sample and pipeline set-up time. On a
// scene with textures, a third variant compiles textures, vertex colours and alpha out (what they cost).
int runSpecializationBench(const BenchOptions& o, const std::vector<std::string>& scenes) {
  vk::Context ctx;
  std::printf("device: %s; %dx%d, %d spp per run, %d runs; medians [min-max]\n", ctx.deviceName().c_str(), o.width, o.height,
              o.spp, o.runs);
  std::printf("%-34s %-12s %14s %22s %12s %10s\n", "scene", "pipelines", "us per sample", "[min-max]", "pipelines s", "Mrays/s");
  nlohmann::json out = nlohmann::json::array();
  for (const std::string& scene : scenes) {
    // Rays per second too: without textures a textured scene's paths differ (albedos, emission), so time per
    // sample alone would mix the cost of texturing with that of other paths.
    std::vector<double> perSample[3], pipes[3], mrays[3];
    int variants = 2;
    for (int run = -1; run < o.runs; ++run)
      for (int general = 0; general < variants; ++general) {
        RenderOptions ro;
        ro.scenePath = scene;
        ro.width = static_cast<uint32_t>(o.width);
        ro.height = static_cast<uint32_t>(o.height);
        ro.spp = static_cast<uint32_t>(o.spp);
        ro.progress = false;
        ro.background = glm::vec3(1.0f);
        ro.specialize = general != 1;
        ro.withoutTextures = general == 2;
        RenderOutcome r = runRender(ctx, ro);
        if (run < 0 && general == 0 && r.features.textures) variants = 3;
        if (run < 0) continue;
        perSample[general].push_back(r.stats.seconds / double(r.film.totalSamples()) * 1e6);
        mrays[general].push_back(double(r.stats.rays()) / r.stats.seconds * 1e-6);
        pipes[general].push_back(r.setup.pipelines);
      }
    std::string name = std::filesystem::path(scene).filename().string();
    const char* labels[3] = {"specialized", "general", "untextured"};
    for (int general = 0; general < variants; ++general) {
      auto [lo, hi] = std::minmax_element(perSample[general].begin(), perSample[general].end());
      std::printf("%-34s %-12s %14.3f %10.3f-%-10.3f %12.3f %10.2f\n", name.c_str(), labels[general], median(perSample[general]),
                  *lo, *hi, median(pipes[general]), median(mrays[general]));
    }
    std::printf("%-34s %-12s %14.2fx\n", "", "ratio", median(perSample[1]) / median(perSample[0]));
    if (variants == 3)
      std::printf("%-34s %-12s %14.2fx time per sample, %.2fx rays per second\n", "", "textured / untextured",
                  median(perSample[0]) / median(perSample[2]), median(mrays[0]) / median(mrays[2]));
    nlohmann::json row = {{"scene", scene},
                          {"specialized_us_per_sample", median(perSample[0])},
                          {"general_us_per_sample", median(perSample[1])},
                          {"specialized_pipeline_seconds", median(pipes[0])},
                          {"general_pipeline_seconds", median(pipes[1])}};
    row["specialized_mrays_per_second"] = median(mrays[0]);
    row["general_mrays_per_second"] = median(mrays[1]);
    if (variants == 3) {
      row["untextured_us_per_sample"] = median(perSample[2]);
      row["untextured_mrays_per_second"] = median(mrays[2]);
    }
    out.push_back(row);
  }
  if (!o.jsonPath.empty())
    writeFileAtomically(o.jsonPath, nlohmann::json{{"device", ctx.deviceName()}, {"results", out}}.dump(2) + "\n");
  return 0;
}

namespace {

// One case per scene and integrator; cases are interleaved run by run so machine noise hits them alike.
struct BenchCase {
  std::string scene;
  Integrator integrator;
  bool traceKernel;  // the traversal-kernel benchmark runs once per scene
  std::string name() const { return std::filesystem::path(scene).filename().string(); }
};

RenderOptions benchRenderOptions(const BenchOptions& o, const BenchCase& c) {
  RenderOptions ro;
  ro.scenePath = c.scene;
  ro.width = static_cast<uint32_t>(o.width);
  ro.height = static_cast<uint32_t>(o.height);
  ro.spp = static_cast<uint32_t>(o.spp);
  ro.progress = false;
  ro.background = glm::vec3(1.0f);  // so scenes without emitters still bounce rays
  ro.workgroupSize = o.workgroupSize;
  ro.wavefrontPaths = o.wavefrontPaths;
  ro.integrator = c.integrator;
  ro.stageTimes = true;  // the per-kernel table and the primary and bounce Mrays/s (samples/s pays for them)
  return ro;
}

// One counted run of a case: its set-up, rates and kernels, and the traversal kernel alone where it runs.
void recordBenchRun(vk::Context& ctx, const BenchOptions& o, const BenchCase& c, const RenderOutcome& r, Samples& s) {
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
  recordKernels(s, st, r.film.totalSamples());
  if (!c.traceKernel) return;
  TraceRates t = traceBenchmark(ctx, c.scene, o.width, o.height, 1, s.diffuseRays);
  s.tracePrimary.insert(s.tracePrimary.end(), t.primary.begin(), t.primary.end());
  s.traceDiffuse.insert(s.traceDiffuse.end(), t.diffuse.begin(), t.diffuse.end());
  s.traceDiffuseBinary.insert(s.traceDiffuseBinary.end(), t.diffuseBinary.begin(), t.diffuseBinary.end());
}

void printBenchHeader(const vk::Context& ctx, const BenchOptions& o, const RenderOutcome::Tuning& tuning) {
  std::printf(
      "device: %s (subgroup %u); %dx%d, %d spp per run, %d runs, workgroup %u%s, wavefront %u paths%s, every stage "
      "timed, medians [min-max]\n",
      ctx.deviceName().c_str(), tuning.subgroupSize, o.width, o.height, o.spp, o.runs, tuning.workgroupSize,
      tuning.workgroupAuto ? " (device's)" : "", tuning.wavefrontPaths, tuning.wavefrontAuto ? " (device's)" : "");
  std::printf("%-34s %-10s %9s %7s %7s %8s %7s | %10s %9s %9s %9s | %9s %9s %9s\n", "scene", "integrator", "triangles", "load s",
              "bvh s", "upload s", "pipes s", "samples/s", "primary", "bounces", "total", "trace 1st", "trace dif", "dif bvh2");
  std::printf("%-34s %-10s %9s %7s %7s %8s %7s | %10s %9s %9s %9s | %9s %9s %9s\n", "", "", "", "", "", "", "", "", "Mrays/s",
              "Mrays/s", "Mrays/s", "Mrays/s", "Mrays/s", "Mrays/s");
}

// A case's row of the table, and its medians as JSON.
nlohmann::json printBenchRow(const BenchCase& c, const Samples& s, double firstPipelines, const RenderOutcome::Tuning& tuning) {
  auto range = [](const std::vector<double>& v) {
    if (v.empty()) return std::make_pair(0.0, 0.0);
    auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    return std::make_pair(*lo, *hi);
  };
  std::printf("%-34s %-10s %9u %7.3f %7.3f %8.3f %7.3f | %10.0f %9.2f %9.2f %9.2f | %9.2f %9.2f %9.2f  [samples/s %.0f-%.0f]\n",
              c.name().c_str(), toString(c.integrator), s.triangles, median(s.load), median(s.bvh), median(s.upload),
              median(s.pipelines), median(s.sps), median(s.primary), median(s.incoherent), median(s.total),
              median(s.tracePrimary), median(s.traceDiffuse), median(s.traceDiffuseBinary), range(s.sps).first,
              range(s.sps).second);
  return {{"scene", c.scene},
          {"integrator", toString(c.integrator)},
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
          {"trace_diffuse_binary_bvh_mrays_per_second", median(s.traceDiffuseBinary)},
          {"trace_diffuse_rays", s.diffuseRays},
          {"pipeline_seconds_first_use", firstPipelines},
          {"workgroup_size", tuning.workgroupSize},
          {"wavefront_paths", tuning.wavefrontPaths}};
}

}  // namespace

int runBenchKernels(const BenchOptions& o) {
  if (o.runs < 1 || o.runs > 1000) throw Error("--runs must be between 1 and 1000");
  if (o.spp < 1 || o.width < 1 || o.height < 1 || o.width > 8192 || o.height > 8192)
    throw Error("bad --spp, --width or --height");
  std::vector<std::string> scenes = o.scenes.empty() ? defaultScenes() : o.scenes;
  if (scenes.empty()) throw Error("no scenes to benchmark");
  if (o.specialization) return runSpecializationBench(o, scenes);
  if (o.sah) return runSahBench(o, scenes);
  vk::Context ctx;
  std::vector<BenchCase> cases;
  for (const std::string& scene : scenes)
    for (size_t k = 0; k < o.integrators.size(); ++k) cases.push_back({scene, integratorFromString(o.integrators[k]), k == 0});
  std::vector<Samples> samples(cases.size());
  // Round 0 warms caches (Mesa's shader cache, the page cache, the allocator) and is not counted, except that
  // its pipeline time is reported as the first-use figure.
  std::vector<double> firstPipelines(cases.size(), 0.0);
  RenderOutcome::Tuning tuning;  // as the last run resolved it (the same for every scene)
  for (int run = -1; run < o.runs; ++run)
    for (size_t i = 0; i < cases.size(); ++i) {
      RenderOutcome r = runRender(ctx, benchRenderOptions(o, cases[i]));
      tuning = r.tuning;
      if (run < 0)
        firstPipelines[i] = r.setup.pipelines;
      else
        recordBenchRun(ctx, o, cases[i], r, samples[i]);
    }
  printBenchHeader(ctx, o, tuning);
  nlohmann::json out = nlohmann::json::array();
  for (size_t i = 0; i < cases.size(); ++i) out.push_back(printBenchRow(cases[i], samples[i], firstPipelines[i], tuning));
  std::printf(
      "primary/bounces: wavefront intersection stages (GPU time; none in the megakernel); total: all rays over\n"
      "render wall time;\n"
      "trace 1st/dif: the traversal kernel alone (4-wide BVH) on camera rays and on 4 cosine bounce rays per primary\n"
      "hit; dif bvh2: the same bounce rays through the binary BVH, interleaved.\n"
      "pipelines: creation plus first-dispatch compile, median of warm runs; first use in this process: %.3f s\n"
      "(Mesa's on-disk shader cache may make even that warm; clear ~/.cache/vkmc for a cold figure).\n",
      firstPipelines.front());
  for (size_t i = 0; i < cases.size(); ++i)
    out[i]["per_kernel"] = printKernels(cases[i].name() + " [" + toString(cases[i].integrator) + "]", samples[i]);
  std::printf(
      "\nitems: rays for the tracing kernels and the megakernel, paths for camera_rays and shade, samples for\n"
      "accumulate;\n"
      "est. GB/s: path-state, queue, hit, shadow-ray and film bytes moved (BVH and triangle fetches not counted).\n");
  if (!o.jsonPath.empty())
    writeFileAtomically(o.jsonPath, nlohmann::json{{"device", ctx.deviceName()}, {"results", out}}.dump(2) + "\n");
  return 0;
}

}  // namespace vkmc
