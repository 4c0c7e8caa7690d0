// What lavapipe (Mesa's CPU Vulkan driver) reads from the environment when its first instance is made: the SIMD
// width of its kernels, and where it caches their machine code. Chosen once per process, before any Vulkan call.
#pragma once

namespace vkmc::vk {

struct LavapipeEnvironment {
  unsigned vectorBits = 0;    // LP_NATIVE_VECTOR_WIDTH as lavapipe will use it: 128, 256 or 512 (its subgroup x 32)
  bool vectorChosen = false;  // vkmc set it (the CPU has AVX-512: docs/journal/performance.md, "Sixteen lanes"), not the user
};

// On a CPU with AVX-512 and no LP_NATIVE_VECTOR_WIDTH given, sets it to 512 (16-lane kernels, measured faster
// than lavapipe's default 8); and gives Mesa's shader cache a directory per width unless the user chose one. Mesa
// 22.3 keys its cached machine code without the width, so a run at another width would load kernels compiled for
// the old one while the device reports the new subgroup size. Idempotent: the first call decides.
const LavapipeEnvironment& prepareLavapipeEnvironment();

}  // namespace vkmc::vk
