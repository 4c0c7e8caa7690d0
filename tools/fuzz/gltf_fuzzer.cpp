// libFuzzer entry: any bytes as a .gltf (or a .glb when they start with its magic), loaded as vkmc loads a scene
// file, then the BVH built over what loaded. A finding is a crash, a sanitizer report, a hang or a leak; a
// vkmc::Error (or another exception main() turns into one line) is the expected outcome of bad input.
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "bvh/bvh.h"
#include "cpu_timeout.h"
#include "error.h"
#include "scene/gltf_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vkmc::fuzz::CpuTimeout timeout;
  std::vector<unsigned char> bytes(data, data + size);
  bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  // External URIs resolve here: the corpus folder holds the seeds' .bin files.
  const char* baseDir = std::getenv("VKMC_FUZZ_BASEDIR");
  vkmc::LoadLimits limits;  // smaller than vkmc's, so that one input stays fast; the checks are the same
  limits.maxTriangles = 1u << 18;
  limits.input.maxJsonValues = 1u << 18;
  limits.input.maxExternalFileBytes = 1u << 26;
  try {
    vkmc::Scene scene = vkmc::loadGltfFromMemory(bytes, binary, baseDir ? baseDir : ".", "fuzz input", limits);
    vkmc::Bvh bvh = vkmc::buildBvh(scene.triangleBounds());
    if (bvh.wideNodes.empty()) std::abort();
  } catch (const std::exception&) {
  }
  return 0;
}
