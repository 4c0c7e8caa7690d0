// --estimator auto's decisions without a GPU (policy/estimator_choice.h): which keys it searches, how big a pilot
// is, what a candidate's reading is relative to, and when a challenger wins.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "estimators/estimator_config.h"
#include "policy/estimator_choice.h"

using namespace vkmc;

namespace {
bool hasKey(const std::vector<SearchStep>& steps, const std::string& key) {
  for (const SearchStep& s : steps)
    if (s.key == key) return true;
  return false;
}

// A pilot over a w x h subset (every pixel of it) whose samples have the given mean and variance everywhere.
PilotSamples flatPilot(size_t pixels, double mean, double variance, double cost) {
  PilotSamples p;
  p.mean.assign(pixels, glm::dvec3(mean));
  p.sampleVariance.assign(pixels, glm::dvec3(variance));
  p.cost = cost;
  return p;
}

PilotPixels allPixels(uint32_t w, uint32_t h) {
  PilotPixels where{w, h, {}};
  for (uint32_t i = 0; i < w * h; ++i) where.index.push_back(i);
  return where;
}
}  // namespace

TEST(EstimatorChoice, SearchesTheKeysTheUserLeftAndTheSceneCanUse) {
  const std::vector<SearchStep> all = estimatorSearchSteps({}, SearchScene{true, true});
  for (const char* key : {"light_samples", "bsdf_samples", "mis", "rr", "light_sampling"}) EXPECT_TRUE(hasKey(all, key)) << key;
  // Roulette first: it paid most, and under a budget's share the first challengers are the ones that fit.
  EXPECT_EQ(all.front().key, "rr");
  // Four light samples first, two only where four lost; two BSDF continuations first, four only where two won.
  for (const SearchStep& s : all) {
    if (s.key == "light_samples") {
      EXPECT_EQ(s.values, (std::vector<double>{4, 2}));
      EXPECT_TRUE(s.nextWhereLost);
    }
    if (s.key == "bsdf_samples") {
      EXPECT_EQ(s.values, (std::vector<double>{2, 4}));
      EXPECT_FALSE(s.nextWhereLost);
    }
  }
  const std::vector<SearchStep> pinned = estimatorSearchSteps({"light_samples", "rr"}, SearchScene{true, true});
  EXPECT_FALSE(hasKey(pinned, "light_samples"));
  EXPECT_FALSE(hasKey(pinned, "rr"));
  EXPECT_TRUE(hasKey(pinned, "bsdf_samples"));
  // Without lights next-event estimation has nothing to sample, so its keys change nothing.
  const std::vector<SearchStep> dark = estimatorSearchSteps({}, SearchScene{false, true});
  EXPECT_FALSE(hasKey(dark, "light_samples"));
  EXPECT_FALSE(hasKey(dark, "mis"));
  EXPECT_TRUE(hasKey(dark, "bsdf_samples"));
  // Splitting adds its contributions with float atomics: a device without them is not offered it.
  const std::vector<SearchStep> noAtomics = estimatorSearchSteps({}, SearchScene{true, false});
  EXPECT_FALSE(hasKey(noAtomics, "light_samples"));
  EXPECT_FALSE(hasKey(noAtomics, "bsdf_samples"));
  EXPECT_TRUE(hasKey(noAtomics, "mis"));
  // On Lambertian surfaces alone the MIS heuristics weigh nearly alike: mis is not searched.
  const std::vector<SearchStep> matte = estimatorSearchSteps({}, SearchScene{true, true, false});
  EXPECT_FALSE(hasKey(matte, "mis"));
  EXPECT_TRUE(hasKey(matte, "light_samples"));
  // Solid-angle sampling changes only how a point of an emissive triangle is drawn: not offered for punctual lights
  // or an environment alone.
  const std::vector<SearchStep> punctual = estimatorSearchSteps({}, SearchScene{true, true, true, false});
  EXPECT_FALSE(hasKey(punctual, "light_sampling"));
  EXPECT_TRUE(hasKey(punctual, "light_samples"));
}

