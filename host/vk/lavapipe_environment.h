// What lavapipe (Mesa's CPU Vulkan driver) reads from the environment when its first instance is made: the SIMD
// width of its kernels, and where it caches their machine code. Chosen once per process, before any Vulkan call.
#pragma once

namespace vkmc::vk {

struct LavapipeEnvironment {
  unsigned vectorBits = 0;    // LP_NATIVE_VECTOR_WIDTH as lavapipe will use it: 128, 256 or 512 (its subgroup x 32)
  bool vectorChosen = false;  // vkmc set it (cpuPrefersSixteenLanes), not the user
};

// Whether 16-lane kernels (512-bit) beat lavapipe's default 8 on this CPU, as measured: on an AMD EPYC with AVX-512
// they rendered 9-15% faster; on an Intel Xeon with AVX-512 (Sapphire Rapids) 7-13% slower (a 512-bit instruction
// costs it more than two 256-bit ones): docs/journal/performance.md, "Sixteen lanes" and "Eight lanes on an Intel
// Xeon". So: AVX-512 on an AMD CPU.
bool cpuPrefersSixteenLanes();

// Where the CPU prefers 16 lanes and no LP_NATIVE_VECTOR_WIDTH is given, sets it to 512; and gives Mesa's shader cache a
// directory per width unless the user chose one. Mesa 22.3 keys its cached machine code without the width, so a run at another
// width would load kernels compiled for the old one while the device reports the new subgroup size. Idempotent: the first call
// decides.
const LavapipeEnvironment& prepareLavapipeEnvironment();

}  // namespace vkmc::vk
