// The table of pre-specialized SPIR-V variants (spirv/kernel_variants_index.h, generated) and the choice.
#include "render/kernel_variants.h"

#include "spirv/kernel_variants_index.h"

namespace vkmc {

namespace {
template <size_t N>
std::vector<vk::SpecConstant> fixedList(const uint32_t (&fixed)[N][2]) {
  std::vector<vk::SpecConstant> list;
  for (const auto& f : fixed) list.push_back({f[0], f[1]});
  return list;
}

std::vector<SpirvVariantInfo> buildTable() {
  std::vector<SpirvVariantInfo> table;
#define VKMC_VARIANT_ROW(kernel, name, spirv, fixed) \
  table.push_back({kernel, std::span<const uint32_t>(spirv), name, fixedList(fixed)});
  VKMC_ALL_SPIRV_VARIANTS(VKMC_VARIANT_ROW)
#undef VKMC_VARIANT_ROW
  return table;
}

bool matches(const SpirvVariantInfo& v, const std::vector<vk::SpecConstant>& specs) {
  for (const vk::SpecConstant& f : v.fixed) {
    bool found = false;
    for (const vk::SpecConstant& s : specs) {
      if (s.id != f.id) continue;
      if (s.value != f.value) return false;
      found = true;
    }
    if (!found) return false;  // left at its default, which the variant does not know
  }
  return true;
}
}  // namespace

std::span<const SpirvVariantInfo> spirvVariants() {
  static const std::vector<SpirvVariantInfo> table = buildTable();
  return table;
}

ChosenSpirv chooseSpirv(std::string_view kernel, std::span<const uint32_t> general, const std::vector<vk::SpecConstant>& specs) {
  for (const SpirvVariantInfo& v : spirvVariants())
    if (v.kernel == kernel && matches(v, specs)) return {v.spirv, v.name};
  return {general, ""};
}

}  // namespace vkmc
