// libFuzzer entry: any bytes as a checkpoint file (io/checkpoint). Most inputs fail the checksum at once, so the
// harness also reseals each input's body with a valid checksum: the header and payload checks behind it are what
// a forged file meets. A vkmc::Error is the expected outcome.
#include <cstdint>
#include <cstring>
#include <string>

#include "cpu_timeout.h"
#include "error.h"
#include "io/checkpoint.h"
#include "scene/content_hash.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vkmc::fuzz::CpuTimeout timeout;
  std::string bytes(reinterpret_cast<const char*>(data), size);
  for (int resealed = 0; resealed < 2; ++resealed) {
    if (resealed && bytes.size() >= 8) {
      vkmc::ContentHash h;
      h.add(bytes.data(), bytes.size() - 8);
      const uint64_t sum = h.value();
      std::memcpy(bytes.data() + bytes.size() - 8, &sum, 8);
    }
    try {
      vkmc::decodeCheckpoint(bytes, "fuzz input");
    } catch (const vkmc::Error&) {
    }
  }
  return 0;
}
