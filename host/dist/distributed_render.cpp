// Batches across ranks, folded in order at rank 0 (see the header).
#include "dist/distributed_render.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>

#include "error.h"
#include "io/checkpoint.h"
#include "render/render_stats.h"

namespace vkmc {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::string bytesOf(const std::vector<gpu::FilmPixel>& batch) {
  return std::string(reinterpret_cast<const char*>(batch.data()), batch.size() * sizeof(gpu::FilmPixel));
}

// Rank 0's pixel estimate (shadow roulette's) on every rank.
void sharePixelEstimate(PathRenderer& renderer, const RankGroup& group, const Film& rootFilm) {
  std::string bytes;
  if (group.isRoot()) {
    std::vector<glm::vec4> estimate = runningPixelEstimate(rootFilm);
    bytes.assign(reinterpret_cast<const char*>(estimate.data()), estimate.size() * sizeof(glm::vec4));
  }
  group.broadcast(bytes);
  if (!group.isRoot()) {
    std::vector<glm::vec4> estimate(bytes.size() / sizeof(glm::vec4));
    std::memcpy(estimate.data(), bytes.data(), estimate.size() * sizeof(glm::vec4));
    renderer.setPixelEstimate(estimate);
  }
}

// Where the render stands: rank 0's state (a checkpoint's, perhaps), told to every rank. Returns the next sample.
uint32_t startingPoint(PathRenderer& renderer, const RankGroup& group, RenderState& state, const DistributedPlan& plan) {
  if (state.film.pixels() == 0) state.film = Film(plan.width, plan.height);
  state.film.replicateVariance = plan.replicateVariance;
  state.film.replicates = plan.replicates;
  std::string where = group.isRoot() ? std::to_string(state.nextSample) + " " + std::to_string(state.batchSamples) : "";
  group.broadcast(where);
  uint32_t next = 0, partial = 0;
  std::sscanf(where.c_str(), "%u %u", &next, &partial);
  if (group.isRoot()) {
    if (partial > 0) renderer.restoreBatch(state.batch);  // a single-process checkpoint's unfolded batch: rank 0 finishes it
    if (state.film.totalSamples() + state.film.totalNonfinite() > 0) renderer.uploadPixelEstimate(state.film);
  }
  if (plan.refreshPixelEstimate && group.distributed()) sharePixelEstimate(renderer, group, state.film);
  return next;
}

// Rank 0 folds a round's batches in batch order.
void foldRound(PathRenderer& renderer, const std::vector<std::string>& batches, uint32_t next, RenderState& state) {
  for (const std::string& b : batches)
    if (!b.empty()) {
      if (b.size() != state.film.pixels() * sizeof(gpu::FilmPixel))
        throw Error("internal error: a rank's batch has the wrong size");
      state.film.addBatch(reinterpret_cast<const gpu::FilmPixel*>(b.data()));
    }
  state.nextSample = next;
  state.batch.clear(), state.batchSamples = 0;
  renderer.uploadPixelEstimate(state.film);
}

// Every rank's counters to rank 0, summed over the counters the render started from; rank 0 gets every report.
std::vector<RankReport> gatherRankReports(PathRenderer& renderer, const RankGroup& group, RenderState& state, RenderStats& mine,
                                          RankReport report, const RenderStats& before, Clock::time_point start) {
  renderer.finishStats(mine, RenderStats{});
  report.rays = mine.rays();
  report.gpuSeconds = mine.gpuSeconds;
  nlohmann::json j = {{"stats", renderStatsJson(mine)}, {"rank", report.rank},       {"host", report.host},
                      {"device", report.device},        {"batches", report.batches}, {"busy_seconds", report.busySeconds}};
  std::vector<std::string> all = group.gather(j.dump());
  std::vector<RankReport> reports;
  if (!group.isRoot()) return reports;
  state.stats = before;
  for (const std::string& text : all) {
    nlohmann::json r = nlohmann::json::parse(text);
    RenderStats s = renderStatsFromJson(r.at("stats"));
    mergeRunCounters(state.stats, s);
    reports.push_back(
        {r.at("rank"), r.at("host"), r.at("device"), s.rays(), r.at("batches"), r.at("busy_seconds"), s.gpuSeconds});
  }
  state.stats.deriveStageTotals();
  state.stats.seconds = before.seconds + since(start);
  state.stats.samplesPerPixel = state.nextSample;
  return reports;
}

RankReport thisRank(const RankGroup& group, const DistributedPlan& plan) {
  RankReport report;
  report.rank = group.rank();
  report.device = plan.device;
  char host[256] = "?";
  ::gethostname(host, sizeof(host) - 1);
  report.host = host;
  return report;
}

}  // namespace

