// The vkmc subcommands, one file each (command_*.cpp): each adds its options to the CLI11 app and returns the
// function that runs it once the command line is parsed. Exit codes: 0 success, 1 error (vkmc::Error thrown).
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace vkmc {

struct Command {
  CLI::App* app;             // the subcommand: run it when app->parsed()
  std::function<int()> run;  // reads the option values bound at registration
};

Command addRenderCommand(CLI::App& app);
Command addInfoCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);  // the error-against-time study
Command addCompareCommand(CLI::App& app);
Command addBenchKernelsCommand(CLI::App& app);
Command addBenchTexturesCommand(CLI::App& app);

// A count flag that also takes "auto" (returned as 0: the device chooses, device_tuning.h), e.g. --workgroup.
uint32_t parseCountOrAuto(const std::string& text, const char* flag);
// A switch that also takes "auto" (nullopt: the device chooses), e.g. --stage-times.
std::optional<bool> parseOnOffAuto(const std::string& text, const char* flag);

}  // namespace vkmc
