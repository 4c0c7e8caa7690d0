// Pre-specialized SPIR-V (cmake/specialize_spirv.py): variants of the largest kernels built for the commonest
// scenes' features, with the code those features switch off already removed. lavapipe parses and inlines a
// module's whole SPIR-V before its specialization constants remove anything, so a variant creates its pipeline
// several times faster (shade: 0.2 s general). A variant is used only where each constant it fixes has that value in
// the render's specialization; it computes exactly what the general SPIR-V does under those constants.
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "vk/kernel.h"

namespace vkmc {

struct ChosenSpirv {
  std::span<const uint32_t> spirv;
  std::string variant;  // the feature sets it was built for ("lambertian+glossy"); empty: the general SPIR-V
};

// The SPIR-V to create a kernel from: the first variant of kernel `kernel` (its SPIR-V's name in the build,
// "shade_atomic") whose fixed constants all appear in `specs` with the same values, else `general` itself.
ChosenSpirv chooseSpirv(std::string_view kernel, std::span<const uint32_t> general, const std::vector<vk::SpecConstant>& specs);

struct SpirvVariantInfo {
  std::string kernel;
  std::span<const uint32_t> spirv;
  std::string name;
  std::vector<vk::SpecConstant> fixed;
};
// Every variant built into this binary.
std::span<const SpirvVariantInfo> spirvVariants();

}  // namespace vkmc
