// Environment maps from files (host/io/environment_image.cpp): .exr and .hdr read alike, bad pixels refused.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <limits>

#include "error.h"
#include "io/environment_image.h"
#include "io/exr.h"
#include "support/test_scenes.h"

using namespace vkmc;

namespace {
const std::filesystem::path& dir() {
  static const std::filesystem::path d = test::makeTempDir("environment_image");
  return d;
}

std::string writeMap(const std::string& name, float pixel) {
  ExrImage image;
  image.width = 2, image.height = 1;
  image.channels["R"] = {1.0f, pixel};
  image.channels["G"] = {2.0f, 0.0f};
  image.channels["B"] = {3.0f, 0.0f};
  std::string path = (dir() / name).string();
  writeExr(path, image);
  return path;
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(EnvironmentImage, ReadsAnExrTimesItsStrength) {
  EnvironmentMap m = readEnvironmentMap(writeMap("good.exr", 4.0f), 30.0f, 2.0f);
  ASSERT_EQ(m.width, 2u);
  ASSERT_EQ(m.height, 1u);
  EXPECT_EQ(m.radiance[0], glm::vec3(2.0f, 4.0f, 6.0f));
  EXPECT_EQ(m.radiance[1], glm::vec3(8.0f, 0.0f, 0.0f));
  EXPECT_EQ(m.rotationDegrees, 30.0f);
}

TEST(EnvironmentImage, ReadsARadianceHdr) {
  // A 1 x 1 RGBE file: (128, 64, 32, 129) is (1, 0.5, 0.25) x 2^(129 - 136) x 2^8 = (1, 0.5, 0.25).
  std::string path = (dir() / "one.hdr").string();
  std::ofstream(path, std::ios::binary) << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n"
                                        << char(128) << char(64) << char(32) << char(129);
  EnvironmentMap m = readEnvironmentMap(path);
  ASSERT_EQ(m.width * m.height, 1u);
  EXPECT_NEAR(m.radiance[0].x, 1.0f, 1e-6f);
  EXPECT_NEAR(m.radiance[0].y, 0.5f, 1e-6f);
  EXPECT_NEAR(m.radiance[0].z, 0.25f, 1e-6f);
}

TEST(EnvironmentImage, RefusesBadPixelsAndFilesWithOneLine) {
  for (float bad : {-1.0f, std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN()}) {
    std::string e = errorOf([&] { readEnvironmentMap(writeMap("bad.exr", bad)); });
    EXPECT_NE(e.find("negative or not finite"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
  EXPECT_NE(errorOf([] { readEnvironmentMap(writeMap("huge.exr", 3e38f), 0.0f, 10.0f); }).find("not finite"), std::string::npos);
  EXPECT_NE(errorOf([] { readEnvironmentMap("/nonexistent/sky.hdr"); }).find("cannot open"), std::string::npos);
  std::string png = (dir() / "sky.png").string();
  std::ofstream(png) << "not an image";
  EXPECT_NE(errorOf([&] { readEnvironmentMap(png); }).find("neither .hdr nor .exr"), std::string::npos);
  std::string broken = (dir() / "broken.hdr").string();
  std::ofstream(broken) << "not an image";
  EXPECT_NE(errorOf([&] { readEnvironmentMap(broken); }).find("cannot read"), std::string::npos);
}
