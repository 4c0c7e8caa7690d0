// --estimator auto's decisions, as pure functions: which keys it searches and in what order, how big a pilot is,
// what a candidate's pilot measured (a sample's relative variance and cost over a subset of pixels), and whether a
// candidate beats the one it would replace. The pilots themselves run in app/estimator_search.cpp.
//
// The search is coordinate-wise, not a grid: the start configuration (the defaults, with every key the user gave
// pinned), then each unpinned key's alternatives with the best so far; a key's winner stays for the keys after it.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace vkmc {

// One key's alternatives to whatever value the best configuration so far has (estimator_params.cpp's values), in
// order: a value is measured only where the one before it won (4 BSDF continuations only after 2 beat 1), or,
// with nextWhereLost, only where it lost or did not fit a budget's share (2 light samples only where 4 did not win).
struct SearchStep {
  std::string key;
  std::vector<double> values;
  bool nextWhereLost = false;
};

// What the scene and the device can use, so the search skips keys that change nothing or cannot run there.
struct SearchScene {
  bool lights = true;        // next-event estimation has something to sample (light_samples, mis)
  bool floatAtomics = true;  // the device adds split paths' and extra light samples' contributions
  bool glossy = true;        // a lobe other than Lambertian: where BSDF sampling finds lights as light sampling does
  bool emitters = true;      // emissive triangles: what light_sampling solid-angle changes
};

// The keys searched, in order: rr efficiency (the per-depth pilot), light_samples {4, 2}, bsdf_samples {2, 4},
// mis balance, light_sampling solid-angle; keys in `pinned` (the user's flags) are left out, splitting where the
// device has no float atomics, light_sampling where no triangle emits, and mis where no lobe is glossy (on Lambertian surfaces a
// BSDF sample's pdf is far below a light sample's wherever the light is small, so both heuristics give nearly the same weights:
// on the Cornell box balance read 0.75x the start, measured at the cost of a pilot).
std::vector<SearchStep> estimatorSearchSteps(const std::set<std::string>& pinned, const SearchScene& scene);

// What a candidate's pilot is expected to cost against the incumbent's (the best so far, which differs from it in
// `key` alone, where it has incumbentValue), before it runs (a budget's check): a light sample or BSDF continuation
// more costs about what the first did, rr efficiency runs a pilot of its own first (and an incumbent with it runs
// one too, so its seconds hold that). From the Cornell box at 192x192 (pilot seconds against the start's:
// light_samples 2 1.46x, bsdf_samples 2 1.87x, mis balance 1.18x, rr efficiency 2.41x), rounded up.
double expectedPilotCost(const std::string& key, double value, double incumbentValue);

// A candidate's pilot over the subset's pixels (`PilotPixels`, the same for every candidate): each pixel's mean and
// one sample's variance, per channel, and the cost of one sample.
struct PilotSamples {
  std::vector<glm::dvec3> mean, sampleVariance;
  double cost = 0.0;
  double stageScale = 1.0;  // what a sample's variance becomes at the render's stage of convergence (stageScale())
};

// A sample's variance at the render's stage of convergence, from the pilot's. Under a QMC sampler a pixel's n samples
// of one scrambling have variance g(n) sigma^2 / n, where sigma^2 is one sample's and g(n) <= 1 the sampler's gain;
// the pilot reads g at its n (qmcGain: the replicates' variance of the mean over the samples' own, as if
// independent, summed over its pixels relative as relMSE weighs them). Modelling g(n) = n^-gamma (Owen-scrambled
// Sobol's variance falls as a power of n), a sample's variance at the render's n_r is the pilot's times
// g(n_r) / g(n_p) = qmcGain^(ln(n_r / n_p) / ln n_p). One light sample gains most from the sampler and splitting least,
// so a pilot at 64 samples a pixel reads splitting better than the render at 2,000 finds it: on soft_shadows four
// light samples read 1.2-1.44x the defaults on pilots of 64 and 128 and rendered at 0.886x. 1 where the pilot shows
// no gain (qmcGain >= 1: the independent sampler, or noise) or the render is no further on; at least
// kChoiceMinStageScale (an extrapolation, not a measurement).
inline constexpr double kChoiceMinStageScale = 0.1;
double stageScale(double qmcGain, double pilotSamplesPerReplicate, double renderSamplesPerReplicate);

// Where the subset's pixels lie in the image.
struct PilotPixels {
  uint32_t width = 0, height = 0;
  std::vector<uint32_t> index;  // y * width + x, one per subset pixel
};

