// EXR round trip of every channel; writes are atomic.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>

#include "error.h"
#include "io/exr.h"
#include "io/output_files.h"

using namespace vkmc;

TEST(Exr, FilmRoundTripsEveryChannel) {
  Film film(7, 5);
  for (size_t p = 0; p < film.pixels(); ++p) {
    film.count[p] = 10 + p;
    film.vertices[p] = 3.5 * double(film.count[p]);
    for (int c = 0; c < 3; ++c) {
      double v = 0.25 * p + c + 1e-3 * p * p;
      film.sum[3 * p + c] = v * film.count[p];
      film.sumSq[3 * p + c] = (v * v + 0.5 + c) * film.count[p];
    }
  }
  auto path = (std::filesystem::temp_directory_path() / "vkmc_exr_roundtrip.exr").string();
  writeFilmExr(path, film);
  ExrImage img = readExr(path);
  ASSERT_EQ(img.width, 7);
  ASSERT_EQ(img.height, 5);
  const char* names[] = {"R",       "G",    "B",         "variance.R", "variance.G", "variance.B", "variance.dof",
                         "samples", "cost", "efficiency"};
  for (const char* n : names) ASSERT_TRUE(img.channels.count(n)) << n;
  EXPECT_EQ(img.channels.size(), 10u);
  for (size_t p = 0; p < film.pixels(); ++p) {
    EXPECT_EQ(img.channels["samples"][p], float(film.count[p]));
    EXPECT_EQ(img.channels["variance.dof"][p], float(film.count[p] - 1));  // independent samples: n - 1
    EXPECT_EQ(img.channels["cost"][p], float(film.cost(p)));
    double rel = 0.0;
    for (int c = 0; c < 3; ++c) rel += film.varianceOfMean(p, c) / (film.mean(p, c) * film.mean(p, c) + 0.01) / 3.0;
    EXPECT_FLOAT_EQ(img.channels["efficiency"][p], float(1.0 / (rel * film.vertices[p])));
    const char* rgb[] = {"R", "G", "B"};
    const char* var[] = {"variance.R", "variance.G", "variance.B"};
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(img.channels[rgb[c]][p], float(film.mean(p, c)));
      EXPECT_EQ(img.channels[var[c]][p], float(film.varianceOfMean(p, c)));
      EXPECT_GT(img.channels[var[c]][p], 0.0f);
    }
  }
  std::filesystem::remove(path);
}

TEST(Exr, FailedWriteLeavesNothingBehind) {
  Film film(4, 4);
  auto dir = std::filesystem::temp_directory_path() / "vkmc_no_such_dir_for_exr";
  std::filesystem::remove_all(dir);
  EXPECT_THROW(writeFilmExr((dir / "x.exr").string(), film), Error);
  EXPECT_FALSE(std::filesystem::exists(dir));
}

TEST(Exr, ReadingGarbageIsAnError) {
  auto path = (std::filesystem::temp_directory_path() / "vkmc_garbage.exr").string();
  writeFileAtomically(path, "not an exr file");
  EXPECT_THROW(readExr(path), Error);
  std::filesystem::remove(path);
}

TEST(Exr, QmcFilmsGiveTheirReplicatesDegreesOfFreedom) {
  // Under sobol a pixel's variance comes from its replicate means: replicates with samples - 1 dof.
  Film film(2, 1);
  film.replicateVariance = true;
  film.count = {8, 2};
  for (uint32_t r = 0; r < gpu::kMaxSampleReplicates; ++r) film.replicateCount[r] = 2;  // pixel 0: all 4
  film.replicateCount[gpu::kMaxSampleReplicates + 0] = 1;                               // pixel 1: 2 of them
  film.replicateCount[gpu::kMaxSampleReplicates + 1] = 1;
  ExrImage img = filmToImage(film);
  EXPECT_EQ(img.channels["variance.dof"][0], float(gpu::kMaxSampleReplicates - 1));
  EXPECT_EQ(img.channels["variance.dof"][1], 1.0f);
}

// Attributes that declare more bytes than the file holds (an opaque type and a string by their declared size, a
// preview by its pixels) are refused by vkmc's header walk before OpenEXR allocates them (2 GiB and 16 GiB here,
// under a 1 GiB address-space cap).
TEST(Exr, AnAttributeLargerThanItsFileIsRefusedBeforeAllocation) {
  ExrImage image;
  image.width = 2, image.height = 1;
  for (const char* c : {"R", "G", "B"}) image.channels[c] = {0.25f, 0.5f};
  const std::string valid = encodeExr(image);
  ASSERT_NO_THROW(decodeExr(valid, "valid", 1 << 16));
  auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const struct {
    std::string attribute, expected;
  } rows[] = {
      {std::string("huge\0opaque\0", 12) + u32(0x7ffffff0) + "xy", "attribute 'huge' declares 2147483632 bytes"},
      {std::string("note\0string\0", 12) + u32(0x7ffffff0) + "xy", "attribute 'note' declares 2147483632 bytes"},
      {std::string("preview\0preview\0", 16) + u32(8) + u32(65535) + u32(65535), "attribute 'preview' declares 17179344908"},
      {std::string("preview\0preview\0", 16) + u32(8) + u32(0xffffffffu) + u32(0xffffffffu), "attribute 'preview' declares"},
      // A tile of 4096 x 4096 is under the limit alone, but not times the file's 3 channels.
      {std::string("tiles\0tiledesc\0", 15) + u32(9) + u32(4096) + u32(4096) + std::string(1, '\0'),
       "4096x4096 pixels of 3 channels"},
  };
  for (const auto& row : rows) {
    std::string bytes = valid;
    bytes.insert(8, row.attribute);
    pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      rlimit cap{uint64_t(1) << 30, uint64_t(1) << 30};
      setrlimit(RLIMIT_AS, &cap);
      try {
        decodeExr(bytes, "forged", 1 << 24);
      } catch (const Error& e) {
        _exit(std::string(e.what()).find(row.expected) != std::string::npos ? 0 : 1);
      }
      _exit(2);
    }
    int status = 0;
    waitpid(child, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << row.expected << ": status " << status;
  }
}

// A data window of more values than the reader allows is refused from the header, before OpenEXR allocates line
// buffers for it (it did, for a 16 KB input, before vkmc's own check after OpenEXR's header read).
TEST(Exr, ADataWindowPastTheLimitIsRefusedFromTheHeader) {
  ExrImage image;
  image.width = 300, image.height = 1;
  for (const char* c : {"R", "G", "B"}) image.channels[c].assign(300, 1.0f);
  const std::string bytes = encodeExr(image);
  ASSERT_NO_THROW(decodeExr(bytes, "valid", 900));
  try {
    decodeExr(bytes, "small limit", 899);
    FAIL() << "not refused";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("it declares 300x1 pixels of 3 channels, more than the 899 values"), std::string::npos)
        << e.what();
  }
}
