// Grid search of the per-depth roulette scales on pilot data.
#include "estimators/efficiency_roulette.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vkmc {

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
      double addedVariance = 0.0, savedCost = 0.0;
      for (const PilotPath& p : pilot) {
        if (p.beta[d] <= 0.0f || p.gathered[d] < 0.0f) continue;
        double s = std::min(1.0, k * p.beta[d]);
        if (s >= 1.0) continue;
        double f = static_cast<double>(p.radiance) - p.gathered[d];
        addedVariance += p.weight * f * f * (1.0 / s - 1.0);
        savedCost += (1.0 - s) * raysPerVertex * (p.lastDepth - d);
      }
      double product = (variance + addedVariance / n) * std::max(cost - savedCost / n, 1e-9);
      if (product < bestProduct) {
        bestProduct = product;
        bestScale = static_cast<float>(k);
      }
    }
    table.scale[d] = bestScale;
    table.predictedGain[d] = variance * cost / bestProduct;
  }
  return table;
}

}  // namespace vkmc
