// Every model in ../shared/scenes loads and renders a few samples with no non-finite sample.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/render_job.h"

using namespace vkmc;
namespace fs = std::filesystem;

TEST(SharedScenes, EveryModelLoadsAndRendersFinite) {
  fs::path root = VKMC_SHARED_SCENES;
  if (!fs::is_directory(root)) GTEST_SKIP() << "no shared scenes at " << root;
  vk::Context ctx;
  int rendered = 0;
  for (const auto& dir : fs::directory_iterator(root)) {
    if (!dir.is_directory()) continue;
    for (const auto& file : fs::directory_iterator(dir.path())) {
      std::string ext = file.path().extension().string();
      if (ext != ".gltf" && ext != ".glb") continue;
      SCOPED_TRACE(file.path().string());
      RenderOptions o;
      o.scenePath = file.path().string();
      o.width = 48;
      o.height = 48;
      o.spp = 2;
      o.progress = false;
      o.background = glm::vec3(1.0f);  // scenes without emitters are lit by the background
      RenderOutcome r = runRender(ctx, o);
      EXPECT_EQ(r.film.totalNonfinite(), 0u);
      EXPECT_EQ(r.film.totalSamples(), 48u * 48u * 2u);
      glm::dvec3 mean = r.film.imageMean();
      EXPECT_GT(mean.x + mean.y + mean.z, 0.0);
      EXPECT_TRUE(std::isfinite(mean.x + mean.y + mean.z));
      ++rendered;
    }
  }
  EXPECT_GE(rendered, 7);
}
