// render/render_stats.h: every field round-trips through JSON exactly, older checkpoints' missing fields read as
// their defaults, and merging two runs sums counters, keeps maxima and flags, and leaves each run's own fields.
#include "render/render_stats.h"

#include <gtest/gtest.h>

#include "error.h"

using namespace vkmc;

namespace {

RenderStats someStats(uint64_t k) {
  RenderStats s;
  s.seconds = 1.25 * double(k), s.gpuSeconds = 0.1 + double(k);
  s.cameraRays = 10 * k, s.extensionRays = 20 * k, s.shadowRays = 30 * k, s.primaryRays = 10 * k;
  s.primarySeconds = 0.3 * double(k), s.incoherentSeconds = 0.7 * double(k);
  s.stageSeconds = {{"intersect", 0.5 * double(k)}, {"shade", 1.0 / 3.0}};
  s.passes = uint32_t(k), s.maxBounces = uint32_t(3 + k), s.samplesPerPixel = uint32_t(64 * k);
  s.nonfiniteEmission = k, s.nonfiniteLightSamples = 2 * k, s.nonfiniteThroughput = 3 * k, s.traversalsCut = 4 * k;
  s.deepWalks = 5 * k, s.deepWalksTraced = 5 * k, s.splitsRefused = 6 * k;
  s.pathsByBounce = std::vector<uint64_t>(k, 7), s.shadowRaysByBounce = {k, k + 1};
  return s;
}

}  // namespace

TEST(RenderStats, EveryFieldRoundTripsThroughJson) {
  const RenderStats a = someStats(3);
  const nlohmann::json j = renderStatsJson(a);
  EXPECT_EQ(renderStatsJson(renderStatsFromJson(j)), j);
  int fields = 0;
  forEachStat([&](const char*, StatMerge, bool, const auto&) { ++fields; }, a);
  EXPECT_EQ(int(j.size()), fields) << "a field written under a name another field has";
  EXPECT_EQ(renderStatsFromJson(j).stageSeconds.at("shade"), 1.0 / 3.0);
}

TEST(RenderStats, FieldsOlderCheckpointsLackReadAsDefaults) {
  nlohmann::json j = renderStatsJson(someStats(2));
  j.erase("splits_refused");
  j.erase("stages_untimed");
  RenderStats s = renderStatsFromJson(j);
  EXPECT_EQ(s.splitsRefused, 0u);
  EXPECT_FALSE(s.stagesUntimed);
  j.erase("shadow_rays");
  EXPECT_THROW(renderStatsFromJson(j), Error) << "a field every checkpoint has is required";
  j = renderStatsJson(someStats(2));
  j["passes"] = 1e300;  // no undefined float-to-integer conversion: refused
  EXPECT_THROW(renderStatsFromJson(j), Error);
  j = renderStatsJson(someStats(2));
  j["paths_by_bounce"] = {1, -2};
  EXPECT_THROW(renderStatsFromJson(j), Error);
}

TEST(RenderStats, MergingSumsCountersKeepsMaximaAndLeavesOwnFields) {
  RenderStats into = someStats(2);
  RenderStats from = someStats(3);
  from.stagesUntimed = true;
  from.stageSeconds["accumulate"] = 2.0;
  mergeRunCounters(into, from);
  EXPECT_EQ(into.cameraRays, 50u);
  EXPECT_EQ(into.rays(), 50u + 100u + 150u);
  EXPECT_EQ(into.splitsRefused, 30u);
  EXPECT_EQ(into.passes, 5u);
  EXPECT_EQ(into.maxBounces, 6u);
  EXPECT_TRUE(into.stagesUntimed);
  EXPECT_DOUBLE_EQ(into.stageSeconds.at("intersect"), 2.5);
  EXPECT_DOUBLE_EQ(into.stageSeconds.at("accumulate"), 2.0);
  EXPECT_EQ(into.pathsByBounce, (std::vector<uint64_t>{14, 14, 7})) << "2 entries + 3 entries, element by element";
  EXPECT_EQ(into.seconds, 2.5) << "wall seconds are the run's own";
  EXPECT_EQ(into.samplesPerPixel, 128u);
  EXPECT_EQ(into.primarySeconds, 0.6);
}