std::vector<RankReport> renderDistributed(PathRenderer& renderer, const RankGroup& group, RenderState& state,
                                          const RenderControl& control, const DistributedPlan& plan) {
  if (renderer.ears().enabled())
    throw Error("rr ears learns between one process's passes; renders under mpirun (more than one rank) do not support it yet");
  const uint32_t ranks = group.size(), me = group.rank();
  const uint32_t perPass = renderer.samplesPerPass();
  const uint32_t batchSamples = plan.timeBudget > 0.0 ? perPass : renderer.samplesPerBatch();
  const uint32_t slots = batchSamples / perPass;  // sample passes a batch takes (fewer for a short one)
  const RenderStats before = state.stats;
  RenderStats mine;
  RankReport report = thisRank(group, plan);
  uint32_t next = startingPoint(renderer, group, state, plan);
  const uint32_t firstBatch = next / batchSamples;
  auto range = [&](uint64_t j, uint32_t& lo, uint32_t& hi) {
    uint64_t l = j == 0 ? next : (firstBatch + j) * uint64_t(batchSamples);
    uint64_t h = std::min<uint64_t>((firstBatch + j + 1) * uint64_t(batchSamples), plan.spp);
    lo = uint32_t(std::min<uint64_t>(l, plan.spp)), hi = uint32_t(std::max<uint64_t>(h, lo));
  };
  auto start = Clock::now();
  double lastCheckpoint = 0.0;
  state.interrupted = false;
  for (uint64_t round = 0; next < plan.spp; ++round) {
    uint32_t lo, hi;
    range(round * ranks + me, lo, hi);
    int stop = 0;  // the signal that stopped a rank, relayed to all (the largest number where two ranks were)
    for (uint32_t slot = 0; slot < slots && !stop; ++slot) {
      uint32_t s = lo + slot * perPass;
      if (s < hi) {
        auto t = Clock::now();
        renderer.renderSamples(s, std::min(perPass, hi - s), mine);
        report.busySeconds += since(t);
      }
      stop = group.maxOver(control.stop ? control.stop->load() : 0);
    }
    if (stop) {  // the round in flight is abandoned on every rank: the state stays that of the last round
      renderer.takeBatch();
      state.interrupted = true;
      state.stopSignal = stop;
      break;
    }
    std::string batch;
    if (lo < hi) batch = bytesOf(renderer.takeBatch()), ++report.batches;
    std::vector<std::string> batches = group.gather(batch);
    uint32_t roundEnd, unused;
    range(round * ranks + ranks - 1, unused, roundEnd);
    next = std::max(roundEnd, std::min(next, plan.spp));
    if (group.isRoot()) foldRound(renderer, batches, next, state);
    if (plan.refreshPixelEstimate && group.distributed()) sharePixelEstimate(renderer, group, state.film);
    bool budgetSpent = plan.timeBudget > 0.0 && since(start) >= plan.timeBudget;
    if (group.maxOver(group.isRoot() && budgetSpent ? 1 : 0) != 0) break;
    if (group.isRoot() && control.checkpoint && control.checkpointEvery > 0.0 && next < plan.spp &&
        since(start) - lastCheckpoint >= control.checkpointEvery) {
      state.stats = before;
      mergeRunCounters(state.stats, mine);  // rank 0's own counters so far: the others' arrive at the end
      state.stats.seconds = before.seconds + since(start);
      state.stats.samplesPerPixel = next;
      control.checkpoint(state);
      lastCheckpoint = since(start);
    }
  }
  return gatherRankReports(renderer, group, state, mine, report, before, start);
}

}  // namespace vkmc
