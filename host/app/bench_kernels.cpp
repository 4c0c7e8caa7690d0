// Benchmark: each scene is set up once per run (so set-up is measured too), warmed with one sample, then
// timed. Scenes are interleaved run by run so machine noise hits them alike; medians and min-max reported.
#include "app/bench_kernels.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "app/render_job.h"
#include "error.h"
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
  std::vector<double> load, bvh, upload, pipelines, sps, primary, incoherent, total;
  uint32_t triangles = 0;
};

}  // namespace

int runBenchKernels(const BenchOptions& o) {
  if (o.runs < 1 || o.runs > 1000) throw Error("--runs must be between 1 and 1000");
  if (o.spp < 1 || o.width < 1 || o.height < 1 || o.width > 8192 || o.height > 8192) throw Error("bad --spp, --width or --height");
  std::vector<std::string> scenes = o.scenes.empty() ? defaultScenes() : o.scenes;
  if (scenes.empty()) throw Error("no scenes to benchmark");
  vk::Context ctx;
  std::vector<Samples> samples(scenes.size());
  for (int run = 0; run < o.runs; ++run) {
    for (size_t i = 0; i < scenes.size(); ++i) {
      RenderOptions ro;
      ro.scenePath = scenes[i];
      ro.width = static_cast<uint32_t>(o.width);
      ro.height = static_cast<uint32_t>(o.height);
      ro.spp = static_cast<uint32_t>(o.spp);
      ro.progress = false;
      ro.background = glm::vec3(1.0f);  // so scenes without emitters still bounce rays
      RenderOutcome r = runRender(ctx, ro);
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
    }
  }
  std::printf("device: %s; %dx%d, %d spp per run, %d runs, medians [min-max]\n", ctx.deviceName().c_str(), o.width, o.height,
              o.spp, o.runs);
  std::printf("%-28s %9s %8s %7s %8s %9s | %10s %12s %14s %12s\n", "scene", "triangles", "load s", "bvh s", "upload s",
              "pipes s", "samples/s", "primary Mr/s", "incoherent Mr/s", "total Mr/s");
  nlohmann::json out = nlohmann::json::array();
  for (size_t i = 0; i < scenes.size(); ++i) {
    const Samples& s = samples[i];
    auto range = [](const std::vector<double>& v) {
      auto [lo, hi] = std::minmax_element(v.begin(), v.end());
      return std::make_pair(*lo, *hi);
    };
    std::string name = std::filesystem::path(scenes[i]).filename().string();
    std::printf("%-28s %9u %8.3f %7.3f %8.3f %9.3f | %10.0f %12.2f %14.2f %12.2f  [total %.2f-%.2f]\n", name.c_str(),
                s.triangles, median(s.load), median(s.bvh), median(s.upload), median(s.pipelines), median(s.sps),
                median(s.primary), median(s.incoherent), median(s.total), range(s.total).first, range(s.total).second);
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
                   {"pipeline_seconds_first_run", s.pipelines.front()}});
  }
  std::printf("pipelines: creation plus first-dispatch compile; the first run may pay Mesa's cold disk cache (%.3f s here).\n",
              samples.front().pipelines.front());
  if (!o.jsonPath.empty())
    writeFileAtomically(o.jsonPath, nlohmann::json{{"device", ctx.deviceName()}, {"results", out}}.dump(2) + "\n");
  return 0;
}

}  // namespace vkmc
