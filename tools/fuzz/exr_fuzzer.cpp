// libFuzzer entry: any bytes as an OpenEXR file, decoded as io/exr reads references, `compare`'s images and
// environment maps (decodeExr). OpenEXR itself is not instrumented; decodeExr's own checks are.
#include <cstdint>
#include <string>

#include "cpu_timeout.h"
#include "error.h"
#include "io/exr.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vkmc::fuzz::CpuTimeout timeout;
  try {
    vkmc::decodeExr(std::string(reinterpret_cast<const char*>(data), size), "fuzz input",
                    uint64_t(1) << 16);  // small: fast inputs, and the size check under test
  } catch (const vkmc::Error&) {
  }
  return 0;
}
