// rr ears's guard: EARS's first pass and one pass of throughput roulette as large are measured, each by its
// efficiency per sample, 1 / (relative variance of a sample x seconds of a sample); the better renders the rest
// (ears_fallback auto). Both passes are in the image, and the choice depends on earlier passes only: unbiased.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "estimators/estimator_config.h"
#include "render/ears_image_statistics.h"

namespace vkmc {

// One policy's pass: the relative variance of one sample (relativeSampleVariance) and the seconds one sample took.
struct PolicyPass {
  double relativeVariance = 0.0;
  double secondsPerSample = 0.0;
  double efficiency() const;  // 1 / (variance x seconds); +inf for a noiseless pass, 0 for a non-finite one
};

// The mean over pixels (with at least two samples in the pass) of their samples' unbiased variance relative to
// scale^2 + epsilon, averaged over the channels. Nothing is left out: a firefly counts as it does in the image's
// error. Under sobol a pixel's samples are stratified, so this is a little above the variance of one sample, for
// either policy alike. Throws on a size mismatch.
double relativeSampleVariance(const std::vector<PixelSums>& pass, const std::vector<glm::vec4>& scale, double epsilon);

// The guard's outcome, for the report.
struct EarsGuardOutcome {
  bool compared = false;      // both passes ran
  bool fellBack = false;      // throughput roulette rendered the rest
  uint32_t fromSample = 0;    // the first sample after the comparison
  PolicyPass ears, throughput;
};

// Whether throughput roulette renders the rest: Always, or under Auto when its efficiency is at least EARS's (a tie
// goes to the cheaper kernels). Never: false.
bool earsFallsBack(EarsFallback mode, const PolicyPass& ears, const PolicyPass& throughput);

// One line for the report: what was measured and chosen.
std::string earsGuardLine(const EarsGuardOutcome& g);

}  // namespace vkmc