// What the choice compares: the mean over the subset of a sample's variance relative to the pixel's value (as in
// relMSE: over value^2 + epsilon), its standard error over pixels, and the efficiency 1 / (relVariance x cost).
// The value a candidate's variance is relative to comes from the other candidates (all unbiased for it) over a
// window of kChoiceWindowRadius pixels around: a pilot has two samples a pixel, and a value from the candidate's
// own samples would shrink its relative variance where a rare bright sample raises both, while one pixel's
// others alone read 0 too often where the value is not.
struct CandidateReading {
  double relVariance = 0.0, relVarianceSe = 0.0, cost = 0.0;
  double stageScale = 1.0;     // the pilot's: its variances are read at the render's stage (stageScale())
  std::vector<double> pixels;  // each subset pixel's relative variance a sample (what compare pairs)
  double efficiency() const { return relVariance > 0.0 && cost > 0.0 ? 1.0 / (relVariance * cost) : 0.0; }
  // The efficiency's relative standard error (the cost counted exact: a pass's GPU time).
  double relativeSe() const { return relVariance > 0.0 ? relVarianceSe / relVariance : 0.0; }
};

// Every candidate's reading against the means pooled over all of them.
inline constexpr int kChoiceWindowRadius = 2;
std::vector<CandidateReading> readCandidates(const PilotPixels& where, const std::vector<PilotSamples>& pilots, double epsilon);

// The confirmation's readings (see confirmationShape): each pixel's value from every search pilot (none of them the
// confirmation's own samples), windowed over the search's denser subset, so a value stays independent of the
// candidates it divides; `values` holds the first pixels of the search's subset.
std::vector<glm::dvec3> pooledValues(const PilotPixels& where, const std::vector<PilotSamples>& pilots);
std::vector<CandidateReading> readAgainst(const std::vector<glm::dvec3>& values, const std::vector<PilotSamples>& pilots,
                                          double epsilon);

// A challenger against the incumbent: the log of their efficiencies' ratio and its standard error, paired pixel by
// pixel (the delta method over the same pixels: a hard pixel is hard for both, and the spread of pixels'
// difficulty cancels).
struct Comparison {
  double logRatio = 0.0, se = 0.0;
  bool measured = false;  // both have a reading
};
Comparison compare(const CandidateReading& challenger, const CandidateReading& incumbent);

// A challenger replaces the incumbent where it measures at least kChoiceMargin times as efficient and the one-sided
// 95% bound of the (paired) ratio is above 1: a pilot is short, and a switch on noise costs more than staying.
inline constexpr double kChoiceMargin = 1.05;
bool beats(const CandidateReading& challenger, const CandidateReading& incumbent);

// The confirmation's rule: the winner's fresh reading at least kChoiceMargin times the start's. One comparison, not
// the best of several, so its point estimate is free of the winner's curse (not of every bias: a heavy tail's
// variance reads low more often than high), and switching where it reads ahead is what maximises the expected
// efficiency; the search's 95% bound guards against switching on noise among many. With the bound here too,
// veach_mis's heavy-tailed readings (a fresh ratio of 1.42x, 0.73-2.75) kept the defaults at 0.97x.
bool confirms(const CandidateReading& winner, const CandidateReading& start);

// Where a sample count ends the render (no time budget or target error), a challenger is chosen only where its sample
// costs at most kChoiceMaxCostAtSampleCount times the start's: the efficiency it wins is lower error for more time,
// and the user asked for samples, not for a render many times as long. On the albedo-0.99 furnace the per-depth
// roulette pilot read 1.1x the start's efficiency at 22x its cost a sample (paths of a thousand vertices), and a
// 10-s render of 256 samples took 67 s. Under a budget or a target error, efficiency alone decides.
inline constexpr double kChoiceMaxCostAtSampleCount = 4.0;
bool affordableAtSampleCount(const CandidateReading& challenger, const CandidateReading& start);

// rr efficiency's pilot is rendered only where the table its roulette pilot learnt predicts more than this much of
// the throughput rule's efficiency (RouletteTable::gainOverThroughput, a model of the pilot's paths): where paths
// rarely reach the roulette depth, or the table loses to the rule, its pilot pass would take a short budget's share
// from the keys after it (on veach_mis at 24 s the start and that pass left no room for light_samples, which pays 2x
// there; its table predicts 1.0). Only where the table predicts essentially nothing: the prediction reads the
// paths it was fitted to, and misses heavy tails both ways (glossy_room predicts 3.4 and measures 0.87x at equal
// time, many_lights predicts 1.03 and measures 1.36x).
inline constexpr double kChoiceMinRoulettePrediction = 1.02;

// Under a time budget the pilots take at most kChoiceMaxShare of it (what the issue that asked for auto allowed):
// a challenger is measured only where the pilots' seconds so far and its expected seconds fit.
bool pilotFitsBudget(double pilotSecondsSoFar, double expectedSeconds, double timeBudget);

