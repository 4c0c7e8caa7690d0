// Pre-specialized SPIR-V (render/kernel_variants.h, cmake/specialize_spirv.py): chosen exactly where the render's
// constants match a variant's fixed ones, and the same image, bit for bit, as the general SPIR-V it comes from.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>

#include "../shaders/shared/layout.h"
#include "app/render_job.h"
#include "io/exr.h"
#include "render/kernel_variants.h"
#include "support/render_helpers.h"

using namespace vkmc;
using vkmc::test::scenePath;
using vkmc::test::sharedContext;

namespace {
const SpirvVariantInfo* find(const std::string& kernel, const std::string& name) {
  for (const SpirvVariantInfo& v : spirvVariants())
    if (v.kernel == kernel && v.name == name) return &v;
  return nullptr;
}
}  // namespace

TEST(KernelVariants, TheCommonFeatureSetsAreBuiltForShadingAndTheWalks) {
  for (const char* kernel : {"shade", "shade_atomic"})
    for (const char* set : {"lambertian", "glossy", "textured"}) EXPECT_NE(find(kernel, set), nullptr) << kernel << " " << set;
  // The walks read none of the material constants, so their lambertian and glossy variants are one.
  for (const char* kernel : {"intersect", "intersect_deep", "shadow", "shadow_deep"}) {
    EXPECT_NE(find(kernel, "lambertian+glossy"), nullptr) << kernel;
    EXPECT_NE(find(kernel, "textured"), nullptr) << kernel;
  }
}

TEST(KernelVariants, AVariantIsChosenOnlyWhereEveryFixedConstantMatches) {
  ASSERT_FALSE(spirvVariants().empty());
  const std::vector<uint32_t> general(64, 0u);  // stands for the general SPIR-V: never a variant's words
  for (const SpirvVariantInfo& v : spirvVariants()) {
    ASSERT_FALSE(v.fixed.empty()) << v.kernel << " " << v.name;
    ASSERT_GE(v.spirv.size(), 5u);
    EXPECT_EQ(v.spirv[0], 0x07230203u) << v.kernel << " " << v.name;  // SPIR-V's magic number
    std::vector<vk::SpecConstant> specs = v.fixed;
    specs.push_back({SPEC_WORKGROUP_SIZE, 64u});  // constants a variant leaves open do not matter
    ChosenSpirv chosen = chooseSpirv(v.kernel, general, specs);
    EXPECT_EQ(chosen.variant, v.name) << v.kernel;
    EXPECT_EQ(chosen.spirv.data(), v.spirv.data()) << v.kernel << " " << v.name;
    for (size_t i = 0; i < v.fixed.size(); ++i) {
      std::vector<vk::SpecConstant> changed = specs, missing;
      changed[i].value ^= 1u;
      for (size_t j = 0; j < specs.size(); ++j)
        if (j != i) missing.push_back(specs[j]);
      // Another variant may fit the changed value, this one never; a constant left at its default fits none.
      EXPECT_NE(chooseSpirv(v.kernel, general, changed).spirv.data(), v.spirv.data())
          << v.kernel << " " << v.name << " id " << v.fixed[i].id;
      EXPECT_NE(chooseSpirv(v.kernel, general, missing).spirv.data(), v.spirv.data())
          << v.kernel << " " << v.name << " id " << v.fixed[i].id;
    }
    EXPECT_EQ(chooseSpirv("no_such_kernel", general, specs).spirv.data(), general.data()) << "a variant of another kernel";
  }
}

struct VariantCase {
  std::string name, path, expectedSet;
  float bsdfSamples = 1.0f;  // > 1: paths split, and shade is built with float atomics (shade_atomic)
};
void PrintTo(const VariantCase& c, std::ostream* os) { *os << c.path; }
class PrespecializedSpirv : public ::testing::TestWithParam<VariantCase> {};

TEST_P(PrespecializedSpirv, RendersTheGeneralSpirvsImageBitForBit) {
  const VariantCase& c = GetParam();
  if (!std::filesystem::exists(c.path)) GTEST_SKIP() << "no " << c.path;
  RenderOptions o;
  o.scenePath = c.path;
  o.width = 24;
  o.height = 24;
  o.spp = 8;
  o.seed = 3;
  o.progress = false;
  o.integrator = Integrator::Wavefront;
  o.estimator.bsdfSamples = c.bsdfSamples;
  RenderOutcome pre = runRender(sharedContext(), o);
  EXPECT_EQ(pre.spirvVariant, c.expectedSet);
  o.prespecializedSpirv = false;
  RenderOutcome general = runRender(sharedContext(), o);
  EXPECT_EQ(general.spirvVariant, "");
  if (c.bsdfSamples <= 1.0f) {
    EXPECT_EQ(encodeFilmExr(pre.film), encodeFilmExr(general.film)) << "the images differ";
  } else {
    // Split paths add into the film with float atomics, whose order varies from run to run (so does the general
    // SPIR-V's image): the same paths, the sums equal to rounding.
    ExrImage a = filmToImage(pre.film), b = filmToImage(general.film);
    for (const char* ch : {"R", "G", "B"})
      for (size_t i = 0; i < a.channels[ch].size(); ++i) {
        float x = a.channels[ch][i], y = b.channels[ch][i];
        ASSERT_LE(std::abs(x - y), 1e-5f * (std::abs(x) + std::abs(y)) + 1e-7f) << ch << " pixel " << i;
      }
  }
  EXPECT_EQ(pre.stats.rays(), general.stats.rays());
}

INSTANTIATE_TEST_SUITE_P(KernelVariants, PrespecializedSpirv,
                         ::testing::Values(VariantCase{"cornell_box", scenePath("cornell_box.gltf"), "lambertian"},
                                           VariantCase{"cornell_box_split", scenePath("cornell_box.gltf"), "lambertian", 2.0f},
                                           VariantCase{"veach_mis", scenePath("veach_mis.gltf"), "glossy"},
                                           VariantCase{"shared_DamagedHelmet",
                                                       std::string(VKMC_SHARED_SCENES) + "/DamagedHelmet/DamagedHelmet.gltf",
                                                       "textured"}),
                         [](const auto& info) { return info.param.name; });
