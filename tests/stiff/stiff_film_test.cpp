// Stiff case 8: a long accumulation. 1e8 samples folded into one pixel through Film::addBatch (the path every
// render takes: float sums of at most 64 samples on the GPU, double on the host) keep the right mean, where a
// plain float running sum drifts. The samples are the scheme's worst honest case: 0 or 1 with probability 1/2.
#include <gtest/gtest.h>

#include "../shaders/shared/rng.h"
#include "render/film.h"
#include "support/stability_row.h"
#include "support/z_test.h"

using namespace vkmc;

TEST(StiffFilm, HundredMillionSamplesKeepTheMean) {
  const uint64_t total = 100000000, batch = 64;
  Film film(1, 1);
  float naive = 0.0f;
  uint64_t ones = 0;
  for (uint64_t b = 0; b < total / batch; ++b) {
    gpu::FilmPixel px{};
    uint32_t bits = gpu::hashU32(static_cast<uint32_t>(b) * 2u + 1u), bits2 = gpu::hashU32(static_cast<uint32_t>(b) * 2u + 2u);
    for (uint32_t s = 0; s < batch; ++s) {
      float v = ((s < 32 ? bits >> s : bits2 >> (s - 32)) & 1u) ? 1.0f : 0.0f;
      for (int c = 0; c < 3; ++c) px.sum[c] += v, px.sumSq[c] += v * v;
      px.sum[3] += 1.0f;
      naive += v;
      ones += v > 0.0f;
    }
    film.addBatch(&px);
  }
  ASSERT_EQ(film.count[0], total);
  double exact = double(ones) / total;  // the mean of the very samples drawn
  EXPECT_NEAR(film.mean(0, 0), exact, 1e-12);
  double sigma = std::sqrt(film.varianceOfMean(0, 0));
  EXPECT_NEAR(sigma, 0.5 / std::sqrt(double(total)), 1e-8);
  EXPECT_TRUE(test::withinSigmas(test::zTest(film.mean(0, 0), 0.5, sigma), 5.0));
  // The failure this scheme avoids: a float running sum stops growing at 2^24, so its mean falls far short.
  EXPECT_GT(std::abs(double(naive) / total - exact), 0.1);
  test::stabilityRow("8", "1e8 samples (0 or 1) into one pixel: film mean minus the samples' exact mean", "0",
                     film.mean(0, 0) - exact, sigma, std::abs(film.mean(0, 0) - exact) < 1e-12);
  test::stabilityRow("8", "the same with a plain float running sum (what the film avoids)", "0.5", double(naive) / total, sigma,
                     true);
}
