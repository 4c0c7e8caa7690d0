// The estimator configuration: Russian roulette, splitting, importance sampling and MIS choices. Parsed from
// CLI flags or a JSON estimator file (same keys), validated, echoed in reports, and turned into the kernels'
// specialization constants here and nowhere else.
//
// | key             | values                                  | default    |
// |-----------------|-----------------------------------------|------------|
// | rr              | none, fixed, throughput, efficiency     | throughput |
// | rr_q            | fixed mode: termination probability q   | 0.5        |
// | rr_c            | fixed mode: value c returned on a kill  | 0          |
// | rr_depth        | first depth with roulette               | 3          |
// | shadow_rr       | threshold (x pixel estimate); 0 = off   | 0          |
// | shadow_rr_q     | termination probability of tiny ones    | 0.5        |
// | camera_rr       | termination probability of camera rays  | 0          |
// | light_samples   | M light samples per hit                 | 1          |
// | bsdf_samples    | K continuations per hit (float factor)  | 1          |
// | split_depth     | splitting applies at depths < this      | 1          |
// | bsdf_sampling   | uniform, cosine, bsdf                   | bsdf       |
// | light_sampling  | area, solid-angle                       | area       |
// | light_select    | uniform, power                          | power      |
// | nee             | on, off                                 | on         |
// | mis             | none, balance, power                    | power      |
// | max_depth       | scattering-event cap, 0 = none          | 0          |
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "vk/kernel.h"

namespace vkmc {

enum class RouletteMode { None, Fixed, Throughput, Efficiency };
enum class BsdfSampling { Uniform, Cosine, Bsdf };
enum class LightSampling { Area, SolidAngle };
enum class LightSelect { Uniform, Power };
enum class MisHeuristic { None, Balance, Power };

struct EstimatorConfig {
  RouletteMode rr = RouletteMode::Throughput;
  float rrQ = 0.5f;
  float rrC = 0.0f;
  uint32_t rrDepth = 3;
  float shadowRrThreshold = 0.0f;
  float shadowRrQ = 0.5f;
  float cameraRrQ = 0.0f;
  uint32_t lightSamples = 1;
  uint32_t splitDepth = 1;
  float bsdfSamples = 1.0f;  // q: floor(q + u) continuations, each weighted 1/q
  BsdfSampling bsdfSampling = BsdfSampling::Bsdf;
  LightSampling lightSampling = LightSampling::Area;
  LightSelect lightSelect = LightSelect::Power;
  bool nee = true;
  MisHeuristic mis = MisHeuristic::Power;
  uint32_t maxDepth = 0;
  std::string name;  // free text from the estimator file, echoed in reports

  // Throws vkmc::Error naming the offending key.
  void validate() const;
  bool unbiased() const { return maxDepth == 0; }
  bool needsFloatAtomics() const { return lightSamples > 1 || splitsPaths(); }
  bool splitsPaths() const { return bsdfSamples > 1.0f; }
  // Room for split children, as a multiple of the camera paths of a pass: ceil(K)^split_depth, at most 64 (a
  // full pool continues paths unsplit with weight 1, which stays unbiased but loses the variance reduction).
  uint32_t pathPoolFactor() const;
  nlohmann::json toJson() const;
  // Applies the keys present in j over the current values (unknown keys are an error).
  void applyJson(const nlohmann::json& j);
  std::vector<vk::SpecConstant> specConstants() const;
  std::string summary() const;
};

EstimatorConfig loadEstimatorFile(const std::string& path);

// Names <-> enums, shared by the CLI and the JSON reader.
RouletteMode parseRoulette(const std::string& s);
BsdfSampling parseBsdfSampling(const std::string& s);
LightSampling parseLightSampling(const std::string& s);
LightSelect parseLightSelect(const std::string& s);
MisHeuristic parseMis(const std::string& s);
bool parseOnOff(const std::string& s, const char* key);

}  // namespace vkmc
