// `vkmc bench-textures [SCENES]`: texture lookups in each device form on each scene's textures, coherent and
// incoherent, interleaved round by round (bench/texture_forms.h). Medians [min-max] of GPU time per lookup.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "analysis/summary_statistics.h"
#include "app/commands.h"
#include "bench/texture_forms.h"
#include "error.h"
#include "render/gpu_scene.h"
#include "scene/gltf_loader.h"
#include "vk/context.h"

namespace vkmc {

namespace {

struct BenchTexturesOptions {
  std::vector<std::string> scenes;
  uint32_t invocations = 1u << 18;
  int rounds = 7;
};

std::vector<std::string> defaultTexturedScenes() {
  std::vector<std::string> out;
  for (const char* candidate :
       {"../shared/scenes/DamagedHelmet/DamagedHelmet.gltf", "../shared/scenes/BoxTextured/BoxTextured.gltf"})
    if (std::filesystem::exists(candidate)) out.push_back(candidate);
  if (out.empty()) throw Error("bench-textures: no scenes given and ../shared/scenes has none of the default textured models");
  return out;
}

int runBenchTextures(const BenchTexturesOptions& o) {
  if (o.invocations == 0 || o.invocations > (1u << 24)) throw Error("--invocations must be in [1, 16777216]");
  if (o.rounds < 1 || o.rounds > 1000) throw Error("--rounds must be in [1, 1000]");
  std::vector<std::string> scenes = o.scenes.empty() ? defaultTexturedScenes() : o.scenes;
  vk::Context ctx;
  std::printf("Device: %s; %u invocations (a surface point each, up to 4 slot lookups), %d rounds interleaved,\n",
              ctx.deviceName().c_str(), o.invocations, o.rounds);
  std::printf("GPU time per lookup, medians [min-max]; diff: largest channel difference from the sampled image form\n");
  std::printf("%-22s %-10s %9s  %-18s %22s %8s %10s\n", "scene", "order", "lookups", "form", "ns/lookup", "ratio", "diff");
  for (const std::string& path : scenes) {
    Scene scene = loadGltf(path, deviceLoadLimits(ctx));
    if (scene.textures.empty()) throw Error("bench-textures: " + path + " has no textures");
    std::string name = std::filesystem::path(path).filename().string();
    for (bool coherent : {true, false}) {
      std::vector<gpu::TestRay> lookups = makeTextureLookups(scene, o.invocations, coherent, 1u);
      std::vector<TextureFormTiming> forms = timeTextureForms(ctx, scene, lookups, o.rounds);
      double base = median(forms.front().nsPerLookup);
      for (const TextureFormTiming& f : forms) {
        if (!f.skipped.empty()) {
          std::printf("%-22s %-10s %9s  %-18s skipped: %s\n", name.c_str(), coherent ? "coherent" : "incoherent", "",
                      f.form.c_str(), f.skipped.c_str());
          continue;
        }
        auto [lo, hi] = std::minmax_element(f.nsPerLookup.begin(), f.nsPerLookup.end());
        char range[64];
        std::snprintf(range, sizeof range, "%.2f [%.2f-%.2f]", median(f.nsPerLookup), *lo, *hi);
        std::printf("%-22s %-10s %9llu  %-18s %22s %8.2f %10.2e\n", name.c_str(), coherent ? "coherent" : "incoherent",
                    (unsigned long long)countTextureLookups(lookups), f.form.c_str(), range, median(f.nsPerLookup) / base,
                    f.maxDifference);
      }
    }
  }
  std::printf(
      "forms: sampled image = the renderer's (the texture pages as an array image, filtered and sRGB-decoded\n"
      "by the sampler); texel buffer = the same pages' RGBA8 texels in a storage texel buffer, bilinear in the\n"
      "kernel, sRGB by pow per tap (the renderer's form until 2026-11-28)\n");
  return 0;
}

}  // namespace

Command addBenchTexturesCommand(CLI::App& app) {
  auto o = std::make_shared<BenchTexturesOptions>();
  CLI::App* bench = app.add_subcommand("bench-textures", "texture lookups per device form (texel buffers, sampled images)");
  bench->add_option("scenes", o->scenes, "textured scenes (default: DamagedHelmet and BoxTextured from ../shared/scenes)");
  bench->add_option("--invocations", o->invocations, "surface points looked up per dispatch")->capture_default_str();
  bench->add_option("--rounds", o->rounds, "timed rounds, each form once per round")->capture_default_str();
  return {bench, [o] { return runBenchTextures(*o); }};
}

}  // namespace vkmc