// A pilot's size: a pass of the render's (a pilot's cost per sample is read from its GPU time, and on lavapipe a
// pass of fewer paths costs less per path for the splitting candidates than the render's full passes will: at half a
// pass two BSDF continuations measured 1.68x the start's cost where the render took 2.25x), at most kChoiceMaxShare
// of the render's planned pixel-samples over the candidates. Its samples a pixel: as few as fill it over the image, a
// multiple of the replicates, at least kChoiceMinPilotSpp, at most kChoiceMaxPilotSpp; its pixels: what that leaves.
// Many samples on few pixels rather than few on many: under Owen-scrambled Sobol a pixel's samples stratify, and
// the estimators that gain most from it (one light sample) are read at a later stage of their convergence, nearer
// the render's. At 16 a pixel the pilots read 4 light samples 1.32x the start on soft_shadows (a sample's relative
// variance 0.033 against 0.075), and the render then lost (0.86x: 0.85x the variance a sample, not 0.43x); at 64
// the start reads 0.047 and 2 light samples 0.95x, so the defaults render.
inline constexpr double kChoiceMaxShare = 0.05;
inline constexpr uint32_t kChoiceNominalSpp = 256;  // what a render with no sample count or budget plans for
inline constexpr uint32_t kChoiceMinPilotSpp = 64;
inline constexpr uint32_t kChoiceMaxPilotSpp = 64;
// The most pilots a search runs: the start, every value of every step, and the confirmation's two (the winner and
// the start again, on fresh samples: the search's readings chose the winner from several comparisons, and so read
// its lead high). The share of the samples holds them all.
inline constexpr uint32_t kChoiceConfirmationPilots = 2;
uint32_t pilotsPlanned(const std::vector<SearchStep>& steps);
// Whether a render of plannedPixelSamples leaves its pilots at least kChoiceMinPilotPixels pixels each (at
// kChoiceMinPilotSpp) within kChoiceMaxShare: a smaller one is too short to choose in.
inline constexpr uint32_t kChoiceMinPilotPixels = 256;
// Under a time budget, the default chooses only from this many seconds: 5% of less holds the start's pilot and its
// kernels (about 0.25 s on the Cornell box) and little else.
inline constexpr double kChoiceMinBudgetSeconds = 10.0;
bool renderFitsPilots(double plannedPixelSamples, uint32_t candidates);

struct PilotShape {
  uint32_t pixels = 0, spp = 0;
};
PilotShape pilotShape(uint32_t pathsPerPass, double plannedPixelSamples, uint32_t candidates, uint32_t imagePixels,
                      uint32_t replicates);

// Under a time budget, a pass of the render's size is most of the share on a short render (at 24 s and 128x128 the
// start's pass took 0.64 s of the furnace's 1.2 s, and its roulette pilot, 26.9x there, never fitted). So the
// search's pilots cover a prefix of the pass's pixels: as many as kChoicePilotsInShare pilots of the start's pace fit
// into the share (a typical search: the start 1, rr efficiency 2.5 with its table's pilot, four light samples 2.5,
// MIS 1.2, light sampling 1.2, the confirmation 3.5), at least kChoiceMinPilotPixels. The start's pace comes from a
// probe: its pilot's first pixels (1/kChoiceProbeFraction of the pass), extended once the pace is known.
inline constexpr double kChoicePilotsInShare = 12.0;
inline constexpr uint32_t kChoiceProbeFraction = 8;
uint32_t probePixels(PilotShape search);
uint32_t pilotPixelsInShare(PilotShape search, double shareSeconds, double secondsPerPixel);
// A candidate that splits paths runs its pilot on the whole pass all the same: its cost a path grows with the pass
// (its path pool outgrows the caches; four BSDF continuations on many_lights read 2.1x the start's cost at 28,672
// paths and 2.8x at 258,048), so only a pass of the render's size reads the cost it will render at. It is compared
// with the others on their common prefix.
// rr efficiency's own pilot (its table) renders kChoiceRoulettePilotPixels times the search's pixels at its few
// samples each (4): a quarter of a search pilot's paths, the whole image at 128x128.
inline constexpr uint32_t kChoiceRoulettePilotPixels = 4;

// The confirmation's pilots read the winner and the start nearer the render's stage of convergence: at most as many
// samples as a search pilot, on fewer of its pixels at more samples each (a quarter of the render's planned samples a pixel,
// at most kChoiceMaxConfirmationSpp, at least the search's, a multiple of the replicates, over at least
// kChoiceMinPilotPixels pixels). Under Owen-scrambled Sobol one light sample stratifies more with every sample and
// two gain less from it: on soft_shadows the search's 64 a pixel read two light samples 1.13-1.23x the defaults,
// 256 read 0.87-0.95x, and the render of 2,000 found 0.9x. 128, not 256: at half the pixels veach_mis's
// heavy-tailed readings were too wide to keep its gain (docs/journal/estimator-auto.md).
inline constexpr double kChoiceConfirmationStage = 4.0;
inline constexpr uint32_t kChoiceMaxConfirmationSpp = 128;
PilotShape confirmationShape(PilotShape search, double plannedSpp, uint32_t replicates);

}  // namespace vkmc
