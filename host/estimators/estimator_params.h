// One row per estimator parameter: key, kind, default, range or value names, help and specialization constant.
// The CLI flags, the JSON reader, range checks, the report's echo, --help and the spec constants all read
// these rows (estimator_params.cpp), so a parameter is added or changed in one place.
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>

#include "estimators/estimator_config.h"

namespace vkmc {

enum class ParamKind { Count, Real, Choice, Switch };  // uint32_t, float, an enum by name, on/off

struct ParamName {
  const char* name;
  uint32_t value;
};

struct EstimatorParam {
  const char* key;  // JSON key; the CLI flag is the key with dashes (rr_q: --rr-q)
  ParamKind kind;
  double defaultValue;  // a Choice's enum value, a Switch's 0 or 1
  double min, max;      // Count and Real; max is excluded when maxExclusive
  bool maxExclusive;
  const char* rangeNote;             // why the bound, appended to the range error
  std::span<const ParamName> names;  // Choice and Switch, in the order --help lists them
  int specId;                        // SPEC_* of shaders/shared/layout.h, or -1 when only the host reads it
  const char* help;
  // Every value travels as a double: exact for uint32_t, float and the enums' small values.
  double (*get)(const EstimatorConfig&);
  void (*set)(EstimatorConfig&, double);

  std::string flag() const;
  std::string text(double value) const;  // "throughput", "0.5"
  std::string helpText() const;          // help, every value name and the default
  nlohmann::json toJson(const EstimatorConfig& c) const;
  // Type and name checks; the range is checked by checkRange (EstimatorConfig::validate).
  void setFromJson(EstimatorConfig& c, const nlohmann::json& v) const;
  void checkRange(const EstimatorConfig& c) const;  // throws Error naming the key
  uint32_t specValue(const EstimatorConfig& c) const;
};

std::span<const EstimatorParam> estimatorParams();
const EstimatorParam* findEstimatorParam(std::string_view key);  // nullptr for an unknown key

}  // namespace vkmc