TEST(EstimatorChoice, UnderABudgetThePilotsFitItsShare) {
  // A 30-s budget leaves the pilots 1.5 s: with 1 s spent, a pilot expected at 0.4 s fits and one at 0.6 s not.
  EXPECT_TRUE(pilotFitsBudget(1.0, 0.4, 30.0));
  EXPECT_FALSE(pilotFitsBudget(1.0, 0.6, 30.0));
  EXPECT_TRUE(pilotFitsBudget(1e9, 1e9, 0.0));  // no budget: the samples' share bounds the pilots (pilotShape)
  // A continuation or a light sample more costs about what the first did; rr efficiency runs its own pilot first.
  // Against the incumbent, which may have taken the key's smaller value already.
  EXPECT_DOUBLE_EQ(expectedPilotCost("bsdf_samples", 4, 1), 4.0);
  EXPECT_DOUBLE_EQ(expectedPilotCost("bsdf_samples", 4, 2), 2.0);
  EXPECT_DOUBLE_EQ(expectedPilotCost("light_samples", 2, 1), 1.5);
  EXPECT_GT(expectedPilotCost("rr", 3, 0), expectedPilotCost("mis", 1, 0));
}

// The search's pixels from the start's probe: as many as kChoicePilotsInShare pilots of its pace fit into the share.
TEST(EstimatorChoice, UnderABudgetThePilotsCoverAsManyPixelsAsTheShareFits) {
  const PilotShape pass{4096, 64};
  EXPECT_EQ(probePixels(pass), 4096u / kChoiceProbeFraction);  // the probe: an eighth of the pass
  EXPECT_EQ(probePixels(PilotShape{300, 64}), 256u);           // at least kChoiceMinPilotPixels
  EXPECT_EQ(probePixels(PilotShape{100, 64}), 100u);           // never past the pass
  // The furnace at 24 s: a pixel's 64 samples took 0.64 s / 4096 pixels; 1.2 s fits 12 pilots of 640 pixels.
  const double perPixel = 0.64 / 4096;
  EXPECT_EQ(pilotPixelsInShare(pass, 1.2, perPixel), uint32_t(std::floor(1.2 / (kChoicePilotsInShare * perPixel))));
  EXPECT_LT(pilotPixelsInShare(pass, 1.2, perPixel), 4096u);
  EXPECT_EQ(pilotPixelsInShare(pass, 120.0, perPixel), 4096u);                 // a long budget: the whole pass
  EXPECT_EQ(pilotPixelsInShare(pass, 1e-3, perPixel), kChoiceMinPilotPixels);  // never under the least a pilot reads
  EXPECT_EQ(pilotPixelsInShare(PilotShape{100, 64}, 1e-3, perPixel), 100u);
  EXPECT_EQ(pilotPixelsInShare(pass, 0.0, perPixel), 4096u);  // no budget: the samples' share sized the pass already
}

// A pilot's variance read at the render's stage of convergence: g(n) = n^-gamma through the pilot's gain.
TEST(EstimatorChoice, ReadsAVarianceAtTheRendersStageOfConvergence) {
  // A gain of 1/4 at 32 samples a scrambling is gamma = 0.4; at 1,024 the gain is 1/16: a quarter of the pilot's.
  EXPECT_NEAR(stageScale(0.25, 32.0, 1024.0), 0.25, 1e-12);
  EXPECT_NEAR(stageScale(0.5, 32.0, 32.0 * 32.0), 0.5, 1e-12);
  // Where a candidate gains less from the sampler its variance falls less: their ratio moves towards the one that
  // gains more, which is what the render finds.
  EXPECT_LT(stageScale(0.3, 32.0, 1000.0), stageScale(0.7, 32.0, 1000.0));
  EXPECT_EQ(stageScale(1.0, 32.0, 1000.0), 1.0);                 // independent samples: no gain to extrapolate
  EXPECT_EQ(stageScale(1.3, 32.0, 1000.0), 1.0);                 // noise above 1 is read as none
  EXPECT_EQ(stageScale(0.5, 32.0, 16.0), 1.0);                   // a render no further on than the pilot
  EXPECT_EQ(stageScale(0.5, 1.0, 1000.0), 1.0);                  // one sample a scrambling has no gain to read
  EXPECT_EQ(stageScale(1e-6, 32.0, 1e6), kChoiceMinStageScale);  // an extrapolation, bounded
  // The reading carries it: a candidate's relative variance a sample is its pilot's times the scale.
  PilotSamples p;
  p.mean.assign(4, glm::dvec3(1.0)), p.sampleVariance.assign(4, glm::dvec3(2.0)), p.cost = 1.0, p.stageScale = 0.25;
  const std::vector<CandidateReading> r = readAgainst(std::vector<glm::dvec3>(4, glm::dvec3(1.0)), {p}, 0.0);
  EXPECT_NEAR(r[0].relVariance, 0.5, 1e-12);
  EXPECT_EQ(r[0].stageScale, 0.25);
}

