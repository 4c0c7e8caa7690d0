// Where a path's uniform numbers come from (`--sampler`): independent hashes, or Owen-scrambled Sobol points in
// padded 2D blocks (Burley 2020, "Practical Hash-based Owen Scrambling"), decorrelated per pixel by hashing, or
// indexed along a Morton curve over the image (ZSobol: Ahmed & Wonka 2020, as pbrt-v4's ZSobolSampler).
//
// Dimensions are numbered by rng.h and taken in pairs: pair d/2 is one 2D sample, the first two dimensions of a
// Sobol sequence (a (0,2)-sequence: any 2^k consecutive aligned points fall one per elementary interval),
// its sample order shuffled and its values Owen-scrambled with seeds of its own, so pairs are independent of
// each other and each stays stratified (padding). A 1D sample is one half of a pair.
//
// Honest variance: a pixel's samples are split into R independent replicates (`replicates`, 1 to
// kMaxSampleReplicates; sample index i belongs to replicate i % R and is point i / R of that replicate's own
// scrambling), so the spread of the R replicate means is an unbiased estimate of the variance of the pixel mean
// (host/render/film.cpp). Fewer replicates keep more of the sequence's stratification (QMC error falls faster
// than 1/n inside one); more give the per-pixel variance more degrees of freedom (R - 1). R = 1 is one
// scrambling, as Cycles and pbrt-v4 sample: the least error, and no variance estimate (Film::estimatesVariance).
#ifndef VKMC_SAMPLER_H
#define VKMC_SAMPLER_H
#include "glsl_cpp.h"
#include "layout.h"
#include "rng.h"
VKMC_BEGIN_NAMESPACE

VKMC_CONST uint kSamplerIndependent = 0u, kSamplerSobol = 1u, kSamplerZSobol = 2u;
VKMC_CONST float kOneMinusEpsilon = 0.99999994f;  // the largest float below 1 (pbrt-v4#313: never return 1)

VKMC_FN uint reverseBits32(uint v) {
#ifdef __cplusplus
  v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
  v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
  v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
  v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
  return (v >> 16) | (v << 16);
#else
  return bitfieldReverse(v);
#endif
}

// Laine-Karras style hash (pbrt-v4's FastOwenScrambler constants): a bijection of 32-bit words in which bit k of
// the result depends on bits 0..k of the input only.
VKMC_FN uint laineKarras(uint v, uint seed) {
  v ^= v * 0x3d20adeau;
  v += seed;
  v *= (seed >> 16u) | 1u;
  v ^= v * 0x05526c56u;
  v ^= v * 0x53a22864u;
  return v;
}

// Owen scrambling of a 32-bit fraction (most significant bit first): each bit is flipped by a hash of the bits
// above it.
VKMC_FN uint owenScramble(uint v, uint seed) { return reverseBits32(laineKarras(reverseBits32(v), seed)); }

// The sample order within a replicate, shuffled (Burley's nested uniform scramble of the index): bit k of the
// index is flipped by a hash of the bits above it, so the first 2^k indices map onto one aligned block of 2^k
// indices (common high bits), whose Sobol points are a digitally shifted (0,k,2)-net.
VKMC_FN uint shuffleIndex(uint index, uint seed) { return owenScramble(index, seed); }

// Dimension 0 of the Sobol sequence (van der Corput) and dimension 1, as 32-bit fractions. Dimension 1's
// generators are the Pascal matrix mod 2: bit r of the fraction (r = 0 the most significant) is the XOR of the
// index bits k with binom(k, r) odd, i.e. (Lucas) with k a bitwise superset of r. That superset sum over the 5-bit
// positions is five shift-and-XOR steps, where the generator loop took one step per index bit
// (tests/unit/sampler_test.cpp checks the two agree).
VKMC_FN uint sobolBits(uint index, uint dimension) {
  if (dimension == 0u) return reverseBits32(index);
  uint x = index;  // bit k: index bit k; after the steps, bit r: output bit r
  x ^= (x >> 1u) & 0x55555555u;
  x ^= (x >> 2u) & 0x33333333u;
  x ^= (x >> 4u) & 0x0f0f0f0fu;
  x ^= (x >> 8u) & 0x00ff00ffu;
  x ^= (x >> 16u) & 0x0000ffffu;
  return reverseBits32(x);
}

VKMC_FN float bitsToUnit(uint bits) { return min(float(bits >> 8u) * (1.0f / 16777216.0f), kOneMinusEpsilon); }

// Morton code of a pixel (16 bits per axis).
VKMC_FN uint spreadBits16(uint x) {
  x &= 0xffffu;
  x = (x | (x << 8u)) & 0x00ff00ffu;
  x = (x | (x << 4u)) & 0x0f0f0f0fu;
  x = (x | (x << 2u)) & 0x33333333u;
  x = (x | (x << 1u)) & 0x55555555u;
  return x;
}
VKMC_FN uint mortonCode(uint x, uint y) { return spreadBits16(x) | (spreadBits16(y) << 1u); }

