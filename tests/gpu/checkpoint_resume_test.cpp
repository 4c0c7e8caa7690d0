// A resumed render equals the uninterrupted one bit for bit (app/render_job.h RunControl, render/render_state.h):
// every render here writes a checkpoint after every pass, and the last one written (a pass before the end) is
// resumed to the target. Cases stop inside a float batch (the device's unfolded sums travel in the checkpoint)
// and just after a fold, with the learned and per-pixel state the estimators keep (efficiency roulette's pilot,
// shadow roulette's pixel estimate), QMC replicates, and both integrators.
#include <gtest/gtest.h>
#include <signal.h>

#include <atomic>

#include <cstring>

#include "error.h"
#include "io/checkpoint.h"
#include "support/render_helpers.h"
#include "support/test_scenes.h"

using namespace vkmc;
using namespace vkmc::test;

namespace {

std::filesystem::path dir() {
  static std::filesystem::path d = makeTempDir("checkpoint");
  return d;
}

// 256x128 pixels: 8 samples a pass, 64 (8 passes) a float batch.
RenderOptions options(uint32_t spp, const EstimatorConfig& e, Integrator integrator = Integrator::Wavefront) {
  RenderOptions o;
  o.scenePath = scenePath("cornell_box.gltf");
  o.width = 256;
  o.height = 128;
  o.spp = spp;
  o.seed = 77;
  o.estimator = e;
  o.integrator = integrator;
  o.progress = false;
  return o;
}

struct ResumeCase {
  const char* name;
  uint32_t spp;
  uint32_t batchAtCheckpoint;  // samples of the device's unfolded batch in the last checkpoint
  EstimatorConfig estimator;
  Integrator integrator = Integrator::Wavefront;
};

EstimatorConfig with(const char* key, nlohmann::json value) {
  EstimatorConfig e;
  e.applyJson({{key, value}});
  return e;
}

class ResumedRender : public ::testing::TestWithParam<ResumeCase> {};

}  // namespace

TEST_P(ResumedRender, EqualsTheUninterruptedOneBitForBit) {
  const ResumeCase c = GetParam();
  const RenderOptions o = options(c.spp, c.estimator, c.integrator);
  RunControl run;
  run.checkpointPath = (dir() / (std::string(c.name) + ".ckpt")).string();
  run.checkpointEvery = 1e-9;  // after every pass but the last
  RenderOutcome full = runRender(sharedContext(), o, run);
  ASSERT_GT(full.checkpointsWritten, 0u);
  EXPECT_FALSE(full.interrupted);

  Checkpoint ck = readCheckpoint(run.checkpointPath);
  EXPECT_EQ(ck.state.nextSample, c.spp - 8);
  EXPECT_EQ(ck.state.batchSamples, c.batchAtCheckpoint);
  RunControl resume;
  resume.resumeConfig = &ck.config;
  resume.resumeState = &ck.state;
  RenderOutcome resumed = runRender(sharedContext(), o, resume);
  EXPECT_TRUE(resumed.resumed);
  const Film &a = full.film, &b = resumed.film;
  EXPECT_EQ(a.sum, b.sum);
  EXPECT_EQ(a.sumSq, b.sumSq);
  EXPECT_EQ(a.count, b.count);
  EXPECT_EQ(a.nonfinite, b.nonfinite);
  EXPECT_EQ(a.replicateSum, b.replicateSum);
  EXPECT_EQ(a.replicateCount, b.replicateCount);
  EXPECT_EQ(full.stats.rays(), resumed.stats.rays());
  EXPECT_EQ(full.stats.samplesPerPixel, resumed.stats.samplesPerPixel);
  EXPECT_EQ(full.stats.pathsByBounce, resumed.stats.pathsByBounce);
}

