// Grid search of the per-depth roulette scales on pilot data.
#include "estimators/efficiency_roulette.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "../shaders/shared/roulette.h"

namespace vkmc {

namespace {

// Roulette at depth d with survival(beta) over the pilot's paths: the relative second moment it adds (a survivor's
// F / s in place of F) and the rays it saves, both summed over paths.
struct DepthTerms {
  double addedVariance = 0.0, savedCost = 0.0;
};
template <class Survival>
DepthTerms depthTerms(const std::vector<PilotPath>& pilot, uint32_t d, double raysPerVertex, Survival survival) {
  DepthTerms t;
  for (const PilotPath& p : pilot) {
    if (p.beta[d] <= 0.0f || p.gathered[d] < 0.0f) continue;
    const double s = survival(p.beta[d]);
    if (s >= 1.0) continue;
    const double f = static_cast<double>(p.radiance) - p.gathered[d];
    t.addedVariance += p.weight * f * f * (1.0 / s - 1.0);
    t.savedCost += (1.0 - s) * raysPerVertex * (p.lastDepth - d);
  }
  return t;
}

// V x T per sample with the rule survival(d, beta) deciding at every roulette depth from firstDepth, each path's
// decisions in sequence: a survivor's throughput is divided by its survival, which the next decision sees, and the
// path's remaining estimate T_d after decision d adds T_d^2 (1/P_d - 1/P_{d-1}) to its second moment, P_d the
// probability of surviving decisions up to d. Its vertices cost what they did unrouletted, times their P.
template <class Survival>
double rouletteProduct(const std::vector<PilotPath>& pilot, double variance, double raysPerVertex, uint32_t firstDepth,
                       Survival survival) {
  const double n = static_cast<double>(std::max<size_t>(pilot.size(), 1));
  double added = 0.0, rays = 0.0;
  for (const PilotPath& p : pilot) {
    double reach = 1.0, vertices = 0.0;
    for (uint32_t d = 0; d <= p.lastDepth; ++d) {
      vertices += reach;
      if (d < firstDepth || d >= kRouletteTableDepths || p.beta[d] <= 0.0f || p.gathered[d] < 0.0f) continue;
      const double s = std::min(1.0, survival(d, static_cast<float>(p.beta[d] / reach)));
      if (!(s > 0.0) || s >= 1.0) continue;
      const double tail = static_cast<double>(p.radiance) - p.gathered[d];
      added += p.weight * tail * tail * (1.0 / (reach * s) - 1.0 / reach);
      reach *= s;
    }
    rays += 1.0 + raysPerVertex * vertices;
  }
  return (variance + added / n) * (rays / n);
}

}  // namespace

RouletteTable optimizeRouletteScales(const std::vector<PilotPath>& pilot, double sampleVariance, double raysPerVertex,
                                     uint32_t firstDepth) {
  RouletteTable table;
  table.scale.fill(std::numeric_limits<float>::infinity());
  table.predictedGain.fill(1.0);
  const double n = static_cast<double>(std::max<size_t>(pilot.size(), 1));
  double cost = 0.0;  // rays per sample without roulette: camera ray + rays per vertex
  for (const PilotPath& p : pilot) cost += 1.0 + raysPerVertex * (p.lastDepth + 1);
  cost /= n;
  const double variance = std::max(sampleVariance, 1e-30);
  for (uint32_t d = firstDepth; d < kRouletteTableDepths; ++d) {
    double bestProduct = variance * cost;
    float bestScale = std::numeric_limits<float>::infinity();
    for (int g = 0; g <= 40; ++g) {
      double k = std::pow(10.0, -2.0 + 0.1 * g);  // 0.01 .. 100
      const DepthTerms t = depthTerms(pilot, d, raysPerVertex, [k](float beta) { return std::min(1.0, k * beta); });
      double product = (variance + t.addedVariance / n) * std::max(cost - t.savedCost / n, 1e-9);
      if (product < bestProduct) {
        bestProduct = product;
        bestScale = static_cast<float>(k);
      }
    }
    table.scale[d] = bestScale;
    table.predictedGain[d] = variance * cost / bestProduct;
  }
  // Both rules as the kernels apply them (rouletteStep): the sqrt rule, and the table's scales under the survival cap.
  const double underThroughput = rouletteProduct(pilot, variance, raysPerVertex, firstDepth, [](uint32_t, float beta) {
    return double(gpu::rouletteStep(gpu::kRouletteThroughput, beta, 1.0f, 0.0f, 0.0f).survival);
  });
  const double underTable = rouletteProduct(pilot, variance, raysPerVertex, firstDepth, [&](uint32_t d, float beta) {
    return double(gpu::rouletteStep(gpu::kRouletteEfficiency, beta, table.scale[d], 0.0f, 0.0f).survival);
  });
  table.gainOverThroughput = underThroughput / underTable;
  return table;
}

}  // namespace vkmc
