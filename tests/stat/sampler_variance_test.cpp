// Honest variance under QMC (issue 14): over many seeds, the variance of each pixel's mean that the film reports
// matches the observed spread of that mean, for every sampler. Under the Sobol samplers the samples inside a
// pixel are correlated, so the film estimates it from the spread of independently scrambled replicates (2, the
// default, and 4); the naive per-sample estimate (as if independent) overstates it, which this test also shows, so
// it can tell an honest estimate from a conservative one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "support/render_helpers.h"

namespace vkmc::test {
namespace {

struct VarianceRatio {
  double ratio = 0.0, sigma = 0.0;  // sum of observed variances / sum of reported ones, and its standard error
};

// Relative variances (each pixel's over its mean^2 + 0.01, as relMSE weighs them), so that the few pixels at the
// light's edge do not decide alone. Pixels are independent (each its own scrambling), so the ratio's standard
// error comes from the per-pixel terms by the delta method: SE = sqrt(sum (a_p - R b_p)^2) / sum b_p.
VarianceRatio ratioOf(const std::vector<double>& observed, const std::vector<double>& reported,
                      const std::vector<double>& weight) {
  double a = 0.0, b = 0.0;
  for (size_t p = 0; p < observed.size(); ++p) a += weight[p] * observed[p], b += weight[p] * reported[p];
  VarianceRatio r;
  r.ratio = a / b;
  double ss = 0.0;
  for (size_t p = 0; p < observed.size(); ++p) {
    double d = weight[p] * (observed[p] - r.ratio * reported[p]);
    ss += d * d;
  }
  r.sigma = std::sqrt(ss) / b;
  return r;
}

struct Spread {
  VarianceRatio honest, naive;  // against the film's estimate, and against the per-sample one
};

Spread measure(Sampler sampler, uint32_t replicates, uint32_t seeds, uint32_t size, uint32_t spp) {
  EstimatorConfig e;
  e.sampler = sampler;
  e.replicates = replicates;
  const size_t pixels = size_t(size) * size;
  std::vector<double> sum(pixels, 0.0), sumSq(pixels, 0.0), reported(pixels, 0.0), naive(pixels, 0.0);
  for (uint32_t s = 0; s < seeds; ++s) {
    RenderOutcome r = renderWith("cornell_box.gltf", e, size, size, spp, 1000 + s);
    for (size_t p = 0; p < pixels; ++p) {
      double m = r.film.mean(p, 0);
      sum[p] += m;
      sumSq[p] += m * m;
      reported[p] += r.film.varianceOfMean(p, 0) / seeds;
      naive[p] += r.film.sampleVarianceOfMean(p, 0) / seeds;
    }
  }
  std::vector<double> observed(pixels), weight(pixels);
  for (size_t p = 0; p < pixels; ++p) {
    observed[p] = (sumSq[p] - sum[p] * sum[p] / seeds) / (seeds - 1.0);
    double mean = sum[p] / seeds;
    weight[p] = 1.0 / (mean * mean + 0.01);
  }
  return {ratioOf(observed, reported, weight), ratioOf(observed, naive, weight)};
}

std::string describe(const VarianceRatio& r) {
  return "observed / reported = " + std::to_string(r.ratio) + " +- " + std::to_string(r.sigma);
}

TEST(SamplerVariance, ReportedVarianceMatchesTheSpreadOverSeeds) {
  struct Case {
    Sampler sampler;
    uint32_t replicates;
  };
  for (Case c : {Case{Sampler::Independent, 2}, Case{Sampler::Sobol, 2}, Case{Sampler::ZSobol, 2}, Case{Sampler::Sobol, 4}}) {
    const Sampler sampler = c.sampler;
    Spread s = measure(sampler, c.replicates, 20, 24, 32);
    std::printf("sampler %u, %u replicates: honest %s; naive %s\n", uint32_t(sampler), c.replicates, describe(s.honest).c_str(),
                describe(s.naive).c_str());
    SCOPED_TRACE("sampler " + std::to_string(uint32_t(sampler)) + ", replicates " + std::to_string(c.replicates));
    EXPECT_LT(std::abs(s.honest.ratio - 1.0), 4.0 * s.honest.sigma) << describe(s.honest);
    EXPECT_LT(s.honest.sigma, 0.1) << "too few seeds to tell";
    if (sampler == Sampler::Independent) {
      EXPECT_LT(std::abs(s.naive.ratio - 1.0), 4.0 * s.naive.sigma) << "independent samples: " << describe(s.naive);
    } else {
      // The per-sample estimate ignores the stratification: it overstates the variance of the mean.
      EXPECT_LT(s.naive.ratio, 1.0 - 4.0 * s.naive.sigma) << "QMC, naive: " << describe(s.naive);
    }
  }
}

// Over seeds: each pixel's mean and the observed variance of it, and the image mean's mean and variance.
struct SeedSpread {
  std::vector<double> mean, observed;
  double imageMean = 0.0, imageMeanVariance = 0.0;
};

SeedSpread spreadOverSeeds(const std::string& scene, uint32_t replicates, uint32_t seeds, uint32_t size, uint32_t spp) {
  EstimatorConfig e;
  e.replicates = replicates;
  const size_t pixels = size_t(size) * size;
  std::vector<double> sum(pixels, 0.0), sumSq(pixels, 0.0);
  double imageSum = 0.0, imageSumSq = 0.0;
  for (uint32_t s = 0; s < seeds; ++s) {
    RenderOutcome r = renderWith(scene, e, size, size, spp, 2000 + s);
    EXPECT_EQ(r.film.estimatesVariance(), replicates >= 2);
    double image = 0.0;
    for (size_t p = 0; p < pixels; ++p) {
      const double m = r.film.mean(p, 0);
      sum[p] += m, sumSq[p] += m * m, image += m / double(pixels);
    }
    imageSum += image, imageSumSq += image * image;
  }
  SeedSpread out;
  for (size_t p = 0; p < pixels; ++p) {
    out.mean.push_back(sum[p] / seeds);
    out.observed.push_back((sumSq[p] - sum[p] * sum[p] / seeds) / (seeds - 1.0));
  }
  out.imageMean = imageSum / seeds;
  out.imageMeanVariance = (imageSumSq - imageSum * imageSum / seeds) / (seeds - 1.0) / seeds;
  return out;
}

// One scrambling (--replicates 1) reports no variance; over seeds it has the same mean as two replicates and,
// on a smooth integrand (the tiny light's falloff), far less spread: one 32-point net against two of 16, where
// Owen-scrambled error falls like n^-3.
TEST(SamplerVariance, OneScramblingKeepsTheMeanAndSpreadsLessThanTwoReplicates) {
  const uint32_t seeds = 20, size = 16, spp = 32;
  SeedSpread one = spreadOverSeeds("stiff/tiny_light.gltf", 1, seeds, size, spp);
  SeedSpread two = spreadOverSeeds("stiff/tiny_light.gltf", 2, seeds, size, spp);
  const double z = (one.imageMean - two.imageMean) / std::sqrt(one.imageMeanVariance + two.imageMeanVariance);
  EXPECT_LT(std::abs(z), 4.0) << "image means " << one.imageMean << " and " << two.imageMean;
  double a = 0.0, b = 0.0;
  for (size_t p = 0; p < one.mean.size(); ++p) {
    const double w = 1.0 / (two.mean[p] * two.mean[p] + 0.01);
    a += w * one.observed[p], b += w * two.observed[p];
  }
  std::printf("tiny light, %u spp: spread over seeds, one scrambling / two replicates = %.3f\n", spp, a / b);
  EXPECT_LT(a, 0.5 * b) << "one scrambling / two replicates = " << a / b;
}

}  // namespace
}  // namespace vkmc::test
