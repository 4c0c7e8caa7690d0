// Environment maps from files (host/io/environment_image.cpp): .exr and .hdr read alike, bad pixels refused.
#include <gtest/gtest.h>

#include <algorithm>
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

namespace {
// A Radiance file of width x height texels in the run-length encoding (each channel one run a row) or flat.
std::string radianceFile(uint32_t width, uint32_t height, bool rle) {
  std::string s = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(height) + " +X " + std::to_string(width) + "\n";
  for (uint32_t y = 0; y < height; ++y) {
    if (!rle) {
      for (uint32_t x = 0; x < width; ++x) s += {char(128), char(64), char(32), char(129)};
      continue;
    }
    s += {char(2), char(2), char(width >> 8), char(width & 0xff)};
    for (char value : {char(128), char(64), char(32), char(129)})
      for (uint32_t x = 0; x < width; x += 127) s += {char(128 + std::min(127u, width - x)), value};
  }
  return s;
}
}  // namespace

// The run-length encoding decodes as the flat file does; every cut of either, and a run that overruns its row, is
// refused with one line (stb_image 2.27 looped forever on some cuts and decoded others to black).
TEST(EnvironmentImage, TruncatedOrCorruptRadianceFilesAreRefusedNotLoopedOnOrBlackened) {
  const std::string rle = radianceFile(300, 3, true), flat = radianceFile(300, 3, false);
  std::ofstream(dir() / "rle.hdr", std::ios::binary) << rle;
  std::ofstream(dir() / "flat.hdr", std::ios::binary) << flat;
  EnvironmentMap a = readEnvironmentMap((dir() / "rle.hdr").string()), b = readEnvironmentMap((dir() / "flat.hdr").string());
  ASSERT_EQ(a.width, 300u);
  EXPECT_EQ(a.radiance, b.radiance);
  EXPECT_NEAR(a.radiance[899].y, 0.5f, 1e-6f);
  for (const std::string* file : {&rle, &flat})
    for (size_t cut : {size_t(20), size_t(40), file->size() / 2, file->size() - 1}) {
      std::ofstream(dir() / "cut.hdr", std::ios::binary | std::ios::trunc) << file->substr(0, cut);
      std::string e = errorOf([] { readEnvironmentMap((dir() / "cut.hdr").string()); });
      EXPECT_NE(e.find("cannot read"), std::string::npos) << cut << ": " << e;
      EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    }
  std::string overrun = rle;
  overrun[overrun.find("\n-Y") + 21] = char(128 + 127);  // the first row's third run (of 46) now overruns it
  std::ofstream(dir() / "overrun.hdr", std::ios::binary) << overrun;
  EXPECT_NE(errorOf([] { readEnvironmentMap((dir() / "overrun.hdr").string()); }).find("overruns its scanline"),
            std::string::npos);
}

// A 69-byte file that declares 12000 x 12000 texels is refused from its header, before its pixels are allocated.
TEST(EnvironmentImage, AMapLargerThanTheDeviceHoldsIsRefusedBeforeAllocation) {
  std::ofstream(dir() / "huge.hdr", std::ios::binary) << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 12000 +X 12000\n"
                                                      << std::string(8, 'x');
  std::string e = errorOf([] { readEnvironmentMap((dir() / "huge.hdr").string(), 0.0f, 1.0f, 1u << 20); });
  EXPECT_NE(e.find("more than the 1048576 texels"), std::string::npos) << e;
  const std::string exr = writeMap("wide.exr", 1.0f);  // 2 x 1 texels, 3 channels: 6 values
  e = errorOf([&] { readEnvironmentMap(exr, 0.0f, 1.0f, 1); });
  EXPECT_NE(e.find("more than the 3 values"), std::string::npos) << e;
  EXPECT_NE(errorOf([&] { readExr(exr, 5); }).find("declares 2x1 pixels of 3 channels"), std::string::npos);
  EXPECT_EQ(readExr(exr, 6).width, 2);
}
