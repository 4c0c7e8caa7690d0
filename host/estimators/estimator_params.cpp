// The estimator parameter table, and the conversions every reader of a key shares.
#include "estimators/estimator_params.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>
#include <type_traits>

#include "../shaders/shared/ears.h"
#include "error.h"

namespace vkmc {
namespace {

template <typename E>
constexpr uint32_t valueOf(E e) {
  return static_cast<uint32_t>(e);
}

template <auto Field>
double read(const EstimatorConfig& c) {
  auto v = c.*Field;
  if constexpr (std::is_enum_v<decltype(v)>)
    return valueOf(v);
  else
    return static_cast<double>(v);
}

template <auto Field>
void write(EstimatorConfig& c, double v) {
  using T = std::remove_cvref_t<decltype(c.*Field)>;
  if constexpr (std::is_enum_v<T>)
    c.*Field = static_cast<T>(static_cast<uint32_t>(v));
  else
    c.*Field = static_cast<T>(v);
}

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Interval {
  double min, max;
  bool maxExclusive;
};
constexpr Interval halfOpen(double lo, double hi) { return {lo, hi, true}; }
constexpr Interval closed(double lo, double hi) { return {lo, hi, false}; }
constexpr Interval atLeast(double lo) { return {lo, kInfinity, false}; }

template <auto Field>
constexpr EstimatorParam count(const char* key, uint32_t def, uint32_t lo, uint32_t hi, int spec, const char* help,
                               const char* rangeNote = "") {
  return {key,  ParamKind::Count, double(def),  double(lo), double(hi), false, rangeNote, {}, spec,
          help, &read<Field>,     &write<Field>};
}

template <auto Field>
constexpr EstimatorParam real(const char* key, float def, Interval in, int spec, const char* help) {
  return {key, ParamKind::Real, def, in.min, in.max, in.maxExclusive, "", {}, spec, help, &read<Field>, &write<Field>};
}

template <auto Field, typename E>
constexpr EstimatorParam choice(const char* key, E def, std::span<const ParamName> names, int spec, const char* help) {
  return {key, ParamKind::Choice, double(valueOf(def)), 0, 0, false, "", names, spec, help, &read<Field>, &write<Field>};
}

constexpr ParamName kOnOff[] = {{"on", 1}, {"off", 0}};

template <auto Field>
constexpr EstimatorParam onOff(const char* key, bool def, int spec, const char* help) {
  return {key, ParamKind::Switch, def ? 1.0 : 0.0, 0, 0, false, "", kOnOff, spec, help, &read<Field>, &write<Field>};
}

constexpr ParamName kRouletteNames[] = {{"none", valueOf(RouletteMode::None)},
                                        {"fixed", valueOf(RouletteMode::Fixed)},
                                        {"throughput", valueOf(RouletteMode::Throughput)},
                                        {"efficiency", valueOf(RouletteMode::Efficiency)},
                                        {"ears", valueOf(RouletteMode::Ears)}};
constexpr ParamName kBsdfSamplingNames[] = {{"uniform", valueOf(BsdfSampling::Uniform)},
                                            {"cosine", valueOf(BsdfSampling::Cosine)},
                                            {"bsdf", valueOf(BsdfSampling::Bsdf)}};
constexpr ParamName kLightSamplingNames[] = {{"area", valueOf(LightSampling::Area)},
                                             {"solid-angle", valueOf(LightSampling::SolidAngle)}};
constexpr ParamName kLightSelectNames[] = {{"uniform", valueOf(LightSelect::Uniform)}, {"power", valueOf(LightSelect::Power)}};
constexpr ParamName kMisNames[] = {
    {"none", valueOf(MisHeuristic::None)}, {"balance", valueOf(MisHeuristic::Balance)}, {"power", valueOf(MisHeuristic::Power)}};

constexpr ParamName kEarsFallbackNames[] = {
    {"auto", valueOf(EarsFallback::Auto)}, {"never", valueOf(EarsFallback::Never)}, {"always", valueOf(EarsFallback::Always)}};

constexpr ParamName kSamplerNames[] = {
    {"independent", valueOf(Sampler::Independent)}, {"sobol", valueOf(Sampler::Sobol)}, {"zsobol", valueOf(Sampler::ZSobol)}};

using C = EstimatorConfig;
// In the order of --help. The defaults are the renderer's (EstimatorConfig's constructor applies them).
constexpr EstimatorParam kParams[] = {
    count<&C::maxDepth>("max_depth", 0, 0, 100000, SPEC_MAX_DEPTH,
                        "cap on scattering events (biased); 0 = no cap, Russian roulette only", " (0 = no cap)"),
    choice<&C::rr>("rr", RouletteMode::Throughput, kRouletteNames, SPEC_RR_MODE, "Russian roulette"),
    real<&C::rrQ>("rr_q", 0.5f, halfOpen(0, 1), SPEC_RR_Q, "fixed roulette: termination probability q"),
    real<&C::rrC>("rr_c", 0.0f, atLeast(0), SPEC_RR_C, "fixed roulette: value c returned on termination"),
    count<&C::rrDepth>("rr_depth", 3, 0, 256, SPEC_RR_DEPTH, "first depth with roulette",
                       " (before it no path can end by roulette)"),
    real<&C::shadowRrThreshold>("shadow_rr", 0.0f, atLeast(0), SPEC_SHADOW_RR_THRESHOLD,
                                "shadow-ray roulette threshold x pixel estimate; 0 = off"),
    real<&C::shadowRrQ>("shadow_rr_q", 0.5f, halfOpen(0, 1), SPEC_SHADOW_RR_Q, "termination probability of tiny shadow rays"),
    real<&C::cameraRrQ>("camera_rr", 0.0f, halfOpen(0, 1), SPEC_CAMERA_RR_Q,
                        "camera-ray roulette termination probability; 0 = off"),
    real<&C::earsMax>("ears_max", gpu::kEarsFactorMax, closed(1, gpu::kEarsFactorMax), SPEC_EARS_MAX,
                      "rr ears: the largest factor q, so at most this many copies of a vertex; 1 = learned roulette alone"),
    real<&C::earsLightMax>("ears_light_max", 0.0f, closed(0, gpu::kEarsLightFactorMax), SPEC_EARS_LIGHT_MAX,
                           "rr ears: the largest light factor qL, so at most this many light samples a copy; 0 = light "
                           "samples not learned (light_samples, as without ears), 1 = learned shadow-ray roulette alone"),
    choice<&C::earsFallback>(
        "ears_fallback", EarsFallback::Auto, kEarsFallbackNames, -1,
        "rr ears: after a warm-up pass of EARS, a few samples a pixel of EARS and a full pass of "
        "throughput roulette are measured (EARS again on its next pass where it was close); auto: "
        "EARS renders the rest where its efficiency, 1/(variance x seconds) a sample, beats throughput "
        "roulette's by the guard's margin (the report's ears.guard gives both readings), else throughput roulette; "
        "never: EARS throughout; always: throughput roulette after the comparison. Under a time "
        "budget, learning and comparing may take a small share of it: where they would not fit, auto and "
        "always render with throughput roulette uncompared, never with EARS trained that far"),
    count<&C::lightSamples>("light_samples", 1, 1, 4096, SPEC_LIGHT_SAMPLES, "light samples per hit below --split-depth"),
    count<&C::splitDepth>("split_depth", 1, 0, 100000, SPEC_SPLIT_DEPTH,
                          "splitting applies at depths below this; 1: the first hit"),
    real<&C::bsdfSamples>("bsdf_samples", 1.0f, closed(1, 64), SPEC_BSDF_SAMPLES,
                          "BSDF continuations K per hit below --split-depth, each weighted 1/K"),
    choice<&C::bsdfSampling>("bsdf_sampling", BsdfSampling::Bsdf, kBsdfSamplingNames, SPEC_BSDF_SAMPLING,
                             "continuation direction sampling"),
    choice<&C::lightSampling>("light_sampling", LightSampling::Area, kLightSamplingNames, SPEC_LIGHT_SAMPLING,
                              "a point on the light's area or a direction in its solid angle"),
    choice<&C::lightSelect>("light_select", LightSelect::Power, kLightSelectNames, -1,
                            "how a light sample picks its light (an emissive triangle, a punctual light or the environment)"),
    onOff<&C::nee>("nee", true, SPEC_NEE, "next-event estimation"),
    choice<&C::mis>("mis", MisHeuristic::Power, kMisNames, SPEC_MIS, "MIS heuristic of light and BSDF sampling"),
    choice<&C::sampler>("sampler", Sampler::Sobol, kSamplerNames, SPEC_SAMPLER,
                        "uniform numbers: independent hashes, Owen-scrambled Sobol per pixel, or Morton-ordered "
                        "ZSobol"),
    count<&C::replicates>("replicates", 2, 1, gpu::kMaxSampleReplicates, SPEC_SAMPLE_REPLICATES,
                          "independently scrambled replicates per pixel, whose spread is the variance of the pixel "
                          "mean under sobol and zsobol: fewer keep more stratification, more give each pixel's "
                          "variance more degrees of freedom (replicates - 1); 1 keeps all of it and estimates no "
                          "variance"),
};

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%g", v);
  return buf;
}

std::string joinedNames(std::span<const ParamName> names) {
  std::string s;
  for (const ParamName& n : names) s += std::string(s.empty() ? "" : "|") + n.name;
  return s;
}

}  // namespace

