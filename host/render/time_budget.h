// How a time-budgeted render sizes its passes and when it stops (PathRenderer::render). Time is checked between
// passes only, so the rule decides from the last pass's seconds per sample a pixel, its per-pass overhead included.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace vkmc {

// Whether the render stops: the budget is spent (a render never stops short of it).
inline bool timeBudgetSpent(double budget, double elapsed) { return budget > 0.0 && elapsed >= budget; }

// Samples a pixel of the next pass: as many as fit in a quarter of the budget (pass sizes grow geometrically on
// overhead-bound small images), and no more than reach the end of what is left of it, so that the last pass
// ends about a sample past the budget instead of up to a quarter past it; at least 1, at most maxPerPass.
inline uint32_t timeBudgetPassSamples(double budget, double elapsed, double secondsPerSample, uint32_t maxPerPass) {
  const double quarter = budget / 4.0 / std::max(secondsPerSample, 1e-9);
  const double left = std::ceil((budget - elapsed) / std::max(secondsPerSample, 1e-9));
  return static_cast<uint32_t>(std::clamp(std::min(quarter, left), 1.0, double(std::max(maxPerPass, 1u))));
}

}  // namespace vkmc
