// RenderStats as JSON and merged, by the one table of render_stats.h.
#include "render/render_stats.h"

#include <algorithm>

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
        j.at(name).get_to(field);
      },
      stats);
  return stats;
}

void mergeRunCounters(RenderStats& into, const RenderStats& from) {
  forEachStat([](const char*, StatMerge merge, bool, auto& a, const auto& b) { mergeValue(a, b, merge); }, into, from);
}

}  // namespace vkmc
