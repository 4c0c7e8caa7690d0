// `vkmc info SCENE`: the options of the scene report (app/info.cpp prints it).
#include <CLI/CLI.hpp>

#include <memory>

#include "app/commands.h"
#include "app/info.h"

namespace vkmc {

Command addInfoCommand(CLI::App& app) {
  struct InfoArgs {
    RenderOptions options;
    bool general = false;
  };
  auto a = std::make_shared<InfoArgs>();
  CLI::App* info = app.add_subcommand("info", "scene features, kernels and specialization constants, BVH and memory");
  info->add_option("scene", a->options.scenePath, "scene (.gltf or .glb)")->required();
  info->add_flag("--no-specialize", a->general, "show the general pipelines (every feature on)");
  return {info, [a] {
            a->options.specialize = !a->general;
            return runInfo(a->options);
          }};
}

}  // namespace vkmc
