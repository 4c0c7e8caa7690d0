// How a time-budgeted render sizes its passes and when it stops (PathRenderer::render). Time is checked between
// passes only, so the rule decides from the last pass's seconds per sample a pixel, its per-pass overhead included.
#pragma once
#include <algorithm>
#include <cstdint>

namespace vkmc {

// Whether the render stops: one more sample a pixel would end further past the budget than short of it.
inline bool timeBudgetSpent(double budget, double elapsed, double secondsPerSample) {
  return budget > 0.0 && elapsed + 0.5 * secondsPerSample >= budget;
}

// Samples a pixel of the next pass: as many as fit in a quarter of the budget (pass sizes grow geometrically on
// overhead-bound small images), and no more than fit in what is left of it, so that the last pass ends near the
// budget instead of up to a quarter past it; at least 1, at most maxPerPass.
inline uint32_t timeBudgetPassSamples(double budget, double elapsed, double secondsPerSample, uint32_t maxPerPass) {
  const double window = std::min(budget / 4.0, budget - elapsed);
  const double n = window / std::max(secondsPerSample, 1e-9) + 0.5;
  return static_cast<uint32_t>(std::clamp(n, 1.0, double(std::max(maxPerPass, 1u))));
}

}  // namespace vkmc
