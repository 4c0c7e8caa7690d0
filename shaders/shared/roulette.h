// Russian roulette and splitting as pure functions, shared by the path kernels (shading.glsl, camera.glsl), the
// analytic furnace probe and the host's tests. A survivor's value is divided by its survival probability, so
// every rule here is unbiased.
#ifndef VKMC_ROULETTE_H
#define VKMC_ROULETTE_H
#include "glsl_cpp.h"
VKMC_BEGIN_NAMESPACE

// Throughput roulette survives with min(max(beta), kRouletteMaxSurvival). The cap below 1 ends every path with
// probability 1 (no hidden depth cap), but while beta >= cap each survival multiplies beta by a / cap for a
// surface of albedo a, so the second moment grows like (a^2 / cap)^n: a cap of 0.95 (Mitsuba's) gives infinite
// variance above albedo 0.975. 0.999 keeps the variance finite up to albedo 0.9995 and still ends paths.
VKMC_CONST float kRouletteMaxSurvival = 0.999f;

// Roulette modes (SPEC_RR_MODE): none, fixed q, throughput (the sqrt rule below), efficiency (scaled max beta),
// ears (roulette and splitting by a learned cache, ears.h).
VKMC_CONST uint kRouletteNone = 0u, kRouletteFixed = 1u, kRouletteThroughput = 2u, kRouletteEfficiency = 3u, kRouletteEars = 4u;

// One roulette decision: whether the path survives, and the probability a survivor's throughput is divided by.
struct RouletteStep {
  bool survives;
  float survival;
};

// Fixed roulette with termination probability q. With a constant c it is the lecture's
// F' = (F - q c) / (1 - q) with probability 1 - q, else c (unbiased for any c): a terminated path gathers
// c * throughput, a survivor gives up fixedRouletteCompensation(q) * c * throughput. Shadow and camera rays use c = 0.
VKMC_FN RouletteStep fixedRoulette(float q, float r) {
  RouletteStep s;
  s.survives = !(r < q);
  s.survival = 1.0f - q;
  return s;
}
VKMC_FN float fixedRouletteCompensation(float q) { return q / (1.0f - q); }

// Throughput roulette (scale 1) or the efficiency-optimized one (scale k_d, host/estimators/efficiency_roulette.h):
// survival min(scale * max(unsplit beta), cap), through splitCount so that a factor above 1 would split.
VKMC_FN float rouletteSurvival(float unsplitThroughput, float scale, float cap) { return min(scale * unsplitThroughput, cap); }

// Splitting and Russian roulette as one mechanism (as in EARS): a factor q yields floor(q + u) children,
// each weighted 1 / q, so the expected total weight is one. q < 1 is roulette, q > 1 splitting. Written without
// the sum q + u, which float rounding lifts to the next integer (2 + (1 - 2^-24) rounds to 3): never more than
// ceil(q) children, which is what the kernels reserve pool slots for.
VKMC_FN uint splitCount(float q, float u) {
  float whole = floor(q);
  return uint(whole) + (u >= 1.0f - (q - whole) ? 1u : 0u);
}

VKMC_FN RouletteStep throughputRoulette(float unsplitThroughput, float scale, float r) {
  RouletteStep s;
  s.survival = rouletteSurvival(unsplitThroughput, scale, kRouletteMaxSurvival);
  s.survives = splitCount(s.survival, r) > 0u;
  return s;
}

// The default throughput rule judges a path by sqrt(max beta), as Cycles does: a path of throughput 0.04 survives
// with 0.2, not 0.04. On the Cornell box it cut the per-sample relMSE by 1.19x (0.223 -> 0.188 at 64 spp) for
// 8% more rays (docs/tables/estimators.md); the efficiency rule keeps k_d * max(beta), which its pilot models.
VKMC_FN RouletteStep sqrtThroughputRoulette(float unsplitThroughput, float r) {
  return throughputRoulette(sqrt(unsplitThroughput), 1.0f, r);
}

// The path kernels' decision by mode, one definition for shade and the analytic furnace probe so that the probe
// tests the renderer's rule: `scale` is the efficiency mode's k_d at this depth, q the fixed mode's probability.
VKMC_FN RouletteStep rouletteStep(uint mode, float unsplitThroughput, float scale, float q, float r) {
  return mode == kRouletteFixed        ? fixedRoulette(q, r)
         : mode == kRouletteEfficiency ? throughputRoulette(unsplitThroughput, scale, r)
                                       : sqrtThroughputRoulette(unsplitThroughput, r);
}

// Roulette decides at the continuation from vertex `depth` once depth + 1 reaches the first roulette depth.
VKMC_FN bool rouletteApplies(uint depth, uint firstRouletteDepth) { return depth + 1u >= firstRouletteDepth; }

// The splitting factor at a vertex: `factor` (light samples M, or BSDF continuations K) below splitDepth, else 1.
VKMC_FN uint splitFactorAt(uint depth, uint splitDepth, uint factor) { return depth < splitDepth ? factor : 1u; }
VKMC_FN float splitFactorAt(uint depth, uint splitDepth, float factor) {
  return (factor > 1.0f && depth < splitDepth) ? factor : 1.0f;
}

VKMC_END_NAMESPACE
#endif
