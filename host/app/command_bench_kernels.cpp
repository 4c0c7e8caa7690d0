// `vkmc bench-kernels [SCENES]`: the options of the kernel benchmark (app/bench_kernels.cpp runs it).
#include <CLI/CLI.hpp>

#include <memory>
#include <string>

#include "app/bench_kernels.h"
#include "app/commands.h"
#include "render/path_pool.h"

namespace vkmc {

Command addBenchKernelsCommand(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* bench = app.add_subcommand("bench-kernels", "set-up split, samples/s and Mrays/s per scene (medians)");
  bench->add_option("scenes", o->scenes, "scenes (default: the Cornell box and ../shared/scenes benchmark models)");
  bench->add_option("--runs", o->runs, "timed runs per scene")->capture_default_str();
  bench->add_option("--spp", o->spp, "samples per pixel per run")->capture_default_str();
  bench->add_option("--width", o->width, "image width")->capture_default_str();
  bench->add_option("--height", o->height, "image height")->capture_default_str();
  bench->add_option("--json", o->jsonPath, "write the results as JSON");
  bench->add_flag("--specialization", o->specialization, "compare specialized with general (all-features) pipelines");
  auto workgroup = std::make_shared<std::string>("auto"), wavefront = std::make_shared<std::string>("auto");
  bench->add_option("--workgroup", *workgroup, "invocations per workgroup of every kernel: " + workgroupSizesText() + ", or auto")
      ->capture_default_str();
  bench->add_option("--wavefront", *wavefront, "paths in flight per pass at most (" + wavefrontRangeText() + "), or auto")
      ->capture_default_str();
  bench->add_flag("--sah", o->sah, "BVH quality: SAH cost of the binned build against a full sweep build");
  bench->add_option("--integrator", o->integrators, "wavefront, megakernel or both (interleaved, side by side)")
      ->check(CLI::IsMember({"wavefront", "megakernel"}))
      ->expected(1, 2);
  return {bench, [o, workgroup, wavefront] {
            o->workgroupSize = parseCountOrAuto(*workgroup, "--workgroup");
            o->wavefrontPaths = parseCountOrAuto(*wavefront, "--wavefront");
            return runBenchKernels(*o);
          }};
}

}  // namespace vkmc
