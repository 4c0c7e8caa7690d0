// The shared header's structs have the sizes and offsets the GLSL std430 side assumes.
#include <gtest/gtest.h>

#include "../shaders/shared/layout.h"
#include "../shaders/shared/rng.h"
#include "../shaders/shared/sampling.h"
#include "support/z_test.h"

using namespace vkmc::gpu;
using vkmc::test::withinSigmas;
using vkmc::test::zTest;

TEST(Layout, Std430SizesMatchGlsl) {
  EXPECT_EQ(sizeof(PathState), 80u);
  EXPECT_EQ(sizeof(ShadowRay), 48u);
  EXPECT_EQ(sizeof(Material), 880u);
  EXPECT_EQ(sizeof(TextureSlot), 48u);
  EXPECT_EQ(sizeof(FilmPixel), 64u + 16u * (kMaxSampleReplicates - 1u));
  EXPECT_EQ(double(kFilmHighThreshold), std::ldexp(1.0, 56));
  EXPECT_EQ(double(kFilmHighScale), std::ldexp(1.0, -96));  // film.cpp adds the high sums back times 2^96
  EXPECT_EQ(offsetof(Control, shadowArgs), 32u);
  EXPECT_LE(sizeof(PushConstants), 128u);
}

TEST(Rng, UniformAndDecorrelatedAcrossDimensions) {
  // Mean 1/2, variance 1/12, and neighbouring dimensions uncorrelated, within 5 sigma over 1e5 draws.
  const int n = 100000;
  double sum = 0, sumSq = 0, cross = 0;
  for (int i = 0; i < n; ++i) {
    uint key = pathKey(7u, static_cast<uint>(i), 3u);
    double a = randomUnit(key, 4u), b = randomUnit(key, 5u);
    ASSERT_GE(a, 0.0);
    ASSERT_LT(a, 1.0);
    sum += a;
    sumSq += a * a;
    cross += (a - 0.5) * (b - 0.5);
  }
  EXPECT_TRUE(withinSigmas(zTest(sum / n, 0.5, std::sqrt(1.0 / 12 / n)), 5)) << "mean";
  EXPECT_TRUE(withinSigmas(zTest(sumSq / n - (sum / n) * (sum / n), 1.0 / 12, std::sqrt(1.0 / 180 / n)), 5)) << "variance";
  EXPECT_TRUE(withinSigmas(zTest(cross / n, 0.0, (1.0 / 12) / std::sqrt(double(n))), 5)) << "covariance of neighbours";
}

TEST(Sampling, CosineHemisphereMatchesItsPdfMoments) {
  // E[cos] under p = cos/pi is 2/3; every sample lies on the unit upper hemisphere.
  const int n = 200000;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    uint key = pathKey(1u, static_cast<uint>(i), 0u);
    vec3 w = sampleCosineHemisphere(vec2(randomUnit(key, 0u), randomUnit(key, 1u)));
    ASSERT_NEAR(length(w), 1.0f, 1e-5f);
    ASSERT_GE(w.z, 0.0f);
    sum += w.z;
  }
  double sigma = std::sqrt((0.5 - 4.0 / 9.0) / n);  // Var[cos] = E[cos^2] - E[cos]^2 = 1/2 - 4/9
  EXPECT_TRUE(withinSigmas(zTest(sum / n, 2.0 / 3.0, sigma), 5));
}

TEST(Sampling, UniformTriangleBarycentricsHaveUniformMeans) {
  const int n = 200000;
  dvec3 sum(0.0);
  for (int i = 0; i < n; ++i) {
    uint key = pathKey(2u, static_cast<uint>(i), 0u);
    vec3 b = sampleUniformTriangle(vec2(randomUnit(key, 0u), randomUnit(key, 1u)));
    ASSERT_NEAR(b.x + b.y + b.z, 1.0f, 1e-6f);
    ASSERT_GE(std::min(b.x, std::min(b.y, b.z)), -1e-7f);
    sum += dvec3(b);
  }
  double sigma = std::sqrt(1.0 / 18.0 / n);  // Var of a barycentric coordinate under the uniform law: 1/18
  for (int c = 0; c < 3; ++c) EXPECT_TRUE(withinSigmas(zTest(sum[c] / n, 1.0 / 3.0, sigma), 5)) << "coordinate " << c;
}

TEST(Sampling, BasisIsOrthonormal) {
  for (int i = 0; i < 1000; ++i) {
    uint key = pathKey(3u, static_cast<uint>(i), 0u);
    vec3 n = normalize(vec3(randomUnit(key, 0u) - 0.5f, randomUnit(key, 1u) - 0.5f, randomUnit(key, 2u) - 0.5f));
    mat3 m = basisFromNormal(n);
    EXPECT_NEAR(dot(m[0], m[1]), 0.0f, 1e-5f);
    EXPECT_NEAR(dot(m[0], m[2]), 0.0f, 1e-5f);
    EXPECT_NEAR(length(m[0]), 1.0f, 1e-5f);
    EXPECT_NEAR(length(m[1]), 1.0f, 1e-5f);
    EXPECT_NEAR(dot(m[2], n), 1.0f, 1e-6f);
  }
}
