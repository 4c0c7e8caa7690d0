// Estimator configuration: parsing, validation, JSON echo, specialization constants.
#include "estimators/estimator_config.h"

#include <bit>
#include <cmath>
#include <fstream>
#include <sstream>

#include "../shaders/shared/layout.h"
#include "error.h"

namespace vkmc {
namespace {

template <typename E>
E parseEnum(const std::string& s, const char* key, std::initializer_list<std::pair<const char*, E>> names) {
  std::string options;
  for (const auto& [name, value] : names) {
    if (s == name) return value;
    options += std::string(options.empty() ? "" : "|") + name;
  }
  throw Error(std::string(key) + ": '" + s + "' is not one of " + options);
}

const char* nameOf(RouletteMode m) {
  switch (m) {
    case RouletteMode::None: return "none";
    case RouletteMode::Fixed: return "fixed";
    case RouletteMode::Throughput: return "throughput";
    case RouletteMode::Efficiency: return "efficiency";
  }
  return "?";
}
const char* nameOf(BsdfSampling b) { return b == BsdfSampling::Uniform ? "uniform" : b == BsdfSampling::Cosine ? "cosine" : "bsdf"; }
const char* nameOf(LightSampling l) { return l == LightSampling::Area ? "area" : "solid-angle"; }
const char* nameOf(LightSelect l) { return l == LightSelect::Uniform ? "uniform" : "power"; }
const char* nameOf(MisHeuristic m) { return m == MisHeuristic::None ? "none" : m == MisHeuristic::Balance ? "balance" : "power"; }

uint32_t floatBits(float f) { return std::bit_cast<uint32_t>(f); }

}  // namespace

RouletteMode parseRoulette(const std::string& s) {
  return parseEnum<RouletteMode>(s, "rr", {{"none", RouletteMode::None}, {"fixed", RouletteMode::Fixed},
                                           {"throughput", RouletteMode::Throughput}, {"efficiency", RouletteMode::Efficiency}});
}
BsdfSampling parseBsdfSampling(const std::string& s) {
  return parseEnum<BsdfSampling>(s, "bsdf_sampling",
                                 {{"uniform", BsdfSampling::Uniform}, {"cosine", BsdfSampling::Cosine}, {"bsdf", BsdfSampling::Bsdf}});
}
LightSampling parseLightSampling(const std::string& s) {
  return parseEnum<LightSampling>(s, "light_sampling", {{"area", LightSampling::Area}, {"solid-angle", LightSampling::SolidAngle}});
}
LightSelect parseLightSelect(const std::string& s) {
  return parseEnum<LightSelect>(s, "light_select", {{"uniform", LightSelect::Uniform}, {"power", LightSelect::Power}});
}
MisHeuristic parseMis(const std::string& s) {
  return parseEnum<MisHeuristic>(s, "mis", {{"none", MisHeuristic::None}, {"balance", MisHeuristic::Balance}, {"power", MisHeuristic::Power}});
}
bool parseOnOff(const std::string& s, const char* key) { return parseEnum<bool>(s, key, {{"on", true}, {"off", false}}); }

void EstimatorConfig::validate() const {
  auto probability = [](float v, const char* key, bool allowOne) {
    if (!std::isfinite(v) || v < 0.0f || (allowOne ? v > 1.0f : v >= 1.0f))
      throw Error(std::string(key) + " must be in [0, 1" + (allowOne ? "]" : ")"));
  };
  probability(rrQ, "rr_q", false);
  probability(shadowRrQ, "shadow_rr_q", false);
  probability(cameraRrQ, "camera_rr", false);
  if (!std::isfinite(rrC) || rrC < 0.0f) throw Error("rr_c must be finite and >= 0");
  if (!std::isfinite(shadowRrThreshold) || shadowRrThreshold < 0.0f) throw Error("shadow_rr must be finite and >= 0");
  if (rrDepth > 256) throw Error("rr_depth must be at most 256 (before it no path can end by roulette)");
  if (rr == RouletteMode::Fixed && rrQ == 0.0f && maxDepth == 0)
    throw Error("rr fixed with rr_q 0 never ends a path: give rr_q > 0 or a depth cap (--max-depth)");
  if (lightSamples < 1 || lightSamples > 4096) throw Error("light_samples must be between 1 and 4096");
  if (splitDepth > 100000) throw Error("split_depth must be at most 100000");
  if (maxDepth > 100000) throw Error("max_depth must be at most 100000 (0 = no cap)");
  if (rr == RouletteMode::None && maxDepth == 0)
    throw Error("rr none needs a depth cap (--max-depth > 0): without roulette or a cap paths never end");
  if (!nee && lightSamples > 1) throw Error("light_samples > 1 needs nee on");
  if (!std::isfinite(bsdfSamples) || bsdfSamples < 1.0f || bsdfSamples > 64.0f) throw Error("bsdf_samples must be in [1, 64]");
}

nlohmann::json EstimatorConfig::toJson() const {
  return {{"rr", nameOf(rr)},
          {"rr_q", rrQ},
          {"rr_c", rrC},
          {"rr_depth", rrDepth},
          {"shadow_rr", shadowRrThreshold},
          {"shadow_rr_q", shadowRrQ},
          {"camera_rr", cameraRrQ},
          {"light_samples", lightSamples},
          {"split_depth", splitDepth},
          {"bsdf_samples", bsdfSamples},
          {"bsdf_sampling", nameOf(bsdfSampling)},
          {"light_sampling", nameOf(lightSampling)},
          {"light_select", nameOf(lightSelect)},
          {"nee", nee ? "on" : "off"},
          {"mis", nameOf(mis)},
          {"max_depth", maxDepth},
          {"name", name}};
}

void EstimatorConfig::applyJson(const nlohmann::json& j) {
  if (!j.is_object()) throw Error("estimator file must hold a JSON object");
  auto number = [&](const std::string& key, const nlohmann::json& v) {
    if (!v.is_number()) throw Error("estimator key '" + key + "' must be a number");
    return v.get<double>();
  };
  auto count = [&](const std::string& key, const nlohmann::json& v) {
    double d = number(key, v);
    if (d < 0 || d > 4e9 || d != std::floor(d)) throw Error("estimator key '" + key + "' must be a non-negative integer");
    return static_cast<uint32_t>(d);
  };
  auto text = [&](const std::string& key, const nlohmann::json& v) {
    if (!v.is_string()) throw Error("estimator key '" + key + "' must be a string");
    return v.get<std::string>();
  };
  for (const auto& [key, v] : j.items()) {
    if (key == "rr") rr = parseRoulette(text(key, v));
    else if (key == "rr_q") rrQ = static_cast<float>(number(key, v));
    else if (key == "rr_c") rrC = static_cast<float>(number(key, v));
    else if (key == "rr_depth") rrDepth = count(key, v);
    else if (key == "shadow_rr") shadowRrThreshold = static_cast<float>(number(key, v));
    else if (key == "shadow_rr_q") shadowRrQ = static_cast<float>(number(key, v));
    else if (key == "camera_rr") cameraRrQ = static_cast<float>(number(key, v));
    else if (key == "light_samples") lightSamples = count(key, v);
    else if (key == "split_depth") splitDepth = count(key, v);
    else if (key == "bsdf_samples") bsdfSamples = static_cast<float>(number(key, v));
    else if (key == "bsdf_sampling") bsdfSampling = parseBsdfSampling(text(key, v));
    else if (key == "light_sampling") lightSampling = parseLightSampling(text(key, v));
    else if (key == "light_select") lightSelect = parseLightSelect(text(key, v));
    else if (key == "nee") nee = v.is_boolean() ? v.get<bool>() : parseOnOff(text(key, v), "nee");
    else if (key == "mis") mis = parseMis(text(key, v));
    else if (key == "max_depth") maxDepth = count(key, v);
    else if (key == "name") name = text(key, v);
    else if (key == "comment") continue;
    else throw Error("unknown estimator key '" + key + "'");
  }
}

EstimatorConfig loadEstimatorFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("cannot open estimator file '" + path + "'");
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded()) throw Error("estimator file '" + path + "' is not valid JSON");
  EstimatorConfig c;
  c.applyJson(j);
  return c;
}