// ZSobol: the Sobol index of a pair for one pixel's point `index` (< 2^log2Spp). The Morton index of (pixel,
// sample) has its base-4 digits permuted, each by one of the 24 permutations of {0,1,2,3} chosen by a hash of
// the digits above it and of the pair, so neighbouring pixels get well-spread (blue-noise) parts of one
// sequence. `digits`: base-4 digits of the Morton index (pixel bits + log2Spp, rounded up to even).
VKMC_FN uint permutationDigit(uint p, uint digit) {
  // The 24 permutations of {0,1,2,3} in lexicographic order, one byte each (two bits per image), four a word.
  uint word = p < 12u ? (p < 4u   ? 0x78d8b4e4u
                         : p < 8u ? 0xb1e16c9cu
                                  : 0x2d8d39c9u)
                      : (p < 16u   ? 0x36c672d2u
                         : p < 20u ? 0x63931e4eu
                                   : 0x1b4b2787u);
  return (word >> (8u * (p % 4u) + 2u * digit)) & 3u;
}

VKMC_FN uint zsobolIndex(uint mortonIndex, uint pair, uint seed, uint digits, bool oddLog2) {
  uint result = 0u;
  uint pairHash = hashU32(pair * 0x55555555u + seed);
  int lastDigit = oddLog2 ? 1 : 0;
  for (int i = int(digits) - 1; i >= lastDigit; --i) {
    uint shift = uint(2 * i - (oddLog2 ? 1 : 0));
    uint digit = (mortonIndex >> shift) & 3u;
    uint higher = shift + 2u >= 32u ? 0u : mortonIndex >> (shift + 2u);
    uint p = (hashU32(higher ^ pairHash) >> 24u) % 24u;
    result |= permutationDigit(p, digit) << shift;
  }
  if (oddLog2) {
    uint digit = mortonIndex & 1u;
    result |= digit ^ (hashU32((mortonIndex >> 1u) ^ pairHash) & 1u);
  }
  return result;
}

// Where a path's numbers come from: `key` is the stream's key (rng.h pathKey for the independent sampler; a
// replicate's, or a split child's, scrambling key otherwise), `sampleIndex` the pixel's sample number.
struct SampleStream {
  uint key;
  uint sampleIndex;
  uint pixel;
};

// The stream key of a camera path: per sample for the independent sampler; per pixel and replicate for Sobol;
// per replicate (the same for every pixel: the Morton index separates pixels) for ZSobol.
VKMC_FN uint streamKey(uint samplerKind, uint seed, uint pixel, uint sampleIndex, uint replicates) {
  if (samplerKind == kSamplerIndependent) return pathKey(seed, pixel, sampleIndex);
  uint replicate = sampleIndex % replicates;
  if (samplerKind == kSamplerSobol) return hashU32(pathKey(seed, pixel, 0u) ^ hashU32(replicate + 0x2545f491u));
  return hashU32(hashU32(seed + 0x632be5abu) ^ hashU32(replicate + 0x2545f491u));
}

// How a sampler's points are laid out: `replicates` per pixel (R above); for ZSobol `width` (the image's),
// `log2Spp` (a replicate's point numbers are < 2^log2Spp) and `digits` (the Morton index's length in base-4
// digits: pixel bits + log2Spp, rounded up).
struct SamplerShape {
  uint replicates;
  uint width;
  uint log2Spp;
  uint digits;
};

// A per-sample hash key of the stream (stochastic alpha and other decisions that need no stratification).
VKMC_FN uint streamHash(SampleStream s) { return hashU32(s.key ^ hashU32(s.sampleIndex * 0x9e3779b9u + 0x7f4a7c15u)); }

// The Sobol index of a pair's point for stream s (before the dimension's own scrambling).
VKMC_FN uint pairIndex(uint samplerKind, SampleStream s, uint pair, uint pairSeed, SamplerShape shape) {
  uint point = s.sampleIndex / shape.replicates;
  if (samplerKind == kSamplerSobol) return shuffleIndex(point, pairSeed);
  uint morton = (mortonCode(s.pixel % shape.width, s.pixel / shape.width) << shape.log2Spp) | point;
  return zsobolIndex(morton, pair, s.key, shape.digits, (shape.log2Spp & 1u) != 0u);
}
VKMC_FN uint pairSeedOf(SampleStream s, uint pair) { return hashU32(s.key ^ hashU32(pair * 0x68bc21ebu + 0x02e5be93u)); }
VKMC_FN float scrambledComponent(uint index, uint component, uint pairSeed) {
  return bitsToUnit(owenScramble(sobolBits(index, component), hashU32(pairSeed ^ (component + 0x1b873593u))));
}

// Uniform in [0, 1) for dimension `dim`.
VKMC_FN float sampleDimension(uint samplerKind, SampleStream s, uint dim, SamplerShape shape) {
  if (samplerKind == kSamplerIndependent) return randomUnit(s.key, dim);
  uint pair = dim >> 1u;
  uint pairSeed = pairSeedOf(s, pair);
  return scrambledComponent(pairIndex(samplerKind, s, pair, pairSeed, shape), dim & 1u, pairSeed);
}

// Dimensions dim and dim + 1 (dim even: one pair), the same values as two sampleDimension calls, with the pair's
// seed and index computed once.
VKMC_FN vec2 samplePair(uint samplerKind, SampleStream s, uint dim, SamplerShape shape) {
  if (samplerKind == kSamplerIndependent) return vec2(randomUnit(s.key, dim), randomUnit(s.key, dim + 1u));
  uint pair = dim >> 1u;
  uint pairSeed = pairSeedOf(s, pair);
  uint index = pairIndex(samplerKind, s, pair, pairSeed, shape);
  return vec2(scrambledComponent(index, 0u, pairSeed), scrambledComponent(index, 1u, pairSeed));
}

VKMC_END_NAMESPACE
#endif
