// Estimator configuration: the table's rows applied to the whole struct, the rules that join keys, the summary.
#include "estimators/estimator_config.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "error.h"
#include "estimators/estimator_params.h"

namespace vkmc {
namespace {
// The name of a Choice or Switch key's value, for the summary line.
std::string nameOf(const char* key, const EstimatorConfig& c) {
  const EstimatorParam& p = *findEstimatorParam(key);
  return p.text(p.get(c));
}
}  // namespace

EstimatorConfig::EstimatorConfig() {
  for (const EstimatorParam& p : estimatorParams()) p.set(*this, p.defaultValue);
}

void EstimatorConfig::validate() const {
  for (const EstimatorParam& p : estimatorParams()) p.checkRange(*this);
  if (rr == RouletteMode::Fixed && rrQ == 0.0f && maxDepth == 0)
    throw Error("rr fixed with rr_q 0 never ends a path: give rr_q > 0 or a depth cap (--max-depth)");
  if (rr == RouletteMode::None && maxDepth == 0)
    throw Error("rr none needs a depth cap (--max-depth > 0): without roulette or a cap paths never end");
  if (!nee && lightSamples > 1) throw Error("light_samples > 1 needs nee on");
  if (rr == RouletteMode::Ears && bsdfSamples > 1.0f)
    throw Error("rr ears chooses each vertex's splitting itself: leave bsdf_samples at 1");
}

nlohmann::json EstimatorConfig::toJson() const {
  nlohmann::json j = {{"name", name}};
  for (const EstimatorParam& p : estimatorParams()) j[p.key] = p.toJson(*this);
  return j;
}

void EstimatorConfig::applyJson(const nlohmann::json& j) {
  if (!j.is_object()) throw Error("estimator file must hold a JSON object");
  for (const auto& [key, v] : j.items()) {
    if (key == "comment") continue;
    if (key == "name") {
      if (!v.is_string()) throw Error("estimator key 'name' must be a string");
      name = v.get<std::string>();
      continue;
    }
    const EstimatorParam* p = findEstimatorParam(key);
    if (!p) throw Error("unknown estimator key '" + key + "'");
    p->setFromJson(*this, v);
  }
}

EstimatorConfig loadEstimatorFile(const std::string& path) {
  // A FIFO or a device would block the open or never end: only a regular file of a plausible size is read.
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw Error("estimator file '" + path + "' is not a regular file");
  if (std::filesystem::exists(path, ec) && std::filesystem::file_size(path, ec) > (1u << 20))
    throw Error("estimator file '" + path + "' is larger than 1 MiB");
  std::ifstream in(path);
  if (!in) throw Error("cannot open estimator file '" + path + "'");
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded()) throw Error("estimator file '" + path + "' is not valid JSON");
  EstimatorConfig c;
  c.applyJson(j);
  return c;
}

// In ascending id order, as the kernels' plans have always listed them.
std::vector<vk::SpecConstant> EstimatorConfig::specConstants() const {
  std::vector<vk::SpecConstant> specs;
  for (const EstimatorParam& p : estimatorParams())
    if (p.specId >= 0) specs.push_back({static_cast<uint32_t>(p.specId), p.specValue(*this)});
  std::sort(specs.begin(), specs.end(), [](const vk::SpecConstant& a, const vk::SpecConstant& b) { return a.id < b.id; });
  return specs;
}

uint32_t EstimatorConfig::pathPoolFactor() const {
  if (rr == RouletteMode::Ears) return kEarsPoolFactor;
  if (!splitsPaths()) return 1;
  double factor = std::pow(std::ceil(bsdfSamples), std::min<uint32_t>(splitDepth, 3));
  return static_cast<uint32_t>(std::min(64.0, factor));  // 64: the largest factor validate() accepts
}

std::string EstimatorConfig::summary() const {
  std::ostringstream s;
  s << "nee " << nameOf("nee", *this) << ", mis " << nameOf("mis", *this) << ", bsdf " << nameOf("bsdf_sampling", *this)
    << ", lights " << nameOf("light_select", *this) << "/" << nameOf("light_sampling", *this) << ", rr " << nameOf("rr", *this);
  if (rr == RouletteMode::Fixed) s << " (q " << rrQ << ", c " << rrC << ")";
  if (rr == RouletteMode::Ears) {
    s << " (learned roulette and splitting at every vertex";
    if (earsLightMax > 0) s << ", and of its light samples up to " << earsLightMax;
    if (earsFallback == EarsFallback::Auto)
      s << "; throughput roulette instead unless ears measures " << kEarsGuardMargin << "x as efficient";
    if (earsFallback == EarsFallback::Always)
      s << "; throughput roulette once the guard has measured both (ears_fallback always)";
    s << "; throughput roulette from depth " << rrDepth << " where nothing is learned yet)";
  } else if (rr != RouletteMode::None)
    s << " from depth " << rrDepth;
  if (lightSamples > 1) s << ", " << lightSamples << " light samples below depth " << splitDepth;
  if (bsdfSamples > 1) s << ", " << bsdfSamples << " BSDF samples below depth " << splitDepth;
  if (shadowRrThreshold > 0) s << ", shadow rr " << shadowRrThreshold << " (q " << shadowRrQ << ")";
  if (cameraRrQ > 0) s << ", camera rr q " << cameraRrQ;
  s << (maxDepth ? ", depth cap " + std::to_string(maxDepth) + " (biased by truncation)" : ", no depth cap (unbiased)");
  return s.str();
}

}  // namespace vkmc
