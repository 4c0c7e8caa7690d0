// RenderStats as JSON and merged, by the one table of render_stats.h.
#include "render/render_stats.h"

#include <algorithm>
#include <limits>
#include <type_traits>

#include "error.h"

namespace vkmc {
namespace {

template <class T>
void mergeValue(T& into, const T& from, StatMerge merge) {
  if (merge == StatMerge::Sum) into += from;
  if (merge == StatMerge::Max) into = std::max(into, from);
}
void mergeValue(bool& into, const bool& from, StatMerge merge) {
  if (merge == StatMerge::Any) into = into || from;
}
void mergeValue(std::map<std::string, double>& into, const std::map<std::string, double>& from, StatMerge merge) {
  if (merge == StatMerge::Sum)
    for (const auto& [name, value] : from) into[name] += value;
}
void mergeValue(std::vector<uint64_t>& into, const std::vector<uint64_t>& from, StatMerge merge) {
  if (merge != StatMerge::Sum) return;
  into.resize(std::max(into.size(), from.size()), 0);
  for (size_t i = 0; i < from.size(); ++i) into[i] += from[i];
}

// Each field read only from a JSON value of its own type and range: a forged checkpoint's 1e300 must not become
// an integer by an undefined conversion.
[[noreturn]] void malformed(const char* name) { throw Error(std::string("its counter '") + name + "' is malformed"); }
template <class T>
void readField(const nlohmann::json& v, const char* name, T& field) {
  static_assert(std::is_unsigned_v<T>);
  if (!v.is_number_unsigned() || v.get<uint64_t>() > std::numeric_limits<T>::max()) malformed(name);
  field = T(v.get<uint64_t>());
}
void readField(const nlohmann::json& v, const char* name, double& field) {
  if (!v.is_number()) malformed(name);
  field = v.get<double>();
}
void readField(const nlohmann::json& v, const char* name, bool& field) {
  if (!v.is_boolean()) malformed(name);
  field = v.get<bool>();
}
void readField(const nlohmann::json& v, const char* name, std::map<std::string, double>& field) {
  if (!v.is_object()) malformed(name);
  for (const auto& [key, value] : v.items()) readField(value, name, field[key]);
}
void readField(const nlohmann::json& v, const char* name, std::vector<uint64_t>& field) {
  if (!v.is_array() || v.size() > (1u << 16)) malformed(name);
  field.resize(v.size());
  for (size_t i = 0; i < v.size(); ++i) readField(v[i], name, field[i]);
}

}  // namespace

nlohmann::json renderStatsJson(const RenderStats& stats) {
  nlohmann::json j = nlohmann::json::object();
  forEachStat([&](const char* name, StatMerge, bool, const auto& field) { j[name] = field; }, stats);
  return j;
}

RenderStats renderStatsFromJson(const nlohmann::json& j) {
  RenderStats stats;
  forEachStat(
      [&](const char* name, StatMerge, bool defaultWhenAbsent, auto& field) {
        if (defaultWhenAbsent && !j.contains(name)) return;
        if (!j.is_object() || !j.contains(name)) malformed(name);
        readField(j.at(name), name, field);
      },
      stats);
  return stats;
}

void mergeRunCounters(RenderStats& into, const RenderStats& from) {
  forEachStat([](const char*, StatMerge merge, bool, auto& a, const auto& b) { mergeValue(a, b, merge); }, into, from);
}

}  // namespace vkmc