std::span<const EstimatorParam> estimatorParams() { return kParams; }

const EstimatorParam* findEstimatorParam(std::string_view key) {
  for (const EstimatorParam& p : kParams)
    if (key == p.key) return &p;
  return nullptr;
}

std::string EstimatorParam::flag() const {
  std::string f = std::string("--") + key;
  std::replace(f.begin(), f.end(), '_', '-');
  return f;
}

std::string EstimatorParam::text(double value) const {
  for (const ParamName& n : names)
    if (n.value == value) return n.name;
  return number(value);
}

std::string EstimatorParam::helpText() const {
  std::string values = names.empty() ? "" : ": " + joinedNames(names);
  return help + values + " (default " + text(defaultValue) + ")";
}

nlohmann::json EstimatorParam::toJson(const EstimatorConfig& c) const {
  double v = get(c);
  switch (kind) {
    case ParamKind::Count: return static_cast<uint32_t>(v);
    case ParamKind::Real: return static_cast<float>(v);
    case ParamKind::Choice:
    case ParamKind::Switch: return text(v);
  }
  return nullptr;
}

void EstimatorParam::setFromJson(EstimatorConfig& c, const nlohmann::json& v) const {
  const std::string k = key;
  if (kind == ParamKind::Count || kind == ParamKind::Real) {
    if (!v.is_number()) throw Error("estimator key '" + k + "' must be a number");
    double d = v.get<double>();
    if (kind == ParamKind::Count && (d < 0 || d > 4e9 || d != std::floor(d)))
      throw Error("estimator key '" + k + "' must be a non-negative integer");
    set(c, d);
    return;
  }
  if (kind == ParamKind::Switch && v.is_boolean()) return set(c, v.get<bool>() ? 1.0 : 0.0);
  if (!v.is_string()) throw Error("estimator key '" + k + "' must be a string");
  const std::string s = v.get<std::string>();
  for (const ParamName& n : names)
    if (s == n.name) return set(c, n.value);
  throw Error(k + ": '" + s + "' is not one of " + joinedNames(names));
}

void EstimatorParam::checkRange(const EstimatorConfig& c) const {
  if (kind != ParamKind::Count && kind != ParamKind::Real) return;
  double v = get(c);
  bool inside = std::isfinite(v) && v >= min && (maxExclusive ? v < max : v <= max);
  if (inside) return;
  const std::string k = key;
  if (kind == ParamKind::Count && min == 0) throw Error(k + " must be at most " + number(max) + rangeNote);
  if (kind == ParamKind::Count) throw Error(k + " must be between " + number(min) + " and " + number(max) + rangeNote);
  if (std::isinf(max)) throw Error(k + " must be finite and >= " + number(min) + rangeNote);
  throw Error(k + " must be in [" + number(min) + ", " + number(max) + (maxExclusive ? ")" : "]") + rangeNote);
}

uint32_t EstimatorParam::specValue(const EstimatorConfig& c) const {
  double v = get(c);
  return kind == ParamKind::Real ? std::bit_cast<uint32_t>(static_cast<float>(v)) : static_cast<uint32_t>(v);
}

}  // namespace vkmc
