// vkmc command line: the subcommands (app/command_*.cpp), parsed and dispatched. Exit 0 on success, 1 on an
// error, 2 on bad usage.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <vector>

#include "app/commands.h"
#include "error.h"

int main(int argc, char** argv) {
  CLI::App app{"vkmc: a Vulkan compute Monte Carlo path tracer whose efficiency is measured"};
  app.require_subcommand(1);
  const std::vector<vkmc::Command> commands = {vkmc::addRenderCommand(app), vkmc::addInfoCommand(app), vkmc::addBenchCommand(app),
                                               vkmc::addCompareCommand(app), vkmc::addBenchKernelsCommand(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    std::fprintf(stderr, "vkmc: error: %s (see vkmc --help)\n", msg.c_str());
    return 2;
  }

  try {
    for (const vkmc::Command& c : commands)
      if (c.app->parsed()) return c.run();
  } catch (const std::exception& e) {  // vkmc::Error and anything else: one line, exit 1
    std::fprintf(stderr, "vkmc: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
