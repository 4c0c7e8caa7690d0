// No include runs up the host's layering (host/CMakeLists.txt lists the folders in this order): a folder includes
// only from itself and the folders before it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

TEST(Layering, NoHostIncludeRunsUpTheLayers) {
  const std::vector<std::string> layers = {"vk", "scene", "bvh",      "estimators", "passes", "render",
                                           "io", "dist",  "analysis", "policy",     "bench",  "app"};
  auto rank = [&](const std::string& folder) { return std::find(layers.begin(), layers.end(), folder) - layers.begin(); };
  const std::regex include("#include \"([a-z_]+)/[^\"]+\"");
  size_t files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(std::string(VKMC_SOURCE_DIR) + "/host")) {
    std::string folder = entry.path().parent_path().filename().string();
    if (!entry.is_regular_file() || rank(folder) == long(layers.size())) continue;
    ++files;
    std::ifstream in(entry.path());
    for (std::string line; std::getline(in, line);) {
      std::smatch m;
      if (std::regex_search(line, m, include) && rank(m[1]) < long(layers.size())) {
        EXPECT_LE(rank(m[1]), rank(folder)) << entry.path().string() << " includes " << m[1] << "/";
      }
    }
  }
  EXPECT_GT(files, 40u);
}