INSTANTIATE_TEST_SUITE_P(Checkpoint, ResumedRender,
                         ::testing::Values(ResumeCase{"inside_a_batch", 40, 32, EstimatorConfig{}},
                                           ResumeCase{"after_a_fold", 72, 0, EstimatorConfig{}},
                                           ResumeCase{"efficiency_roulette", 40, 32, with("rr", "efficiency")},
                                           // Passes of 1, 2, 4, then 8 samples (the estimate refreshed after each): a fold after
                                           // 63, the last checkpoint at 71.
                                           ResumeCase{"shadow_roulette_after_a_fold", 79, 8, with("shadow_rr", 0.5)},
                                           ResumeCase{"sobol_replicates", 40, 32, with("sampler", "sobol")},
                                           ResumeCase{"one_scrambling", 40, 32, with("replicates", 1)},
                                           ResumeCase{"megakernel", 40, 32, EstimatorConfig{}, Integrator::Megakernel}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(ResumedRenderRefusal, AnotherConfigurationIsNamed) {
  const RenderOptions o = options(24, EstimatorConfig{});
  RunControl run;
  run.checkpointPath = (dir() / "refusal.ckpt").string();
  run.checkpointEvery = 1e-9;
  runRender(sharedContext(), o, run);
  Checkpoint ck = readCheckpoint(run.checkpointPath);
  auto refusal = [&](const RenderOptions& other) -> std::string {
    Checkpoint copy = ck;
    RunControl resume;
    resume.resumeConfig = &copy.config;
    resume.resumeState = &copy.state;
    try {
      runRender(sharedContext(), other, resume);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  RenderOptions spp = o;
  spp.spp = 32;
  EXPECT_NE(refusal(spp).find("differs in spp"), std::string::npos);
  RenderOptions rr = o;
  rr.estimator.rr = RouletteMode::Fixed;
  EXPECT_NE(refusal(rr).find("differs in estimator.rr"), std::string::npos) << refusal(rr);
  RenderOptions scene = o;
  scene.scenePath = scenePath("veach_mis.gltf");
  EXPECT_NE(refusal(scene).find("differs in scene"), std::string::npos) << refusal(scene);
  RenderOptions size = o;
  size.width = 128;
  EXPECT_NE(refusal(size).find("differs in width"), std::string::npos) << refusal(size);
}

TEST(ResumedTimeBudget, ContinuesWithWhatIsLeftOfTheBudget) {
  RenderOptions o = options(1u << 24, EstimatorConfig{});
  // Each run is stopped at its first checkpoint (the sync point afterCheckpoint), which follows its first pass: a
  // budget of ten minutes is never what ends them, however slow the machine.
  o.timeBudget = 600.0;
  std::atomic<int> stop{0};
  RunControl run;
  run.checkpointPath = (dir() / "budget.ckpt").string();
  run.checkpointEvery = 1e-9;
  run.stop = &stop;
  run.afterCheckpoint = [&] { stop = SIGTERM; };
  RenderOutcome full = runRender(sharedContext(), o, run);
  ASSERT_EQ(full.checkpointsWritten, 1u);
  ASSERT_TRUE(full.interrupted);
  Checkpoint ck = readCheckpoint(run.checkpointPath);
  std::atomic<int> stopResumed{0};
  RunControl resume;
  resume.resumeConfig = &ck.config;
  resume.resumeState = &ck.state;
  resume.checkpointPath = (dir() / "budget_resumed.ckpt").string();
  resume.checkpointEvery = 1e-9;
  resume.stop = &stopResumed;
  resume.afterCheckpoint = [&] { stopResumed = SIGTERM; };
  const uint32_t before = ck.state.nextSample;
  const double secondsBefore = ck.state.stats.seconds;
  RenderOutcome resumed = runRender(sharedContext(), o, resume);
  // At least one more pass (a budget always takes one), and the seconds of both runs in the report.
  EXPECT_GT(resumed.stats.samplesPerPixel, before);
  EXPECT_GT(resumed.stats.seconds, secondsBefore);
  EXPECT_EQ(resumed.film.count[0], resumed.stats.samplesPerPixel);
}
