// KHR_materials_iridescence's thin-film Fresnel (shaders/shared/iridescence.h), run as C++: the limits where the
// film must vanish, the incoherent limit of a thick film against the Airy sum worked out here, total internal
// reflection, and bounds.
#include <gtest/gtest.h>

#include <cmath>

#include "../shaders/shared/iridescence.h"

using namespace vkmc::gpu;

namespace {
// Schlick's Fresnel of the base alone (f90 = 1), what the film must give where it is not there.
vec3 baseFresnel(vec3 f0, float cosTheta) { return schlick3(f0, cosTheta); }

void expectNear(vec3 a, vec3 b, float tolerance, const std::string& what) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], tolerance) << what << " channel " << c;
}
}  // namespace

// A film of zero thickness, or one whose ior is the outside's, is no film: the base's own Fresnel.
TEST(Iridescence, NoFilmWhereItHasNoThicknessOrNoIndexStep) {
  for (vec3 f0 : {vec3(0.04f), vec3(0.95f, 0.64f, 0.54f), vec3(0.2f, 0.5f, 0.9f)})
    for (float c : {1.0f, 0.7f, 0.3f, 0.05f}) {
      const std::string what = "f0 " + std::to_string(f0.x) + " cos " + std::to_string(c);
      expectNear(iridescentFresnel(1.0f, 1.8f, c, 0.0f, f0), baseFresnel(f0, c), 0.01f, what + ", thickness 0");
      expectNear(iridescentFresnel(1.0f, 1.0f, c, 350.0f, f0), baseFresnel(f0, c), 0.01f, what + ", film ior 1");
    }
}

// Far thicker than light's coherence the harmonics vanish, and what is left is the incoherent Airy sum of the two
// interfaces: R12 + T12^2 R23 / (1 - R12 R23), R12 by Fresnel's equations and R23 by Schlick at the refracted
// angle (Snell's law inside the film).
TEST(Iridescence, AThickFilmIsTheIncoherentSumOfItsInterfaces) {
  const float filmIor = 1.5f;
  const vec3 f0 = vec3(0.04f, 0.3f, 0.9f);
  for (float c : {1.0f, 0.6f, 0.2f}) {
    const double s2 = (1.0 - double(c) * c) / (filmIor * filmIor), c2 = std::sqrt(1.0 - s2);
    auto schlick = [](double r0, double cosine) { return r0 + (1.0 - r0) * std::pow(1.0 - cosine, 5.0); };
    const double rs = (c - filmIor * c2) / (c + filmIor * c2), rp = (filmIor * c - c2) / (filmIor * c + c2);
    const double r12 = 0.5 * (rs * rs + rp * rp);  // the dielectric Fresnel equations, unpolarized
    const vec3 fresnel = iridescentFresnel(1.0f, filmIor, c, 50000.0f, f0);
    for (int k = 0; k < 3; ++k) {
      const double sq = std::sqrt(std::min(double(f0[k]) + 1e-4, 0.9999)), baseIor = (1.0 + sq) / (1.0 - sq);
      const double r23 = schlick(std::pow((baseIor - filmIor) / (baseIor + filmIor), 2.0), c2);
      const double incoherent = r12 + (1.0 - r12) * (1.0 - r12) * r23 / (1.0 - r12 * r23);
      EXPECT_NEAR(fresnel[k], incoherent, 2e-3) << "cos " << c << " channel " << k;
    }
  }
}

// A film thin enough to interfere colours the reflection: its hue turns with the thickness, unlike the base's.
TEST(Iridescence, AThinFilmInterferes) {
  const vec3 f0 = vec3(0.04f);
  float largestChange = 0.0f;
  for (float d = 100.0f; d <= 800.0f; d += 50.0f) {
    const vec3 f = iridescentFresnel(1.0f, 1.8f, 0.9f, d, f0);
    for (int c = 0; c < 3; ++c) {
      EXPECT_GE(f[c], 0.0f) << d;
      EXPECT_LE(f[c], 1.0f) << d;
    }
    largestChange = std::max(largestChange, std::abs(f.x - f.z));
  }
  EXPECT_GT(largestChange, 0.05f) << "red against blue: the film colours nothing";
}

// From inside a coat (outside ior 1.5, the cosine on the coat's side) a film of ior 1.2 totally reflects beyond the
// critical angle; light that entered the coat from air never reaches it (bsdf_gltf.h carries the cosine in first).
TEST(Iridescence, TotalInternalReflectionInsideTheFilm) {
  expectNear(iridescentFresnel(1.5f, 1.2f, 0.3f, 300.0f, vec3(0.04f)), vec3(1.0f), 0.0f, "past the critical angle");
  const vec3 below = iridescentFresnel(1.5f, 1.2f, 0.95f, 300.0f, vec3(0.04f));
  EXPECT_LT(below.y, 0.5f) << "near normal incidence light enters the film";
}
