// RenderStats' fields in one table: their JSON names and how two runs' values combine. The checkpoint's
// serializer, its reader and the ranks' merge (dist/) all walk this table, so a new counter is one row here.
#pragma once
#include <nlohmann/json.hpp>

#include "render/render_settings.h"

namespace vkmc {

// How a field of one run combines with another run's (ranks of one render, parts of a resumed render).
enum class StatMerge {
  Sum,  // counters, GPU seconds; maps and vectors element by element
  Max,  // maxima
  Any,  // flags: true when either run's is
  Own,  // not merged: the caller's run owns it (wall seconds, samples per pixel, derived totals)
};

// Visits every field of RenderStats as visit(jsonName, merge, defaultWhenAbsent, field of each stats given):
// defaultWhenAbsent is true for fields that older checkpoints lack, read as their default.
template <class Visit, class... Stats>
void forEachStat(Visit&& visit, Stats&... s) {
  visit("seconds", StatMerge::Own, false, s.seconds...);
  visit("gpu_seconds", StatMerge::Sum, false, s.gpuSeconds...);
  visit("camera_rays", StatMerge::Sum, false, s.cameraRays...);
  visit("extension_rays", StatMerge::Sum, false, s.extensionRays...);
  visit("shadow_rays", StatMerge::Sum, false, s.shadowRays...);
  visit("primary_rays", StatMerge::Sum, false, s.primaryRays...);
  visit("primary_seconds", StatMerge::Own, false, s.primarySeconds...);
  visit("incoherent_seconds", StatMerge::Own, false, s.incoherentSeconds...);
  visit("stage_seconds", StatMerge::Sum, false, s.stageSeconds...);
  visit("stages_untimed", StatMerge::Any, true, s.stagesUntimed...);
  visit("passes", StatMerge::Sum, false, s.passes...);
  visit("max_bounces", StatMerge::Max, false, s.maxBounces...);
  visit("samples_per_pixel", StatMerge::Own, false, s.samplesPerPixel...);
  visit("nonfinite_emission", StatMerge::Sum, false, s.nonfiniteEmission...);
  visit("nonfinite_light_samples", StatMerge::Sum, false, s.nonfiniteLightSamples...);
  visit("nonfinite_throughput", StatMerge::Sum, false, s.nonfiniteThroughput...);
  visit("traversals_cut", StatMerge::Sum, false, s.traversalsCut...);
  visit("deep_walks", StatMerge::Sum, false, s.deepWalks...);
  visit("deep_walks_traced", StatMerge::Sum, false, s.deepWalksTraced...);
  visit("splits_refused", StatMerge::Sum, true, s.splitsRefused...);
  visit("paths_by_bounce", StatMerge::Sum, false, s.pathsByBounce...);
  visit("shadow_rays_by_bounce", StatMerge::Sum, false, s.shadowRaysByBounce...);
}

// A run's counters as JSON and back (exact: integers and doubles round-trip). Reading throws vkmc::Error naming a
// missing field or one of the wrong type or range.
nlohmann::json renderStatsJson(const RenderStats& stats);
RenderStats renderStatsFromJson(const nlohmann::json& j);
// Another run's counters added to these (StatMerge of each field).
void mergeRunCounters(RenderStats& into, const RenderStats& from);

}  // namespace vkmc
