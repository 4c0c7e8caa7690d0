// Coordinate search of the per-depth roulette scales on pilot data, with every depth's roulette in the model at
// once (efficiency_roulette.h).
#include "estimators/efficiency_roulette.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "../shaders/shared/roulette.h"

namespace vkmc {
namespace {

constexpr float kNoRoulette = std::numeric_limits<float>::infinity();
constexpr size_t kEvaluatedPaths = 16384;

struct Outcome {
  double addedVariance = 0.0, cost = 0.0;
};

Outcome evaluate(const std::vector<PilotPath>& pilot, const std::array<float, kRouletteTableDepths>& scale,
                 double raysPerVertex, uint32_t firstDepth) {
  Outcome out;
  for (const PilotPath& p : pilot) {
    double reach = 1.0;  // P_d
    double rays = 1.0 + raysPerVertex * std::min<double>(p.lastDepth + 1, firstDepth + 1);
    uint32_t d = firstDepth;
    for (; d < p.lastDepth; ++d) {
      // Past the table the kernels reuse its last scale; the pilot records no throughput there, so the last one
      // stands in (the survival then climbs to the cap: the model's cost of very long paths is an upper bound).
      uint32_t t = std::min<uint32_t>(d, kRouletteTableDepths - 1);
      float beta = d < kRouletteTableDepths ? p.beta[d] : p.beta[t];
      if (d < kRouletteTableDepths && (beta <= 0.0f || p.gathered[d] < 0.0f)) break;
      // As the kernels compute it: "no roulette" (an infinite scale) survives with the cap.
      double s = std::min<double>(double(scale[t]) * beta / reach, gpu::kRouletteMaxSurvival);
      if (d < kRouletteTableDepths) {
        double after = static_cast<double>(p.radiance) - p.gathered[d];
        out.addedVariance += p.weight * after * after * (1.0 / (reach * s) - 1.0 / reach);
      }
      reach *= s;
      rays += reach * raysPerVertex;  // vertex d + 1
    }
    out.cost += rays;
  }
  const double n = static_cast<double>(std::max<size_t>(pilot.size(), 1));
  out.addedVariance /= n;
  out.cost /= n;
  return out;
}

}  // namespace

RouletteTable optimizeRouletteScales(const std::vector<PilotPath>& allPaths, double sampleVariance, double raysPerVertex,
                                     uint32_t firstDepth) {
  // Every kEvaluatedPaths-th share of the pilot: each candidate table walks every path's decisions.
  std::vector<PilotPath> pilot;
  const size_t stride = std::max<size_t>(1, (allPaths.size() + kEvaluatedPaths - 1) / kEvaluatedPaths);
  for (size_t i = 0; i < allPaths.size(); i += stride) pilot.push_back(allPaths[i]);
  RouletteTable table;
  table.scale.fill(kNoRoulette);
  table.predictedGain.fill(1.0);
  const double variance = std::max(sampleVariance, 1e-30);
  const Outcome none = evaluate(pilot, table.scale, raysPerVertex, firstDepth);
  const double baseline = variance * none.cost;
  auto product = [&](const Outcome& o) { return (variance + o.addedVariance) * std::max(o.cost, 1e-9); };
  for (int sweep = 0; sweep < 2; ++sweep) {
    for (uint32_t d = firstDepth; d < kRouletteTableDepths; ++d) {
      float best = table.scale[d];
      double bestProduct = product(evaluate(pilot, table.scale, raysPerVertex, firstDepth));
      for (int g = -1; g <= 20; ++g) {
        table.scale[d] = g < 0 ? kNoRoulette : static_cast<float>(std::pow(10.0, -2.0 + 0.2 * g));  // 0.01 .. 100
        double p = product(evaluate(pilot, table.scale, raysPerVertex, firstDepth));
        if (p < bestProduct) {
          bestProduct = p;
          best = table.scale[d];
        }
      }
      table.scale[d] = best;
      table.predictedGain[d] = baseline / bestProduct;
    }
  }
  return table;
}

}  // namespace vkmc