TEST(EstimatorChoice, ReadsEfficiencyAsInverseRelativeVarianceTimesCost) {
  const PilotPixels where = allPixels(16, 16);
  // B: a quarter of A's variance at twice its cost, so twice as efficient; C: A's variance at A's cost.
  const std::vector<CandidateReading> r =
      readCandidates(where, {flatPilot(256, 0.5, 1.0, 1.0), flatPilot(256, 0.5, 0.25, 2.0), flatPilot(256, 0.5, 1.0, 1.0)}, 1e-2);
  EXPECT_NEAR(r[0].relVariance, 1.0 / (0.25 + 1e-2), 1e-9);
  EXPECT_NEAR(r[1].efficiency() / r[0].efficiency(), 2.0, 1e-9);
  EXPECT_NEAR(r[2].efficiency(), r[0].efficiency(), 1e-12);
  EXPECT_LT(r[0].relVarianceSe, 1e-12);  // every pixel alike: no spread
}

// A rare bright sample raises a pixel's variance and its own mean together: read against its own mean, the
// candidate's relative variance would shrink (two samples x and 0: V / m^2 = 2 however large x). It is read
// against the other candidates' value instead, around the pixel.
TEST(EstimatorChoice, ReadsEachCandidateAgainstTheOthersValue) {
  const PilotPixels where = allPixels(8, 8);
  PilotSamples firefly = flatPilot(64, 0.5, 0.1, 1.0);
  firefly.mean[27] = glm::dvec3(50.0);  // one pixel's samples were x = 100 and 0
  firefly.sampleVariance[27] = glm::dvec3(5000.0);
  const std::vector<CandidateReading> r = readCandidates(where, {firefly, flatPilot(64, 0.5, 0.1, 1.0)}, 1e-2);
  // Against the others' 0.5 the firefly pixel alone adds 5000 / 0.26 / 64 = 300.
  EXPECT_GT(r[0].relVariance, 250.0);
  EXPECT_LT(r[1].relVariance, 1.0);
  EXPECT_GT(r[0].relVarianceSe, 0.1 * r[0].relVariance);
}

// The window: where another candidate reads 0 on one pixel only by chance, its neighbours give the value.
TEST(EstimatorChoice, TheValueComesFromAWindowOfPixels) {
  const PilotPixels where = allPixels(8, 8);
  PilotSamples other = flatPilot(64, 1.0, 0.0, 1.0);
  other.mean[36] = glm::dvec3(0.0);
  const std::vector<CandidateReading> r = readCandidates(where, {flatPilot(64, 1.0, 1.0, 1.0), other}, 1e-2);
  // The 25 pixels whose 5x5 window holds pixel 36 read a value of 0.96 or so; without the window pixel 36 alone
  // would read 1 / 0.01 and add 100 / 64 to the mean.
  EXPECT_GT(r[0].relVariance, 1.0 / (1.0 + 1e-2));
  EXPECT_LT(r[0].relVariance, 1.1);
}

// Two candidates' readings over the same pixels: the incumbent's and the challenger's pilots.
std::pair<CandidateReading, CandidateReading> readPair(const PilotSamples& incumbent, const PilotSamples& challenger) {
  const std::vector<CandidateReading> r =
      readCandidates(allPixels(uint32_t(incumbent.mean.size()), 1), {incumbent, challenger}, 0.0);
  return {r[0], r[1]};
}

TEST(EstimatorChoice, AChallengerWinsByTheMarginAndBeyondItsNoise) {
  const PilotSamples incumbent = flatPilot(16, 1.0, 1.0, 1.0);
  auto beatsIt = [&](const PilotSamples& challenger) {
    const auto [i, c] = readPair(incumbent, challenger);
    return beats(c, i);
  };
  EXPECT_FALSE(beatsIt(flatPilot(16, 1.0, 1.0 / 1.04, 1.0)));  // 4% better: within the margin
  EXPECT_TRUE(beatsIt(flatPilot(16, 1.0, 1.0 / 1.5, 1.0)));    // 50% better, on every pixel alike
  PilotSamples lucky = flatPilot(16, 1.0, 0.0, 1.0);           // 50% better on average, all of it one pixel's
  lucky.sampleVariance[5] = glm::dvec3(16.0 / 1.5);
  EXPECT_FALSE(beatsIt(lucky));
  EXPECT_FALSE(beatsIt(flatPilot(16, 1.0, 1.0, 1.0)));  // the same
  const auto [nothing, measured] = readPair(flatPilot(16, 1.0, 0.0, 1.0), flatPilot(16, 1.0, 0.5, 1.0));
  EXPECT_TRUE(beats(measured, nothing));  // anything measured beats nothing measured
  EXPECT_FALSE(beats(nothing, measured));
}

