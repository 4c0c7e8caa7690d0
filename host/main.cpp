// vkmc command line: the subcommands (app/command_*.cpp), parsed and dispatched. Exit 0 on success, 1 on an
// error, 2 on bad usage.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <vector>

#include <unistd.h>

#include "app/commands.h"
#include "app/malloc_tuning.h"
#include "dist/rank_group.h"
#include "error.h"

int main(int argc, char** argv) {
  vkmc::tuneMallocByReexecuting(argv);  // first: glibc reads its tunables only at start
  CLI::App app{"vkmc: a Vulkan compute Monte Carlo path tracer whose efficiency is measured"};
  app.require_subcommand(1);
  const std::vector<vkmc::Command> commands = {vkmc::addRenderCommand(app),       vkmc::addInfoCommand(app),
                                               vkmc::addBenchCommand(app),        vkmc::addCompareCommand(app),
                                               vkmc::addBenchKernelsCommand(app), vkmc::addBenchTexturesCommand(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    std::fprintf(stderr, "vkmc: error: %s (see vkmc --help)\n", msg.c_str());
    return 2;
  }

  // Under mpirun every rank runs the command (dist/rank_group.h); outside it the group is this process alone.
  vkmc::RankGroup* group = nullptr;
  try {
    if (vkmc::launchedByMpi()) group = &vkmc::RankGroup::world();
    for (const vkmc::Command& c : commands)
      if (c.app->parsed()) {
        int code = c.run();
        if (group) group->finish();
        return code;
      }
  } catch (const std::exception& e) {  // vkmc::Error and anything else: one line, exit 1
    if (group && group->distributed()) {
      // A failure every rank shares (a bad option, a missing scene) is said once, by rank 0, whose abort ends the
      // others first; a rank failing alone says so with its name after a moment, then ends the job.
      if (!group->isRoot()) ::sleep(2);
      std::fprintf(stderr, "vkmc: error: %s%s\n", group->isRoot() ? "" : (group->describe() + ": ").c_str(), e.what());
      std::fflush(stderr);
      group->abort(1);
    }
    std::fprintf(stderr, "vkmc: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
