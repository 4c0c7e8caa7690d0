// rr ears's guard (ears_guard.h).
#include "passes/ears_guard.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "error.h"

namespace vkmc {

double PolicyPass::efficiency() const {
  const double cost = relativeVariance * secondsPerSample;
  if (!std::isfinite(cost) || cost < 0.0) return 0.0;
  return cost > 0.0 ? 1.0 / cost : std::numeric_limits<double>::infinity();
}

double relativeSampleVariance(const std::vector<PixelSums>& pass, const std::vector<glm::vec4>& scale, double epsilon) {
  if (scale.size() != pass.size()) throw Error("internal error: the pass's sums and the scale differ in size");
  double sum = 0.0;
  size_t pixels = 0;
  for (size_t p = 0; p < pass.size(); ++p) {
    const PixelSums& s = pass[p];
    if (!(s.n >= 2.0)) continue;
    double v = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double variance = std::max(0.0, s.sumSq[c] - s.sum[c] * s.sum[c] / s.n) / (s.n - 1.0);
      v += variance / (double(scale[p][c]) * double(scale[p][c]) + epsilon);
    }
    sum += v / 3.0;
    ++pixels;
  }
  return pixels > 0 ? sum / double(pixels) : std::numeric_limits<double>::quiet_NaN();
}

void PolicyTally::addPass(const std::vector<PixelSums>& pass, uint32_t passSamples, double passSeconds) {
  if (sums.empty()) sums.resize(pass.size());
  if (sums.size() != pass.size()) throw Error("internal error: the guard's passes differ in size");
  for (size_t p = 0; p < pass.size(); ++p) {
    sums[p].n += pass[p].n;
    sums[p].sum += pass[p].sum;
    sums[p].sumSq += pass[p].sumSq;
  }
  samples += passSamples;
  seconds += passSeconds;
}

double earsSecondsPerSample(const PolicyTally& t, double pixels, double passSamples, double trainingPixelSamples) {
  if (!(t.trainPixelSamples > 0.0)) return t.samples > 0 ? t.seconds / t.samples : 0.0;
  const double train = t.trainSeconds / t.trainPixelSamples;
  const double lean = t.leanPixelSamples > 0.0 ? t.leanSeconds / t.leanPixelSamples : train;
  const double all = pixels * passSamples, training = std::min(trainingPixelSamples, all);
  return (training * train + (all - training) * lean) / all * pixels;
}

bool earsFallsBack(EarsFallback mode, const PolicyPass& ears, const PolicyPass& throughput) {
  if (mode == EarsFallback::Never) return false;
  if (mode == EarsFallback::Always) return true;
  return !(ears.efficiency() > kEarsGuardMargin * throughput.efficiency());
}

bool earsGuardWatches(EarsFallback mode) { return mode == EarsFallback::Auto; }

bool earsGuardLooksAgain(EarsFallback mode, const PolicyPass& ears, const PolicyPass& throughput) {
  if (mode == EarsFallback::Never) return false;
  if (mode == EarsFallback::Always) return true;
  const double e = ears.efficiency(), t = throughput.efficiency();
  return e <= kEarsGuardMargin * t && e >= kEarsSecondLookRatio * t;
}

double earsLearningSecondsLeft(uint32_t trainingSamples, uint32_t earsSamples, double earsSecondsPerSample,
                               double throughputSeconds) {
  return double(trainingSamples + earsSamples) * earsSecondsPerSample + throughputSeconds;
}

double earsThroughputPassSeconds(double firstSeconds, uint32_t firstSamples, double overhead, uint32_t passes, uint32_t samples) {
  const double perSample = std::max(firstSeconds - overhead, 0.0) / double(std::max(firstSamples, 1u));
  return double(passes) * overhead + double(samples) * perSample;
}

double earsPassOverhead(double seconds, uint32_t samples, double laterSeconds, uint32_t laterSamples, double cap) {
  if (laterSamples <= samples) return 0.0;
  const double a = (seconds * laterSamples - laterSeconds * samples) / double(laterSamples - samples);
  return std::clamp(a, 0.0, std::max(cap, 0.0));
}

double earsLearningCostSeconds(double decidedAt, uint32_t samplesBefore, double endSeconds, uint32_t samplesAfter) {
  if (!std::isfinite(decidedAt) || samplesAfter == 0) return std::numeric_limits<double>::quiet_NaN();
  return decidedAt - double(samplesBefore) * (endSeconds - decidedAt) / double(samplesAfter);
}

bool earsLearningFits(double budget, double elapsed, double secondsLeft) {
  return !(budget > 0.0) || elapsed + secondsLeft <= kEarsLearningBudgetShare * budget;
}

namespace {
std::string earsLearningCostText(const EarsGuardOutcome& g) {
  if (!std::isfinite(g.learningCostSeconds)) return "";
  char buf[120];
  std::snprintf(buf, sizeof(buf), "; choosing cost %.3g s (decided at %.3g s)", g.learningCostSeconds, g.decidedAtSeconds);
  return buf;
}
}  // namespace

std::string earsGuardLine(const EarsGuardOutcome& g) {
  if (g.outOfBudget) {
    char buf[240];
    std::snprintf(buf, sizeof(buf),
                  "ears guard  learning and comparing would take more than %g of the time budget: %s from sample %u%s\n",
                  kEarsLearningBudgetShare, g.fellBack ? "throughput roulette, not compared," : "ears, training cut short,",
                  g.fromSample, earsLearningCostText(g).c_str());
    return buf;
  }
  if (!g.compared) return "";
  char again[120] = "";
  if (g.secondLook)
    std::snprintf(again, sizeof(again), " (measured again: its first %u samples read %.4g)", g.firstEars.samples,
                  g.firstEars.efficiency());
  char watch[200] = "";
  if (g.switchedLater)
    std::snprintf(watch, sizeof(watch), "; watched over %u samples a pixel, ears read %.4g: throughput roulette from sample %u",
                  g.watchedEars.samples, g.watchedEars.efficiency(), g.switchedAt);
  else if (g.watched && g.watchedEars.samples > 0)
    std::snprintf(watch, sizeof(watch), "; watched over %u more samples a pixel, ears read %.4g", g.watchedEars.samples,
                  g.watchedEars.efficiency());
  char buf[640];
  std::snprintf(buf, sizeof(buf),
                "ears guard  efficiency 1/(relative variance x seconds) a sample, measured on %u samples a pixel of ears "
                "and %u of throughput roulette: ears %.4g%s, throughput roulette %.4g; %s from sample %u%s%s\n",
                g.ears.samples, g.throughput.samples, g.ears.efficiency(), again, g.throughput.efficiency(),
                g.switchedLater ? "ears"
                : g.fellBack    ? "throughput roulette"
                                : "ears",
                g.fromSample, watch, earsLearningCostText(g).c_str());
  return buf;
}

}  // namespace vkmc
