// Vose's method, in double so that large and tiny weights stay exact enough.
#include "render/alias_table.h"

#include "error.h"

namespace vkmc {

std::vector<AliasEntry> buildAliasTable(std::span<const double> weights) {
  size_t n = weights.size();
  double total = 0.0;
  for (double w : weights) {
    if (!(w >= 0.0) || w > 1e300) throw Error("alias table weight is negative or not finite");
    total += w;
  }
  if (n == 0 || !(total > 0.0)) throw Error("alias table needs a positive total weight");
  std::vector<AliasEntry> table(n);
  std::vector<double> scaled(n);
  std::vector<uint32_t> small, large;
  for (size_t i = 0; i < n; ++i) {
    table[i].pmf = static_cast<float>(weights[i] / total);
    scaled[i] = weights[i] / total * static_cast<double>(n);
    (scaled[i] < 1.0 ? small : large).push_back(static_cast<uint32_t>(i));
  }
  while (!small.empty() && !large.empty()) {
    uint32_t s = small.back(), l = large.back();
    small.pop_back();
    table[s] = {static_cast<float>(scaled[s]), l, table[s].pmf};
    scaled[l] = (scaled[l] + scaled[s]) - 1.0;
    if (scaled[l] < 1.0) {
      large.pop_back();
      small.push_back(l);
    }
  }
  for (uint32_t i : large) table[i] = {1.0f, i, table[i].pmf};
  for (uint32_t i : small) table[i] = {1.0f, i, table[i].pmf};  // rounding leftovers
  return table;
}

}  // namespace vkmc
