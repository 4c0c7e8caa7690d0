// libFuzzer entry: any bytes as a Radiance .hdr environment map (io/radiance_hdr). A vkmc::Error is the expected
// outcome of bad input; a finding is a crash, a sanitizer report, a hang (CPU time) or an allocation past the cap.
#include <cstdint>
#include <string_view>

#include "cpu_timeout.h"
#include "error.h"
#include "io/radiance_hdr.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vkmc::fuzz::CpuTimeout timeout;
  try {
    vkmc::decodeRadianceHdr(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz input", 1u << 20);
  } catch (const vkmc::Error&) {
  }
  return 0;
}
