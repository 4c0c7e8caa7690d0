// The plain pass policies (pass_policy.h).
#pragma once
#include "passes/pass_policy.h"

namespace vkmc {

// Every pass as large as the renderer would make it, up to spp.
class UniformPasses : public PassPolicy {
 public:
  PassPlan next(const PassContext& c) override;
};

// Shadow-ray roulette reads the running pixel estimate, which is poor after few samples, so its passes start
// small and double: the pass from sample s takes s + 1 samples (1, 2, 4, ...), a function of s alone, so a
// resumed render passes where the uninterrupted one did.
class ShadowRoulettePacing : public PassPolicy {
 public:
  PassPlan next(const PassContext& c) override;
};

}  // namespace vkmc
