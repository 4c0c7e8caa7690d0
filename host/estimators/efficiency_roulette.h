// Efficiency-optimized Russian roulette (after Veach's thesis, sec. 10.4.1, and the ADRRS/EARS line of work):
// the survival probability at depth d is s = min(k_d * max(beta), cap), with one scale k_d per depth chosen
// to maximize the efficiency 1 / (V * T) measured on the scene itself.
//
// A pilot pass without roulette (up to 96 bounces: a shorter cap hides the cost of long paths, and the optimizer
// then keeps paths it should kill) records, for every path i and decision depth d, the throughput beta_{i,d} and
// the part of the sample's estimate gathered after the decision, A_{i,d} = L_i - L_{i,<=d}. Every depth's roulette
// is modelled at once, as the kernels apply it: a path reaches decision d with probability P_d (the product of
// the survivals before it), its throughput there divided by P_d, and survives with s_d = min(k_d beta_d / P_d, cap).
// Its estimate's second moment then exceeds L^2 by sum_d A_d^2 (1/P_{d+1} - 1/P_d), and it traces the rays of
// vertex d + 1 with probability P_{d+1}; so over the pilot's samples
//   V(k) = V + (1/N) sum_i sum_d A_{i,d}^2 (1/P_{i,d+1} - 1/P_{i,d}),   T(k) = (1/N) sum_i (rays of i, each vertex
//   weighted by the probability of reaching it),
// where V is the per-sample variance without roulette. Variances are relative (each path's terms over its
// pixel's mean^2 + epsilon), so the choice optimizes the relMSE efficiency that vkmc reports, rather than letting
// dark pixels take the roulette's noise. The scales minimize V(k) T(k) by coordinate descent (each depth over a
// log-spaced grid, "no roulette at this depth" included, the others as they stand; two sweeps) on at most 16384
// of the pilot's paths. An earlier version judged each depth alone against no roulette anywhere and a 24-bounce
// pilot; it chose mild roulette where aggressive paid (docs/cycles.md, "Would a milder survival close the gap?").
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "../shaders/shared/layout.h"

namespace vkmc {

using gpu::kRouletteTableDepths;  // depths with their own scale (layout.h: the kernels index the same table)

struct PilotPath {
  float radiance = 0.0f;   // luminance of the sample's final estimate L
  float weight = 1.0f;     // 1 / (pixel mean^2 + epsilon): relative error weight of the path's pixel
  uint32_t lastDepth = 0;  // depth of the path's last vertex
  uint32_t pixel = 0;
  std::array<float, kRouletteTableDepths> beta{};      // max component of throughput at the decision; < 0: none
  std::array<float, kRouletteTableDepths> gathered{};  // luminance gathered up to and including depth d; < 0: none
};

struct RouletteTable {
  std::array<float, kRouletteTableDepths> scale{};           // k_d; +inf: no roulette at that depth
  std::array<double, kRouletteTableDepths> predictedGain{};  // the table's predicted efficiency ratio once depths <= d are chosen
};

// sampleVariance: per-sample relative variance of the pixel estimates (image mean); raysPerVertex: rays one
// vertex costs after the decision (its continuation ray plus its light samples).
RouletteTable optimizeRouletteScales(const std::vector<PilotPath>& pilot, double sampleVariance, double raysPerVertex,
                                     uint32_t firstDepth);

}  // namespace vkmc
