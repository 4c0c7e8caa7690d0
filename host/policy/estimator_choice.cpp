#include "policy/estimator_choice.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include "estimators/estimator_config.h"

namespace vkmc {

std::vector<SearchStep> estimatorSearchSteps(const std::set<std::string>& pinned, const SearchScene& scene) {
  std::vector<SearchStep> steps;
  auto add = [&](const char* key, std::vector<double> values, bool nextWhereLost = false) {
    if (!pinned.count(key)) steps.push_back({key, std::move(values), nextWhereLost});
  };
  // Roulette first: the per-depth pilot paid most over vkmc's scenes (basement 4.5x, dark_room 3.5x under auto;
  // 1.25-1.8x on several more in docs/estimators.md), and under a budget's share the first challengers are the ones
  // that fit. Then splitting, then MIS, each against the best so far.
  add("rr", {double(RouletteMode::Efficiency)});
  // Four light samples first, two where four lost: a light sample more costs about half what the first did, and
  // where light samples pay, four paid more than two on every scene measured (veach_mis 1.99x against 1.37x at
  // 24 s), while a short budget's share often fits only one of them.
  if (scene.lights && scene.floatAtomics) add("light_samples", {4, 2}, true);
  if (scene.floatAtomics) add("bsdf_samples", {2, 4});
  if (scene.lights && scene.glossy) add("mis", {double(MisHeuristic::Balance)});
  if (scene.emitters) add("light_sampling", {double(LightSampling::SolidAngle)});
  return steps;
}

double expectedPilotCost(const std::string& key, double value, double incumbentValue) {
  const double from = std::max(incumbentValue, 1.0);
  if (key == "light_samples") return (1.0 + 0.5 * (value - 1.0)) / (1.0 + 0.5 * (from - 1.0));
  if (key == "bsdf_samples") return value / from;
  if (key == "rr") return 2.5;
  return 1.2;
}

bool pilotFitsBudget(double pilotSecondsSoFar, double expectedSeconds, double timeBudget) {
  return !(timeBudget > 0.0) || pilotSecondsSoFar + expectedSeconds <= kChoiceMaxShare * timeBudget;
}

namespace {
// Per subset pixel, the mean of `value` over the subset pixels within the window around it (a summed-area table of
// the sparse image).
std::vector<glm::dvec3> windowMeans(const PilotPixels& where, const std::vector<glm::dvec3>& value) {
  const size_t w = where.width, h = where.height;
  std::vector<glm::dvec3> sum((w + 1) * (h + 1), glm::dvec3(0.0));
  std::vector<double> count((w + 1) * (h + 1), 0.0);
  for (size_t i = 0; i < where.index.size(); ++i) {
    const size_t x = where.index[i] % w, y = where.index[i] / w;
    sum[(y + 1) * (w + 1) + x + 1] += value[i], count[(y + 1) * (w + 1) + x + 1] += 1.0;
  }
  for (size_t y = 1; y <= h; ++y)
    for (size_t x = 1; x <= w; ++x) {
      const size_t at = y * (w + 1) + x, up = at - (w + 1);
      sum[at] += sum[at - 1] + sum[up] - sum[up - 1];
      count[at] += count[at - 1] + count[up] - count[up - 1];
    }
  std::vector<glm::dvec3> mean(where.index.size());
  const long r = kChoiceWindowRadius;
  for (size_t i = 0; i < where.index.size(); ++i) {
    const long x = long(where.index[i] % w), y = long(where.index[i] / w);
    const size_t x0 = size_t(std::max(x - r, 0L)), x1 = size_t(std::min(x + r + 1, long(w)));
    const size_t y0 = size_t(std::max(y - r, 0L)), y1 = size_t(std::min(y + r + 1, long(h)));
    auto box = [&](const auto& table) {
      return table[y1 * (w + 1) + x1] - table[y0 * (w + 1) + x1] - table[y1 * (w + 1) + x0] + table[y0 * (w + 1) + x0];
    };
    mean[i] = box(sum) / std::max(box(count), 1.0);
  }
  return mean;
}
}  // namespace

namespace {
// The mean of `x` and its standard error.
std::pair<double, double> meanAndSe(const std::vector<double>& x) {
  const double n = double(std::max<size_t>(x.size(), 1));
  double mean = 0.0, squares = 0.0;
  for (double v : x) mean += v / n;
  for (double v : x) squares += (v - mean) * (v - mean);
  return {mean, x.size() > 1 ? std::sqrt(squares / (n - 1.0) / n) : 0.0};
}

// Each pixel's relative variance a sample: over the value (the others' means, windowed) squared, channels averaged.
std::vector<double> relativeVariances(const std::vector<glm::dvec3>& sampleVariance, const std::vector<glm::dvec3>& value,
                                      double epsilon) {
  std::vector<double> r(value.size(), 0.0);
  for (size_t i = 0; i < value.size() && i < sampleVariance.size(); ++i) {
    const glm::dvec3 rel = sampleVariance[i] / (value[i] * value[i] + epsilon);
    r[i] = (rel.x + rel.y + rel.z) / 3.0;
  }
  return r;
}

// A pilot's reading against the value each of its pixels is relative to.
CandidateReading readingOf(const PilotSamples& pilot, const std::vector<glm::dvec3>& value, double epsilon) {
  CandidateReading r;
  r.pixels = relativeVariances(pilot.sampleVariance, value, epsilon);
  for (double& p : r.pixels) p *= pilot.stageScale;
  r.stageScale = pilot.stageScale;
  std::tie(r.relVariance, r.relVarianceSe) = meanAndSe(r.pixels);
  r.cost = pilot.cost;
  return r;
}

}  // namespace

std::vector<CandidateReading> readCandidates(const PilotPixels& where, const std::vector<PilotSamples>& pilots, double epsilon) {
  std::vector<CandidateReading> readings(pilots.size());
  if (pilots.empty()) return readings;
  const size_t pixels = where.index.size();
  std::vector<glm::dvec3> total(pixels, glm::dvec3(0.0));
  for (const PilotSamples& p : pilots)
    for (size_t i = 0; i < pixels; ++i) total[i] += p.mean[i];
  const double others = double(std::max<size_t>(pilots.size() - 1, 1));
  for (size_t c = 0; c < pilots.size(); ++c) {
    std::vector<glm::dvec3> value(pixels);
    for (size_t i = 0; i < pixels; ++i) value[i] = pilots.size() > 1 ? (total[i] - pilots[c].mean[i]) / others : total[i];
    readings[c] = readingOf(pilots[c], windowMeans(where, value), epsilon);
  }
  return readings;
}

std::vector<glm::dvec3> pooledValues(const PilotPixels& where, const std::vector<PilotSamples>& pilots) {
  std::vector<glm::dvec3> total(where.index.size(), glm::dvec3(0.0));
  for (const PilotSamples& p : pilots)
    for (size_t i = 0; i < total.size(); ++i) total[i] += p.mean[i] / double(pilots.size());
  return windowMeans(where, total);
}

std::vector<CandidateReading> readAgainst(const std::vector<glm::dvec3>& values, const std::vector<PilotSamples>& pilots,
                                          double epsilon) {
  std::vector<CandidateReading> readings;
  for (const PilotSamples& pilot : pilots) readings.push_back(readingOf(pilot, values, epsilon));
  return readings;
}

PilotShape confirmationShape(PilotShape search, double plannedSpp, uint32_t replicates) {
  replicates = std::max(replicates, 1u);
  const double samples = double(search.pixels) * search.spp;
  double spp = std::clamp(std::floor(plannedSpp / kChoiceConfirmationStage / replicates) * replicates, double(search.spp),
                          double(kChoiceMaxConfirmationSpp / replicates * replicates));
  // At least kChoiceMinPilotPixels pixels (as many as the search's where it has fewer).
  const double leastPixels = std::min<double>(kChoiceMinPilotPixels, search.pixels);
  spp = std::max(std::min(spp, std::floor(samples / leastPixels / replicates) * replicates), double(search.spp));
  return PilotShape{uint32_t(std::clamp(std::floor(samples / spp), 1.0, double(search.pixels))), uint32_t(spp)};
}

Comparison compare(const CandidateReading& challenger, const CandidateReading& incumbent) {
  if (challenger.efficiency() <= 0.0 || incumbent.efficiency() <= 0.0) return {};
  // log(E_c / E_i) = log v_i + log c_i - log v_c - log c_c; each pixel's influence on it, v's by the delta method.
  std::vector<double> difference(std::min(challenger.pixels.size(), incumbent.pixels.size()));
  for (size_t p = 0; p < difference.size(); ++p)
    difference[p] = incumbent.pixels[p] / incumbent.relVariance - challenger.pixels[p] / challenger.relVariance;
  const double logRatio = std::log(incumbent.relVariance * incumbent.cost) - std::log(challenger.relVariance * challenger.cost);
  // One pixel has no spread to read: no interval, so no switch on it.
  const double se = difference.size() > 1 ? meanAndSe(difference).second : std::numeric_limits<double>::infinity();
  return {logRatio, se, true};
}

bool beats(const CandidateReading& challenger, const CandidateReading& incumbent) {
  if (challenger.efficiency() <= 0.0) return false;
  if (incumbent.efficiency() <= 0.0) return true;
  const Comparison c = compare(challenger, incumbent);
  return c.logRatio >= std::log(kChoiceMargin) && c.logRatio - 1.645 * c.se > 0.0;
}

bool confirms(const CandidateReading& winner, const CandidateReading& start) {
  const Comparison c = compare(winner, start);
  return c.measured && std::isfinite(c.se) && c.logRatio >= std::log(kChoiceMargin);
}

bool affordableAtSampleCount(const CandidateReading& challenger, const CandidateReading& start) {
  return start.cost <= 0.0 || challenger.cost <= kChoiceMaxCostAtSampleCount * start.cost;
}

uint32_t pilotsPlanned(const std::vector<SearchStep>& steps) {
  uint32_t pilots = 1 + kChoiceConfirmationPilots;
  for (const SearchStep& step : steps) pilots += uint32_t(step.values.size());
  return pilots;
}

bool renderFitsPilots(double plannedPixelSamples, uint32_t candidates) {
  return kChoiceMaxShare * plannedPixelSamples / std::max(candidates, 1u) >= double(kChoiceMinPilotPixels) * kChoiceMinPilotSpp;
}

PilotShape pilotShape(uint32_t pathsPerPass, double plannedPixelSamples, uint32_t candidates, uint32_t imagePixels,
                      uint32_t replicates) {
  double paths = std::min(double(pathsPerPass), kChoiceMaxShare * plannedPixelSamples / std::max(candidates, 1u));
  replicates = std::max(replicates, 1u);
  PilotShape shape;
  const double fill =
      std::ceil(std::max(paths / std::max(imagePixels, 1u), double(kChoiceMinPilotSpp)) / replicates) * replicates;
  shape.spp = uint32_t(std::clamp(fill, double(replicates), double(kChoiceMaxPilotSpp / replicates * replicates)));
  shape.pixels = uint32_t(std::clamp(std::floor(paths / shape.spp), 1.0, double(imagePixels)));
  return shape;
}

uint32_t probePixels(PilotShape search) {
  return std::min(search.pixels, std::max(search.pixels / kChoiceProbeFraction, kChoiceMinPilotPixels));
}

uint32_t pilotPixelsInShare(PilotShape search, double shareSeconds, double secondsPerPixel) {
  const uint32_t least = std::min(search.pixels, kChoiceMinPilotPixels);
  if (!(shareSeconds > 0.0) || !(secondsPerPixel > 0.0)) return search.pixels;
  const double fit = std::floor(shareSeconds / (kChoicePilotsInShare * secondsPerPixel));
  return uint32_t(std::clamp(fit, double(least), double(search.pixels)));
}

double stageScale(double qmcGain, double pilotSamplesPerReplicate, double renderSamplesPerReplicate) {
  const double np = pilotSamplesPerReplicate, nr = renderSamplesPerReplicate;
  if (!(qmcGain > 0.0 && qmcGain < 1.0) || !(np > 1.0) || !(nr > np)) return 1.0;
  return std::max(std::pow(qmcGain, std::log(nr / np) / std::log(np)), kChoiceMinStageScale);
}

}  // namespace vkmc
