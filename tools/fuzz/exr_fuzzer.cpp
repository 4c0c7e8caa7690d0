// libFuzzer entry: any bytes as an OpenEXR file read by io/exr readExr (references, `compare`, environment maps),
// through a file in /tmp as vkmc reads one. OpenEXR itself is not instrumented; readExr's own checks are.
#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <string>

#include "cpu_timeout.h"
#include "error.h"
#include "io/exr.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vkmc::fuzz::CpuTimeout timeout;
  static const std::string path = "/tmp/vkmc-exr-fuzz-" + std::to_string(::getpid()) + ".exr";
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
  try {
    vkmc::readExr(path, uint64_t(1) << 22);
  } catch (const vkmc::Error&) {
  }
  return 0;
}
