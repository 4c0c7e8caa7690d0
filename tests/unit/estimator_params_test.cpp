// The estimator parameter table against everything derived from it: the struct's defaults, the JSON round trip,
// --help, the specialization constants and the range checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "error.h"
#include "estimators/estimator_params.h"

using namespace vkmc;

namespace {

// A value inside the row's range that differs from its default.
double otherValue(const EstimatorParam& p) {
  switch (p.kind) {
    case ParamKind::Count: return p.defaultValue < p.max ? p.defaultValue + 1 : p.defaultValue - 1;
    case ParamKind::Real: return p.defaultValue > p.min ? p.min : p.min + 0.25;
    case ParamKind::Choice:
    case ParamKind::Switch:
      for (const ParamName& n : p.names)
        if (n.value != p.defaultValue) return n.value;
  }
  ADD_FAILURE() << p.key << " has no second value";
  return p.defaultValue;
}

std::string errorOf(const EstimatorConfig& c) {
  try {
    c.validate();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(EstimatorParams, DefaultsAreTheRows) {
  EstimatorConfig c;
  for (const EstimatorParam& p : estimatorParams()) EXPECT_EQ(p.get(c), p.defaultValue) << p.key;
  EXPECT_NO_THROW(c.validate());
  // Every key echoed, and nothing else but the name: a field without a row would be missing here.
  EXPECT_EQ(c.toJson().size(), estimatorParams().size() + 1);
}

TEST(EstimatorParams, KeysAndFlagsAreUnique) {
  std::set<std::string> keys, flags;
  for (const EstimatorParam& p : estimatorParams()) {
    EXPECT_TRUE(keys.insert(p.key).second) << p.key;
    EXPECT_TRUE(flags.insert(p.flag()).second) << p.flag();
    EXPECT_EQ(p.flag().find('_'), std::string::npos) << p.flag();
    EXPECT_EQ(findEstimatorParam(p.key), &p);
  }
  EXPECT_EQ(findEstimatorParam("no_such_key"), nullptr);
}

TEST(EstimatorParams, EveryKeyRoundTripsThroughJson) {
  for (const EstimatorParam& p : estimatorParams()) {
    SCOPED_TRACE(p.key);
    EstimatorConfig c;
    p.set(c, otherValue(p));
    ASSERT_NE(p.get(c), p.defaultValue);
    EstimatorConfig d;
    d.applyJson(c.toJson());
    EXPECT_EQ(p.get(d), p.get(c));
    EXPECT_EQ(d.toJson(), c.toJson());
  }
  EstimatorConfig named;
  named.applyJson({{"name", "n"}, {"comment", "ignored"}, {"nee", false}});
  EXPECT_EQ(named.name, "n");
  EXPECT_FALSE(named.nee) << "nee also takes a JSON boolean";
}

TEST(EstimatorParams, HelpListsEveryValueAndTheDefault) {
  for (const EstimatorParam& p : estimatorParams()) {
    std::string help = p.helpText();
    for (const ParamName& n : p.names) EXPECT_NE(help.find(n.name), std::string::npos) << p.key << ": " << help;
    EXPECT_NE(help.find("(default " + p.text(p.defaultValue) + ")"), std::string::npos) << p.key << ": " << help;
  }
  EXPECT_NE(findEstimatorParam("rr")->helpText().find("efficiency"), std::string::npos);
}

TEST(EstimatorParams, EverySpecIdIsInTheSpecConstants) {
  EstimatorConfig c;
  std::vector<vk::SpecConstant> specs = c.specConstants();
  size_t withSpec = 0;
  for (const EstimatorParam& p : estimatorParams()) {
    if (p.specId < 0) continue;
    ++withSpec;
    auto it = std::find_if(specs.begin(), specs.end(), [&](const vk::SpecConstant& s) { return int(s.id) == p.specId; });
    ASSERT_NE(it, specs.end()) << p.key;
    EXPECT_EQ(it->value, p.specValue(c)) << p.key;
  }
  EXPECT_EQ(specs.size(), withSpec);
  // Enums pass their value through: it is the kernels' constant.
  c.mis = MisHeuristic::Balance;
  for (const vk::SpecConstant& s : c.specConstants()) {
    if (s.id == SPEC_MIS) {
      EXPECT_EQ(s.value, gpu::kMisBalance);
    }
  }
}

TEST(EstimatorParams, OutOfRangeValuesAreRefusedNamingTheKey) {
  for (const EstimatorParam& p : estimatorParams()) {
    if (p.kind != ParamKind::Count && p.kind != ParamKind::Real) continue;
    SCOPED_TRACE(p.key);
    std::vector<double> outside;
    if (p.min > 0 || p.kind == ParamKind::Real) outside.push_back(p.min - 1);
    if (std::isfinite(p.max)) outside.push_back(p.maxExclusive ? p.max : p.max + 1);
    if (p.kind == ParamKind::Real) outside.push_back(std::nan(""));
    ASSERT_FALSE(outside.empty());
    for (double v : outside) {
      EstimatorConfig c;
      p.set(c, v);
      EXPECT_NE(errorOf(c).find(p.key), std::string::npos) << v << ": " << errorOf(c);
    }
    EstimatorConfig wrongType;
    try {
      wrongType.applyJson({{p.key, "text"}});
      ADD_FAILURE() << "a string was taken as a number";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(p.key), std::string::npos) << e.what();
    }
  }
  try {
    EstimatorConfig().applyJson({{"mis", "best"}});
    ADD_FAILURE() << "an unknown name was taken";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "mis: 'best' is not one of none|balance|power");
  }
  EXPECT_THROW(EstimatorConfig().applyJson({{"rr_typo", 1}}), Error);
}
