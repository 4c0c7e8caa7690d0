#include "passes/pass_policies.h"

#include <algorithm>

namespace vkmc {

PassPlan UniformPasses::next(const PassContext& c) {
  if (c.nextSample >= c.spp) return {};
  return {std::min(c.passSamples, c.spp - c.nextSample)};
}

PassPlan ShadowRoulettePacing::next(const PassContext& c) {
  if (c.nextSample >= c.spp) return {};
  return {std::min({c.passSamples, c.nextSample + 1, c.spp - c.nextSample})};
}

}  // namespace vkmc
