// The glTF extension policy (a required extension vkmc does not implement is refused by name; each used one it
// ignores gets a warning naming it) and triangle strips and fans, which were dropped.
#include <gtest/gtest.h>

#include <fstream>

#include "error.h"
#include "scene/gltf_loader.h"
#include "support/test_scenes.h"

using namespace vkmc;
using vkmc::test::GltfSpec;

namespace {
std::filesystem::path dir() {
  static auto d = test::makeTempDir("extensions");
  return d;
}

// The quad with extensionsUsed / extensionsRequired lists added.
std::string quadUsing(const std::string& name, const std::string& used, const std::string& required) {
  std::string path = test::writeGltf(dir(), name, test::quadSpec());
  std::ifstream in(path);
  std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string lists = "\"extensionsUsed\":[" + used + "],";
  if (!required.empty()) lists += "\"extensionsRequired\":[" + required + "],";
  json.replace(json.find("\"scene\":0,"), 10, "\"scene\":0," + lists);
  std::ofstream(path) << json;
  return path;
}

bool hasWarning(const Scene& s, const std::string& text) {
  for (const std::string& w : s.warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}
}  // namespace

TEST(GltfExtensions, RequiredExtensionsVkmcDoesNotImplementAreRefusedByName) {
  std::string unknown = test::loadError(quadUsing("unknown", "\"VENDOR_magic\"", "\"VENDOR_magic\""));
  EXPECT_NE(unknown.find("requires extension VENDOR_magic, which vkmc does not know"), std::string::npos) << unknown;
  EXPECT_EQ(unknown.find('\n'), std::string::npos);
  std::string partial = test::loadError(
      quadUsing("diffuse_transmission", "\"KHR_materials_diffuse_transmission\"", "\"KHR_materials_diffuse_transmission\""));
  EXPECT_NE(partial.find("requires extension KHR_materials_diffuse_transmission, which vkmc does not implement in full"),
            std::string::npos)
      << partial;
  // A refusal does not read as if the file were rendered with the extension ignored.
  EXPECT_NE(partial.find("so it cannot render the file as required"), std::string::npos) << partial;
  EXPECT_FALSE(partial.ends_with("is ignored")) << partial;
  // Implemented in full: a file that requires them loads.
  for (const char* name :
       {"KHR_materials_emissive_strength", "KHR_draco_mesh_compression", "EXT_meshopt_compression", "KHR_mesh_quantization",
        "EXT_mesh_gpu_instancing", "KHR_materials_transmission", "KHR_materials_volume", "KHR_materials_ior",
        "KHR_materials_clearcoat", "KHR_materials_sheen", "KHR_materials_specular", "KHR_materials_iridescence",
        "KHR_materials_anisotropy", "KHR_materials_dispersion"}) {
    std::string quoted = "\"" + std::string(name) + "\"";
    EXPECT_EQ(test::loadError(quadUsing(name, quoted, quoted)), "") << name;
  }
}

TEST(GltfExtensions, UsedExtensionsThatAreIgnoredAreNamedInWarnings) {
  Scene s = loadGltf(
      quadUsing("used", "\"KHR_materials_diffuse_transmission\",\"KHR_materials_emissive_strength\",\"VENDOR_magic\"", ""));
  EXPECT_TRUE(hasWarning(s, "extension KHR_materials_diffuse_transmission: diffuse transmission is ignored"));
  EXPECT_TRUE(hasWarning(s, "extension VENDOR_magic is unknown to vkmc"));
  EXPECT_FALSE(hasWarning(s, "KHR_materials_emissive_strength"));  // implemented
  EXPECT_EQ(s.warnings.size(), 2u);
}

TEST(GltfExtensions, TriangleStripsAndFansBecomeTrianglesFacingTheSameWay) {
  GltfSpec strip;
  strip.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, 0};  // a zig-zag strip of 5 vertices
  strip.mode = 5;
  Scene s = loadGltf(test::writeGltf(dir(), "strip", strip));
  ASSERT_EQ(s.triangleCount(), 3u);
  for (size_t t = 0; t < 3; ++t) EXPECT_NEAR(s.normals[3 * t].z, 1.0f, 1e-6f) << "strip triangle " << t;
  EXPECT_EQ(s.positions[3], glm::vec3(1, 0, 0));  // triangle 1 is (v1, v3, v2): the odd one swaps to keep its winding
  EXPECT_EQ(s.positions[4], glm::vec3(1, 1, 0));
  GltfSpec fan;
  fan.positions = {0.5f, 0.5f, 0, 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};  // centre, then the corners counter-clockwise
  fan.indices = {0, 1, 2, 3, 4};
  fan.mode = 6;
  s = loadGltf(test::writeGltf(dir(), "fan", fan));
  ASSERT_EQ(s.triangleCount(), 3u);
  for (size_t t = 0; t < 3; ++t) {
    EXPECT_NEAR(s.normals[3 * t].z, 1.0f, 1e-6f) << "fan triangle " << t;
    EXPECT_EQ(s.positions[3 * t + 2], glm::vec3(0.5f, 0.5f, 0)) << "every fan triangle ends at the centre";
  }
}
