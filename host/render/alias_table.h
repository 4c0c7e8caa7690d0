// Walker/Vose alias table: O(1) sampling of a discrete distribution (power-proportional light selection).
#pragma once
#include <cstdint>
#include <span>
#include <vector>

namespace vkmc {

struct AliasEntry {
  float probability;  // keep this entry when the fractional part of u * n is below it
  uint32_t alias;
  float pmf;  // normalized weight of this entry
};

// weights must be finite, non-negative, with a positive sum.
std::vector<AliasEntry> buildAliasTable(std::span<const double> weights);

}  // namespace vkmc
