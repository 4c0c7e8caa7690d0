// EXR round trip of every channel; writes are atomic.
#include <gtest/gtest.h>

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
