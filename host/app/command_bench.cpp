// `vkmc bench STUDY`: an error-against-time study (app/study.h) and where its outputs went.
#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <memory>

#include "app/study.h"
#include "app/commands.h"

namespace vkmc {

Command addBenchCommand(CLI::App& app) {
  struct BenchArgs {
    std::string studyPath, outDir;
  };
  auto a = std::make_shared<BenchArgs>();
  CLI::App* bench = app.add_subcommand("bench", "error-against-time study: renders, results.csv/json, SVG plot, summary, images");
  bench->add_option("study", a->studyPath, "study file (JSON; see host/app/study.h and scenes/studies/)")->required();
  bench->add_option("-o,--output", a->outDir, "output folder (default bench-<study name>)");
  return {bench, [a] {
            Study study = loadStudy(a->studyPath);
            std::string dir = a->outDir.empty() ? "bench-" + study.name : a->outDir;
            runStudy(study, dir);
            std::ifstream summary(dir + "/summary.md");
            std::cout << summary.rdbuf() << "wrote " << dir << "/{";
            for (const char* name : kStudyOutputFiles) std::cout << (name == kStudyOutputFiles[0] ? "" : ",") << name;
            std::cout << "}\n";
            return 0;
          }};
}

}  // namespace vkmc
