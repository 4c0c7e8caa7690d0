#include "vk/lavapipe_environment.h"

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

namespace vkmc::vk {
namespace {

bool cpuHasAvx() {
#if defined(__x86_64__) || defined(__i386__)
  return __builtin_cpu_supports("avx");
#else
  return false;
#endif
}

bool set(const char* name) {
  const char* v = std::getenv(name);
  return v && *v;
}

LavapipeEnvironment decide() {
  LavapipeEnvironment e;
  if (set("LP_NATIVE_VECTOR_WIDTH")) {
    e.vectorBits = unsigned(std::strtoul(std::getenv("LP_NATIVE_VECTOR_WIDTH"), nullptr, 10));
  } else if (cpuPrefersSixteenLanes()) {
    e.vectorBits = 512;
    e.vectorChosen = setenv("LP_NATIVE_VECTOR_WIDTH", "512", 0) == 0;
    if (!e.vectorChosen) e.vectorBits = 256;
  } else {
    e.vectorBits = cpuHasAvx() ? 256 : 128;  // lavapipe's own choice
  }
  const bool disabled = set("MESA_SHADER_CACHE_DISABLE") && std::string(std::getenv("MESA_SHADER_CACHE_DISABLE")) != "false";
  if (!set("MESA_SHADER_CACHE_DIR") && !disabled) {
    std::string base = set("XDG_CACHE_HOME") ? std::getenv("XDG_CACHE_HOME")
                       : set("HOME")         ? std::string(std::getenv("HOME")) + "/.cache"
                                             : "";
    if (!base.empty()) {
      const std::string dir = base + "/vkmc/mesa-lp" + std::to_string(e.vectorBits);
      std::error_code ec;
      std::filesystem::create_directories(dir, ec);  // Mesa makes only the last level
      if (!ec) setenv("MESA_SHADER_CACHE_DIR", dir.c_str(), 0);
    }
  }
  return e;
}

}  // namespace

bool cpuPrefersSixteenLanes() {
#if defined(__x86_64__) || defined(__i386__)
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_is("amd");  // libgcc checks the OS's zmm state too
#else
  return false;
#endif
}

const LavapipeEnvironment& prepareLavapipeEnvironment() {
  static const LavapipeEnvironment environment = decide();
  return environment;
}

}  // namespace vkmc::vk
