// The estimator configuration: Russian roulette, splitting, importance sampling and MIS choices. Parsed from
// CLI flags or a JSON estimator file (same keys), validated, echoed in reports, and turned into the kernels'
// specialization constants here and nowhere else. Each key (its default, range, help and spec constant) is one
// row of the table in estimator_params.cpp; this struct holds the values and the rules that join keys.
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../shaders/shared/layout.h"
#include "../shaders/shared/sampler.h"
#include "vk/kernel.h"

namespace vkmc {

// The kernels' own constants, so the value a spec constant carries cannot drift from what GLSL tests it against.
enum class RouletteMode : uint32_t {
  None = gpu::kRouletteNone,
  Fixed = gpu::kRouletteFixed,
  Throughput = gpu::kRouletteThroughput,
  Efficiency = gpu::kRouletteEfficiency,
  Ears = gpu::kRouletteEars
};
enum class BsdfSampling : uint32_t {
  Uniform = gpu::kBsdfSamplingUniform,
  Cosine = gpu::kBsdfSamplingCosine,
  Bsdf = gpu::kBsdfSamplingFull
};
enum class LightSampling : uint32_t { Area = gpu::kLightSamplingArea, SolidAngle = gpu::kLightSamplingSolidAngle };
enum class LightSelect : uint32_t { Uniform, Power };  // host only: which light table GpuScene builds
enum class Sampler : uint32_t {
  Independent = gpu::kSamplerIndependent,
  Sobol = gpu::kSamplerSobol,
  ZSobol = gpu::kSamplerZSobol
};
// rr ears's guard (path_renderer.cpp): after EARS's first pass, one pass of throughput roulette, then EARS where it
// measures kEarsGuardMargin times as efficient, else throughput roulette (Auto), EARS throughout (Never), or
// throughput roulette (Always: the switch, reproducibly).
enum class EarsFallback : uint32_t { Auto, Never, Always };  // host only

// ears_fallback auto keeps EARS only where it reads above this many times throughput roulette's efficiency. The
// reading is biased toward EARS: a sample's variance leaves out what Sobol stratification takes off the image's
// error, and that is more for throughput roulette, whose cheaper samples reach a larger count (16-s renders at 96x96, both
// policies run to the end, docs/journal/ears.md "What the guard reads": a sample's variance over the image's was 1.1-7.2x
// for throughput roulette against 1.4-4.7x for EARS; the watched reading over the equal-time ratio 1.22 on leaves,
// 1.41-1.62 on the Cornell box, soft_shadows and many_lights, 0.76-1.01 where EARS pays most). Below the margin the
// choice goes to throughput roulette, whose loss where EARS truly won is at most that win.
constexpr double kEarsGuardMargin = 1.25;

enum class MisHeuristic : uint32_t { None = gpu::kMisNone, Balance = gpu::kMisBalance, Power = gpu::kMisPower };

// Path slots per camera path under EARS: room for its splits (a full pool leaves a vertex unsplit, unbiased).
inline constexpr uint32_t kEarsPoolFactor = 4;

struct EstimatorConfig {
  // Every key starts at its default from the table (estimator_params.cpp); {} only keeps a field defined.
  EstimatorConfig();
  RouletteMode rr{};
  float rrQ{};
  float rrC{};
  uint32_t rrDepth{};
  float shadowRrThreshold{};
  float shadowRrQ{};
  float cameraRrQ{};
  float earsMax{};       // rr ears: the largest factor (splitting up to it; 1: learned roulette alone)
  float earsLightMax{};  // rr ears: the largest light factor (0: light samples not learned; 1: their roulette alone)
  bool earsLearnsLight() const { return rr == RouletteMode::Ears && earsLightMax > 0.0f; }
  EarsFallback earsFallback{};
  bool earsMayFallBack() const { return rr == RouletteMode::Ears && earsFallback != EarsFallback::Never; }
  uint32_t lightSamples{};
  uint32_t splitDepth{};
  float bsdfSamples{};  // q: floor(q + u) continuations, each weighted 1/q
  BsdfSampling bsdfSampling{};
  LightSampling lightSampling{};
  LightSelect lightSelect{};
  bool nee{};
  MisHeuristic mis{};
  uint32_t maxDepth{};
  Sampler sampler{};
  uint32_t replicates{};  // independently scrambled replicates a pixel's samples are split into (sampler.h)
  std::string name;       // free text from the estimator file, echoed in reports

  // Every key's range, then the rules that join keys; throws vkmc::Error naming the offending key.
  void validate() const;
  bool unbiased() const { return maxDepth == 0; }
  bool needsFloatAtomics() const { return lightSamples > 1 || splitsPaths(); }
  bool splitsPaths() const { return bsdfSamples > 1.0f || rr == RouletteMode::Ears; }
  // Room for split children, as a multiple of the camera paths of a pass: ceil(K)^min(split_depth, 3), at most 64 (a
  // full pool continues paths unsplit with weight 1, which stays unbiased but loses the variance reduction);
  // kEarsPoolFactor under EARS, whose splits the pool bounds the same way.
  uint32_t pathPoolFactor() const;
  nlohmann::json toJson() const;
  // Applies the keys present in j over the current values (unknown keys are an error).
  void applyJson(const nlohmann::json& j);
  std::vector<vk::SpecConstant> specConstants() const;
  std::string summary() const;
};

EstimatorConfig loadEstimatorFile(const std::string& path);

}  // namespace vkmc
