// Counter-based random numbers: u = hash(path key, dimension), and the dimension layout every sampler shares
// (sampler.h). Stateless, so every path vertex uses a fixed block of dimensions and runs are reproducible
// whatever the dispatch order. Dimensions pair up (2k, 2k + 1) into the 2D samples of sampler.h: the pairs
// below keep 2D integrands (pixel, BSDF direction, light point) inside one pair.
#ifndef VKMC_RNG_H
#define VKMC_RNG_H
#include "glsl_cpp.h"
VKMC_BEGIN_NAMESPACE

VKMC_CONST uint kDimsCamera = 4u;          // pixel jitter (pair 0), camera-ray roulette, spectral channel
VKMC_CONST uint kDimCameraRoulette = 2u;   // within the camera block
VKMC_CONST uint kDimSpectralChannel = 3u;  // the colour channel a path keeps past a dispersive volume
VKMC_CONST uint kDimsPerBounce = 10u;      // five pairs: bsdf, light point, (lobe, roulette), (light select,
                                           // shadow roulette), (split, light split)
VKMC_CONST uint kDimBsdf = 0u;             // and 1
VKMC_CONST uint kDimLightPoint = 2u;       // and 3
VKMC_CONST uint kDimBsdfLobe = 4u;
VKMC_CONST uint kDimRoulette = 5u;
VKMC_CONST uint kDimLightSelect = 6u;
VKMC_CONST uint kDimShadowRoulette = 7u;
VKMC_CONST uint kDimSplit = 8u;
VKMC_CONST uint kDimLightSplit = 9u;  // EARS: how many light samples a copy takes (floor(qL + u))
// Light sample j > 0 of a split bounce takes its three dimensions from a separate stream.
VKMC_CONST uint kDimsSplitBase = 0x40000000u;

// lowbias32 (Chris Wellons): a well-mixed 32-bit permutation.
VKMC_FN uint hashU32(uint x) {
  x ^= x >> 16u;
  x *= 0x21f0aaadu;
  x ^= x >> 15u;
  x *= 0x735a2d97u;
  x ^= x >> 15u;
  return x;
}

VKMC_FN uint pathKey(uint seed, uint pixel, uint sampleIndex) {
  return hashU32(pixel ^ hashU32(sampleIndex ^ hashU32(seed + 0x632be5abu)));
}

// Uniform in [0, 1): 24 random bits, so 1 is never returned.
VKMC_FN float randomUnit(uint key, uint dim) {
  return float(hashU32(key ^ hashU32(dim * 0x9e3779b9u + 0x7f4a7c15u)) >> 8u) * (1.0f / 16777216.0f);
}

// Key of split child c (c > 0) spawned at `depth`: an independent stream for the rest of its path.
VKMC_FN uint childKey(uint key, uint depth, uint c) {
  return c == 0u ? key : hashU32(key ^ hashU32(c * 0x9e3779b9u + depth * 0x85ebca6bu));
}

// Key of one ray's stochastic-alpha decisions (textures.glsl, surfacePresent): `stream` names the ray.
VKMC_FN uint alphaKey(uint key, uint stream) { return hashU32(key ^ hashU32(stream * 0x85ebca6bu + 0xc2b2ae35u)); }

VKMC_FN uint bounceDim(uint depth, uint offset) { return kDimsCamera + depth * kDimsPerBounce + offset; }

// Dimension `offset` (0: light select, 1-2: point, 3: shadow roulette) of light sample j at a bounce: sample 0
// uses the bounce's block, the others a disjoint stream, so splitting leaves sample 0 unchanged.
VKMC_FN uint lightDim(uint depth, uint sampleIndex, uint offset) {
  if (sampleIndex == 0u)
    return bounceDim(depth, offset == 0u ? kDimLightSelect : offset == 3u ? kDimShadowRoulette : kDimLightPoint + offset - 1u);
  return kDimsSplitBase + (depth * 4096u + sampleIndex) * 4u + (offset == 0u ? 2u : offset == 3u ? 3u : offset - 1u);
}

VKMC_END_NAMESPACE
#endif