// Under a sample count a challenger may cost at most kChoiceMaxCostAtSampleCount times the start a sample, however
// efficient: the furnace's per-depth pilot read 1.1x at 22x the cost, and its 256-sample render took 6x as long.
TEST(EstimatorChoice, ASampleCountAffordsAFewTimesTheStartsCost) {
  const PilotSamples start = flatPilot(16, 1.0, 1.0, 1.0);
  const auto [s, cheap] = readPair(start, flatPilot(16, 1.0, 0.25, kChoiceMaxCostAtSampleCount));
  EXPECT_TRUE(affordableAtSampleCount(cheap, s));
  const auto [s2, costly] = readPair(start, flatPilot(16, 1.0, 0.04, 22.0));
  EXPECT_TRUE(beats(costly, s2));  // more efficient: under a budget it would render
  EXPECT_FALSE(affordableAtSampleCount(costly, s2));
}

// The same pixels for every candidate: a pixel that is hard for one is hard for the other, and the comparison's
// noise is what differs between them, not how much pixels differ.
TEST(EstimatorChoice, PairedPixelsCancelTheirDifficulty) {
  PilotSamples incumbent = flatPilot(64, 1.0, 1.0, 1.0), challenger = flatPilot(64, 1.0, 1.0, 1.0);
  std::mt19937 rng(5);
  std::lognormal_distribution<double> difficulty(0.0, 1.5);
  for (size_t i = 0; i < 64; ++i) {
    const double d = difficulty(rng);
    incumbent.sampleVariance[i] = glm::dvec3(d), challenger.sampleVariance[i] = glm::dvec3(d / 1.2);
  }
  const auto [i, c] = readPair(incumbent, challenger);
  EXPECT_GT(c.relativeSe(), 0.15);  // each on its own is uncertain by the pixels' spread
  const Comparison paired = compare(c, i);
  EXPECT_NEAR(std::exp(paired.logRatio), 1.2, 1e-9);
  EXPECT_LT(paired.se, 1e-9);
  EXPECT_TRUE(beats(c, i));
}

TEST(EstimatorChoice, APilotFillsAPassAndStaysAShareOfTheRender) {
  // 192 x 192 under a long budget: a pass of 2^18 paths at 64 samples a pixel (the fewest a pilot takes; a
  // multiple of the 2 replicates), over 4096 pixels.
  PilotShape s = pilotShape(1u << 18, 1e12, 8, 192 * 192, 2);
  EXPECT_EQ(s.spp, kChoiceMinPilotSpp);
  EXPECT_EQ(s.pixels, (1u << 18) / kChoiceMinPilotSpp);
  // A large image: still 64 a pixel, over fewer of its pixels.
  s = pilotShape(1u << 18, 1e12, 8, 1920 * 1080, 2);
  EXPECT_EQ(uint64_t(s.pixels) * s.spp, 1u << 18);
  // A small render: the pilots, the confirmation's two among them, stay within kChoiceMaxShare of its pixel-samples.
  // The start, every value of every step (two light sample counts, two BSDF counts, balance MIS), the winner and
  // the start again.
  const uint32_t pilots = pilotsPlanned({{"light_samples", {2, 4}}, {"bsdf_samples", {2, 4}}, {"mis", {1}}});
  EXPECT_EQ(pilots, 8u);
  s = pilotShape(1u << 18, 128.0 * 128 * 256, pilots, 128 * 128, 2);
  EXPECT_LE(double(pilots) * s.pixels * s.spp, kChoiceMaxShare * 128 * 128 * 256);
  EXPECT_EQ(s.spp % 2, 0u);
  // Three replicates: a multiple of 3.
  s = pilotShape(1u << 18, 1e12, 8, 192 * 192, 3);
  EXPECT_EQ(s.spp % 3, 0u);
  // A tiny render: one pixel at least; never past the image or the batch.
  s = pilotShape(1u << 18, 64.0, 8, 16, 4);
  EXPECT_GE(s.pixels, 1u);
  s = pilotShape(1u << 18, 1e12, 8, 64, 2);
  EXPECT_LE(s.pixels, 64u);
  EXPECT_LE(s.spp, kChoiceMaxPilotSpp);
}

