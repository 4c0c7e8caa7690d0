// The samplers of shaders/shared/sampler.h: stratification of each pixel's points in every 2D pair (before and
// after scrambling, Sobol and ZSobol), uniformity of scrambled dimensions (chi-square), never 1, the index
// shuffle's low-bit property, and the ZSobol digit permutations.
#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "../shaders/shared/sampler.h"
#include "support/chi2.h"

namespace vkmc::gpu {
namespace {

// 2^k points (as 32-bit fractions) fall one per elementary interval of every shape 2^a x 2^(k-a).
bool isNet(const std::vector<uvec2>& pts, uint32_t k) {
  for (uint32_t a = 0; a <= k; ++a) {
    std::set<uint64_t> cells;
    for (uvec2 p : pts) {
      uint64_t cx = a == 0 ? 0 : p.x >> (32 - a), cy = (k - a) == 0 ? 0 : p.y >> (32 - (k - a));
      cells.insert((cx << 32) | cy);
    }
    if (cells.size() != pts.size()) return false;
  }
  return true;
}

uint32_t bitsOf(float u) { return static_cast<uint32_t>(double(u) * 4294967296.0); }

TEST(SobolSequence, FirstTwoDimensionsAreAZeroTwoSequence) {
  for (uint32_t k = 0; k <= 10; ++k) {
    for (uint32_t block : {0u, 3u}) {
      std::vector<uvec2> pts;
      for (uint32_t i = block << k; i < (block + 1) << k; ++i) pts.push_back(uvec2(sobolBits(i, 0), sobolBits(i, 1)));
      EXPECT_TRUE(isNet(pts, k)) << "k " << k << " block " << block;
    }
  }
}

// Dimension 1 from its generator matrix, one generator per index bit (V_k = V_{k-1} ^ V_{k-1} >> 1): what
// sobolBits' loop-free form must equal for every index.
uint32_t sobolDimension1ByGenerators(uint32_t index) {
  uint32_t result = 0, v = 0x80000000u;
  for (uint32_t i = index; i != 0; i >>= 1, v ^= v >> 1)
    if (i & 1) result ^= v;
  return result;
}

TEST(SobolSequence, DimensionOneEqualsItsGeneratorMatrix) {
  for (uint32_t i = 0; i < 4096; ++i) ASSERT_EQ(sobolBits(i, 1), sobolDimension1ByGenerators(i)) << "index " << i;
  uint32_t x = 12345;
  for (int n = 0; n < 100000; ++n) {
    x = hashU32(x);
    ASSERT_EQ(sobolBits(x, 1), sobolDimension1ByGenerators(x)) << "index " << x;
  }
  for (uint32_t bit = 0; bit < 32; ++bit) EXPECT_EQ(sobolBits(1u << bit, 1), sobolDimension1ByGenerators(1u << bit));
  EXPECT_EQ(sobolBits(0xffffffffu, 1), sobolDimension1ByGenerators(0xffffffffu));
}

TEST(Samplers, APairIsItsTwoDimensions) {
  for (uint32_t sampler : {kSamplerIndependent, kSamplerSobol, kSamplerZSobol})
    for (uint32_t sample = 0; sample < 40; ++sample)
      for (uint32_t dim : {0u, 2u, 6u, 14u, lightDim(3u, 2u, 1u)}) {
        const SamplerShape shape{2u, 16u, 4u, 6u};
        SampleStream s{streamKey(sampler, 9u, 77u, sample, shape.replicates), sample, 77u};
        vec2 pair = samplePair(sampler, s, dim, shape);
        EXPECT_EQ(pair.x, sampleDimension(sampler, s, dim, shape)) << sampler << " " << dim;
        EXPECT_EQ(pair.y, sampleDimension(sampler, s, dim + 1u, shape)) << sampler << " " << dim;
      }
  // The kernels' 2D samples start at even dimensions (one pair each).
  for (uint32_t depth = 0; depth < 8; ++depth) {
    EXPECT_EQ(bounceDim(depth, kDimBsdf) % 2u, 0u);
    for (uint32_t j = 0; j < 5; ++j) EXPECT_EQ(lightDim(depth, j, 1u) % 2u, 0u);
  }
}

TEST(SobolSequence, OwenScramblingKeepsTheNet) {
  for (uint32_t seed : {1u, 77u, 0xdeadbeefu}) {
    std::vector<uvec2> pts;
    for (uint32_t i = 0; i < 256; ++i)
      pts.push_back(uvec2(owenScramble(sobolBits(i, 0), seed), owenScramble(sobolBits(i, 1), hashU32(seed))));
    EXPECT_TRUE(isNet(pts, 8)) << "seed " << seed;
  }
}

TEST(SobolSequence, ShuffleMapsTheFirstIndicesOntoAnAlignedBlock) {
  for (uint32_t seed : {3u, 12345u}) {
    for (uint32_t k : {1u, 4u, 9u}) {
      std::set<uint32_t> low, high;
      for (uint32_t i = 0; i < (1u << k); ++i) {
        low.insert(shuffleIndex(i, seed) & ((1u << k) - 1u));
        high.insert(shuffleIndex(i, seed) >> k);
      }
      EXPECT_EQ(low.size(), size_t(1) << k);
      EXPECT_EQ(high.size(), 1u);
    }
  }
}

// A pixel's first 2^k samples of one replicate, dimension pair `pair`, as 32-bit fractions.
std::vector<uvec2> pixelPoints(uint32_t sampler, uint32_t pixel, uint32_t replicate, uint32_t pair, uint32_t k,
                               SamplerShape shape) {
  std::vector<uvec2> pts;
  for (uint32_t i = 0; i < (1u << k); ++i) {
    uint32_t sampleIndex = i * shape.replicates + replicate;
    SampleStream s{streamKey(sampler, 9u, pixel, sampleIndex, shape.replicates), sampleIndex, pixel};
    pts.push_back(
        uvec2(bitsOf(sampleDimension(sampler, s, 2 * pair, shape)), bitsOf(sampleDimension(sampler, s, 2 * pair + 1, shape))));
  }
  return pts;
}

TEST(Samplers, EveryPairOfAPixelIsStratified) {
  const uint32_t width = 64, log2Spp = 6, digits = 6 + (log2Spp + 1) / 2;
  for (uint32_t replicates = 1; replicates <= kMaxSampleReplicates; ++replicates) {  // 1: one scrambling
    const SamplerShape shape{replicates, width, log2Spp, digits};
    for (uint32_t sampler : {kSamplerSobol, kSamplerZSobol}) {
      for (uint32_t pixel : {0u, 1u, 65u, 4000u}) {
        for (uint32_t replicate = 0; replicate < replicates; ++replicate) {
          for (uint32_t pair : {0u, 1u, bounceDim(0, kDimBsdf) / 2, bounceDim(2, kDimLightPoint) / 2, lightDim(1, 3, 1) / 2}) {
            for (uint32_t k : {2u, 4u, 6u}) {
              EXPECT_TRUE(isNet(pixelPoints(sampler, pixel, replicate, pair, k, shape), k))
                  << "sampler " << sampler << " replicates " << replicates << " pixel " << pixel << " replicate " << replicate
                  << " pair " << pair << " k " << k;
            }
          }
        }
      }
    }
  }
}

// Pairs keep their two dimensions together: the light point and the BSDF direction are each one pair.
TEST(Samplers, TwoDimensionalSamplesArePairs) {
  for (uint32_t depth : {0u, 5u}) {
    EXPECT_EQ(bounceDim(depth, kDimBsdf) % 2, 0u);
    EXPECT_EQ(bounceDim(depth, kDimLightPoint) % 2, 0u);
    EXPECT_EQ(lightDim(depth, 0, 1), bounceDim(depth, kDimLightPoint));
    EXPECT_EQ(lightDim(depth, 0, 2), bounceDim(depth, kDimLightPoint) + 1);
    for (uint32_t j : {1u, 7u}) {
      EXPECT_EQ(lightDim(depth, j, 1) % 2, 0u);
      EXPECT_EQ(lightDim(depth, j, 2), lightDim(depth, j, 1) + 1);
    }
  }
}

TEST(Samplers, NeverOne) {
  EXPECT_LT(bitsToUnit(0xffffffffu), 1.0f);
  EXPECT_EQ(bitsToUnit(0u), 0.0f);
}

// One dimension over many pixels (and samples) is uniform: chi-square over 64 bins, for each sampler.
TEST(Samplers, ScrambledDimensionsAreUniform) {
  const uint32_t width = 128, log2Spp = 2, digits = 7 + (log2Spp + 1) / 2;
  const SamplerShape shape{kMaxSampleReplicates, width, log2Spp, digits};
  for (uint32_t sampler : {kSamplerIndependent, kSamplerSobol, kSamplerZSobol}) {
    for (uint32_t dim : {0u, 3u, bounceDim(1, kDimRoulette), lightDim(0, 2, 0)}) {
      std::vector<double> bins(64, 0.0);
      uint32_t n = 0;
      for (uint32_t pixel = 0; pixel < width * 128; pixel += 3) {
        for (uint32_t sampleIndex = 0; sampleIndex < 4 * shape.replicates; sampleIndex += 5) {
          SampleStream s{streamKey(sampler, 21u, pixel, sampleIndex, shape.replicates), sampleIndex, pixel};
          float u = sampleDimension(sampler, s, dim, shape);
          ASSERT_TRUE(u >= 0.0f && u < 1.0f);
          bins[static_cast<size_t>(u * 64.0f)] += 1.0;
          ++n;
        }
      }
      double chi2 = 0.0, expected = double(n) / 64.0;
      for (double b : bins) chi2 += (b - expected) * (b - expected) / expected;
      double p = test::incompleteGammaQ(63.0 / 2.0, chi2 / 2.0);
      EXPECT_GT(p, 1e-4) << "sampler " << sampler << " dim " << dim << ": chi2 " << chi2 << " over 63 dof";
    }
  }
}

TEST(ZSobol, DigitPermutationsAreTheTwentyFour) {
  std::set<uint32_t> seen;
  for (uint32_t p = 0; p < 24; ++p) {
    std::set<uint32_t> image;
    uint32_t code = 0;
    for (uint32_t d = 0; d < 4; ++d) {
      image.insert(permutationDigit(p, d));
      code = code * 4 + permutationDigit(p, d);
    }
    EXPECT_EQ(image.size(), 4u) << "permutation " << p;
    seen.insert(code);
  }
  EXPECT_EQ(seen.size(), 24u);
}

// Neighbouring pixels get distinct parts of the sequence: no two pixels of a 16x16 tile share their first point.
TEST(ZSobol, PixelsGetDistinctPoints) {
  const SamplerShape shape{2u, 16u, 0u, 4u};
  std::set<uint32_t> first;
  for (uint32_t pixel = 0; pixel < 256; ++pixel) {
    SampleStream s{streamKey(kSamplerZSobol, 1u, pixel, 0u, shape.replicates), 0u, pixel};
    first.insert(bitsOf(sampleDimension(kSamplerZSobol, s, 0u, shape)) >> 24);
  }
  EXPECT_EQ(first.size(), 256u);  // the 256 pixels' first x values fall one per 1/256 interval
}

}  // namespace
}  // namespace vkmc::gpu
