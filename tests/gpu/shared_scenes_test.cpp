// Every model in ../shared/scenes loads and renders a few samples with no non-finite sample.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "app/render_job.h"
#include "support/param_name.h"

using namespace vkmc;
namespace fs = std::filesystem;

namespace {
// Every .gltf and .glb one folder below ../shared/scenes (none when it is absent), in name order.
std::vector<fs::path> sharedModels() {
  std::vector<fs::path> models;
  fs::path root = VKMC_SHARED_SCENES;
  if (!fs::is_directory(root)) return models;
  for (const auto& dir : fs::directory_iterator(root)) {
    if (!dir.is_directory()) continue;
    for (const auto& file : fs::directory_iterator(dir.path())) {
      std::string ext = file.path().extension().string();
      if (ext == ".gltf" || ext == ".glb") models.push_back(file.path());
    }
  }
  std::sort(models.begin(), models.end());
  return models;
}

vk::Context& context() {
  static vk::Context ctx;
  return ctx;
}

class SharedScene : public ::testing::TestWithParam<fs::path> {};
}  // namespace

TEST(SharedScenes, AtLeastSevenModelsArePresent) {
  fs::path root = VKMC_SHARED_SCENES;
  if (!fs::is_directory(root)) GTEST_SKIP() << "no shared scenes at " << root;
  EXPECT_GE(sharedModels().size(), 7u);
}

TEST_P(SharedScene, LoadsAndRendersFinite) {
  RenderOptions o;
  o.scenePath = GetParam().string();
  o.width = 48;
  o.height = 48;
  o.spp = 2;
  o.progress = false;
  o.background = glm::vec3(1.0f);  // scenes without emitters are lit by the background
  RenderOutcome r = runRender(context(), o);
  EXPECT_EQ(r.film.totalNonfinite(), 0u);
  EXPECT_EQ(r.film.totalSamples(), 48u * 48u * 2u);
  glm::dvec3 mean = r.film.imageMean();
  EXPECT_GT(mean.x + mean.y + mean.z, 0.0);
  EXPECT_TRUE(std::isfinite(mean.x + mean.y + mean.z));
}

INSTANTIATE_TEST_SUITE_P(SharedScenes, SharedScene, ::testing::ValuesIn(sharedModels()),
                         [](const auto& info) { return test::paramName(fs::relative(info.param, VKMC_SHARED_SCENES).string()); });
// Without ../shared/scenes there are no rows; AtLeastSevenModelsArePresent says so.
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(SharedScene);
