// Efficiency-optimized Russian roulette (after Veach's thesis, sec. 10.4.1, and the ADRRS/EARS line of work):
// the survival probability at depth d is s = min(k_d * max(beta), cap), with one scale k_d per depth chosen
// to maximize the efficiency 1 / (V * T) measured on the scene itself.
//
// A pilot pass without roulette records, for every path i and depth d, the throughput beta_{i,d} at the
// roulette decision, the part of the sample's estimate gathered after it, F_{i,d} = L_i - L_{i,<=d}, and the
// rays traced after it, C_{i,d}. Rouletting with survival s_i adds F^2 (1/s - 1) to the second moment (the
// unbiased estimator F/s with probability s, else 0) and saves (1 - s) C in cost, so over N pilot samples
//   V_d(k) = V + (1/N) sum_i F_{i,d}^2 (1/s_i(k) - 1),   T_d(k) = T - (1/N) sum_i (1 - s_i(k)) C_{i,d},
// where V is the per-sample variance and T the per-sample cost without roulette. Variances are relative
// (each path's F^2 over its pixel's mean^2 + epsilon), so the choice optimizes the relMSE efficiency that
// vkmc reports, rather than letting dark pixels take the roulette's noise. k_d maximizes
// 1 / (V_d(k) T_d(k)) over a log-spaced grid; "no roulette at this depth" (k = infinity) is a candidate, so the
// choice never makes the pilot's efficiency worse. Depths are optimized one at a time (a greedy
// approximation: roulette at one depth changes what later depths see).
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
  std::array<double, kRouletteTableDepths> predictedGain{};  // efficiency ratio predicted at each depth
  // The whole table's efficiency predicted against the default throughput rule (roulette.h's sqrt rule) on the same
  // pilot paths: V x T under that rule over V x T under the table, each path's decisions taken in sequence as the
  // kernels take them (efficiency_roulette.cpp, rouletteProduct). 1 where paths rarely reach the roulette depth or
  // the table learns the rule back: --estimator auto then spends no pilot pass on it. Not modelled: the kernels'
  // 1/eta^2 scale of the throughput inside glass (the pilot records beta without it) and decisions past the
  // table's last depth.
  double gainOverThroughput = 1.0;
};

// sampleVariance: per-sample relative variance of the pixel estimates (image mean); raysPerVertex: rays one
// vertex costs after the decision (its continuation ray plus its light samples).
RouletteTable optimizeRouletteScales(const std::vector<PilotPath>& pilot, double sampleVariance, double raysPerVertex,
                                     uint32_t firstDepth);

}  // namespace vkmc