std::vector<vk::SpecConstant> EstimatorConfig::specConstants() const {
  return {{SPEC_MAX_DEPTH, maxDepth},
          {SPEC_RR_DEPTH, rrDepth},
          {SPEC_NEE, nee ? 1u : 0u},
          {SPEC_MIS, static_cast<uint32_t>(mis)},
          {SPEC_BSDF_SAMPLING, static_cast<uint32_t>(bsdfSampling)},
          {SPEC_LIGHT_SAMPLING, static_cast<uint32_t>(lightSampling)},
          {SPEC_RR_MODE, static_cast<uint32_t>(rr)},
          {SPEC_RR_Q, floatBits(rrQ)},
          {SPEC_RR_C, floatBits(rrC)},
          {SPEC_LIGHT_SAMPLES, lightSamples},
          {SPEC_SPLIT_DEPTH, splitDepth},
          {SPEC_SHADOW_RR_THRESHOLD, floatBits(shadowRrThreshold)},
          {SPEC_SHADOW_RR_Q, floatBits(shadowRrQ)},
          {SPEC_CAMERA_RR_Q, floatBits(cameraRrQ)},
          {SPEC_BSDF_SAMPLES, floatBits(bsdfSamples)}};
}

uint32_t EstimatorConfig::pathPoolFactor() const {
  if (!splitsPaths()) return 1;
  double factor = std::pow(std::ceil(bsdfSamples), std::min<uint32_t>(splitDepth, 3));
  return static_cast<uint32_t>(std::min(64.0, factor));  // 64: the largest factor validate() accepts
}

std::string EstimatorConfig::summary() const {
  std::ostringstream s;
  s << "nee " << (nee ? "on" : "off") << ", mis " << nameOf(mis) << ", bsdf " << nameOf(bsdfSampling) << ", lights "
    << nameOf(lightSelect) << "/" << nameOf(lightSampling) << ", rr " << nameOf(rr);
  if (rr == RouletteMode::Fixed) s << " (q " << rrQ << ", c " << rrC << ")";
  if (rr != RouletteMode::None) s << " from depth " << rrDepth;
  if (lightSamples > 1) s << ", " << lightSamples << " light samples below depth " << splitDepth;
  if (bsdfSamples > 1) s << ", " << bsdfSamples << " BSDF samples below depth " << splitDepth;
  if (shadowRrThreshold > 0) s << ", shadow rr " << shadowRrThreshold << " (q " << shadowRrQ << ")";
  if (cameraRrQ > 0) s << ", camera rr q " << cameraRrQ;
  s << (maxDepth ? ", depth cap " + std::to_string(maxDepth) + " (biased by truncation)" : ", no depth cap (unbiased)");
  return s.str();
}

}  // namespace vkmc