// The confirmation's pilots: a search pilot's samples on fewer pixels at more each, nearer the render's stage of
// convergence (a quarter of its planned samples a pixel, at most 128), at least 256 pixels.
TEST(EstimatorChoice, TheConfirmationReadsNearerTheRendersStage) {
  const PilotShape search{4096, 64};
  PilotShape c = confirmationShape(search, 2200.0, 2);  // soft_shadows' 24 s at 128 x 128
  EXPECT_EQ(c.spp, kChoiceMaxConfirmationSpp);
  EXPECT_EQ(c.pixels, 4096u * 64u / kChoiceMaxConfirmationSpp);
  c = confirmationShape(search, 256.0, 2);  // a render of 256 samples a pixel: the search's own stage
  EXPECT_EQ(c.spp, 64u);
  EXPECT_EQ(c.pixels, 4096u);
  c = confirmationShape({4096, 63}, 400.0, 3);  // three replicates (the search's 63): a multiple of 3
  EXPECT_EQ(c.spp, 99u);
  EXPECT_LE(uint64_t(c.pixels) * c.spp, 4096u * 63u);
  // Over a range of shapes and plans: never more pixels or samples than the search's, never fewer samples a pixel.
  for (uint32_t pixels : {1u, 100u, 256u, 1000u, 4096u})
    for (double planned : {1.0, 64.0, 300.0, 2200.0, 1e6})
      for (uint32_t replicates : {1u, 2u, 3u, 4u}) {
        const PilotShape from{pixels, 64 / replicates * replicates};
        const PilotShape to = confirmationShape(from, planned, replicates);
        EXPECT_LE(to.pixels, from.pixels);
        EXPECT_LE(uint64_t(to.pixels) * to.spp, uint64_t(from.pixels) * from.spp);
        EXPECT_GE(to.spp, from.spp);
        EXPECT_EQ(to.spp % replicates, 0u);
      }
  c = confirmationShape({512, 64}, 5000.0, 2);  // few pixels: kept at kChoiceMinPilotPixels
  EXPECT_EQ(c.pixels, kChoiceMinPilotPixels);
  EXPECT_EQ(c.spp, 128u);
  c = confirmationShape({100, 64}, 5000.0, 2);  // fewer still: the search's shape
  EXPECT_EQ(c.pixels, 100u);
  EXPECT_EQ(c.spp, 64u);
}

// The confirmation reads both pilots against values from elsewhere (the search's pilots), not against each other,
// and confirms on its point estimate: a fresh ratio of at least kChoiceMargin, however wide its interval.
TEST(EstimatorChoice, TheConfirmationReadsAgainstGivenValues) {
  PilotSamples a, b;
  a.mean = {glm::dvec3(100.0), glm::dvec3(100.0)}, b.mean = a.mean;  // their own means do not enter
  a.sampleVariance = {glm::dvec3(4.0), glm::dvec3(16.0)}, b.sampleVariance = {glm::dvec3(1.0), glm::dvec3(1.0)};
  a.cost = b.cost = 1.0;
  const std::vector<CandidateReading> r = readAgainst({glm::dvec3(2.0), glm::dvec3(2.0)}, {a, b}, 0.0);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_DOUBLE_EQ(r[0].relVariance, (1.0 + 4.0) / 2.0);
  EXPECT_DOUBLE_EQ(r[1].relVariance, 0.25);
  EXPECT_TRUE(beats(r[1], r[0]));
  EXPECT_TRUE(confirms(r[1], r[0]));
  EXPECT_FALSE(confirms(r[0], r[1]));
  // The values pooled over the search's pilots: their mean, windowed.
  const PilotPixels where{8, 1, {0, 1, 7}};  // pixels 0 and 1 share a window; 7 is alone in its
  PilotSamples c = a, d = a;
  c.mean = {glm::dvec3(2.0), glm::dvec3(4.0), glm::dvec3(10.0)};
  d.mean = {glm::dvec3(6.0), glm::dvec3(8.0), glm::dvec3(20.0)};
  const std::vector<glm::dvec3> v = pooledValues(where, {c, d});
  EXPECT_DOUBLE_EQ(v[0].x, 5.0);  // (2 + 6) / 2 and (4 + 8) / 2, windowed together
  EXPECT_DOUBLE_EQ(v[1].x, 5.0);
  EXPECT_DOUBLE_EQ(v[2].x, 15.0);  // (10 + 20) / 2, alone
}

TEST(EstimatorChoice, TheConfirmationHoldsOnItsPointEstimate) {
  CandidateReading start, winner;
  start.relVariance = winner.relVariance = 1.0, start.cost = 1.0;
  start.pixels = {1.0, 1.0, 1.0, 1.0}, winner.pixels = {0.1, 1.9, 0.1, 1.9};  // noisy: its interval spans 1
  winner.cost = 1.0 / 1.2;                                                    // 1.2x as efficient
  EXPECT_FALSE(beats(winner, start)) << "the search's test asks its bound too";
  EXPECT_TRUE(confirms(winner, start));
  winner.cost = 1.0 / 1.04;  // under the margin
  EXPECT_FALSE(confirms(winner, start));
}
