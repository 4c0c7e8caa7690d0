// The environment light: an equirectangular map of radiance, importance sampled by a piecewise-constant 2D
// distribution over its pixels (luminance x sin(theta): marginal over rows, conditional over columns, as pbrt's
// PiecewiseConstant2D), with its pdf and its inverse. A 1 x 1 map is a constant environment, sampled uniformly
// on the sphere.
//   Directions: +Y is up (v = 0, the top row); the image's centre (u = 0.5) looks along -Z and u grows toward
//   +X: the map direction is (sin(theta) sin(phi), cos(theta), -sin(theta) cos(phi)), theta = pi v,
//   phi = 2 pi (u - 0.5). A rotation by angle a turns the environment by a about +Y (counter-clockwise seen
//   from above).
//   Distribution (BINDING_ENVIRONMENT_DISTRIBUTION, float[], envDistributionSize(w, h) entries):
//     [0] integral of the function over the unit square; marginal cdf (h + 1); row integrals (h);
//     conditional cdfs (h rows of w + 1); the function (h rows of w).
// GLSL: the including file declares the distribution buffer as envDistribution[]; C++ passes it as a pointer.
#ifndef VKMC_ENVIRONMENT_MAP_H
#define VKMC_ENVIRONMENT_MAP_H
#include "glsl_cpp.h"
#include "layout.h"
#include "sampling.h"
#ifdef __cplusplus
#define VKMC_ENV_TABLE const float *envDistribution,
#define VKMC_ENV_TABLE_ARG envDistribution,
#else
#define VKMC_ENV_TABLE
#define VKMC_ENV_TABLE_ARG
#endif
VKMC_BEGIN_NAMESPACE

VKMC_FN uint envMarginalCdfOffset() { return 1u; }
VKMC_FN uint envRowIntegralOffset(uint height) { return 2u + height; }
VKMC_FN uint envConditionalCdfOffset(uint height) { return 2u + 2u * height; }
VKMC_FN uint envFunctionOffset(uint width, uint height) { return 2u + 2u * height + height * (width + 1u); }
VKMC_FN uint envDistributionSize(uint width, uint height) { return envFunctionOffset(width, height) + width * height; }
// The function the distribution follows at pixel row `row`: luminance x sin(theta) at the row's centre.
VKMC_FN float envRowSinTheta(uint row, uint height) { return sin(kPi * (float(row) + 0.5f) / float(height)); }

// The bin of u in a cdf of `count` bins at `offset`: the last i with cdf[i] <= u (so never an empty bin).
VKMC_FN uint envFindBin(VKMC_ENV_TABLE uint offset, uint count, float u) {
  uint lo = 0u, hi = count;
  while (hi - lo > 1u) {
    uint mid = (lo + hi) / 2u;
    if (envDistribution[offset + mid] <= u)
      lo = mid;
    else
      hi = mid;
  }
  return lo;
}

// A point of the unit square (u: column, v: row) with density function / integral; pdf in area measure.
VKMC_FN vec2 sampleEnvDistribution(VKMC_ENV_TABLE uint width, uint height, vec2 u, INOUT(float) pdf) {
  float integral = envDistribution[0];
  uint mo = envMarginalCdfOffset();
  uint row = envFindBin(VKMC_ENV_TABLE_ARG mo, height, u.y);
  float c0 = envDistribution[mo + row], c1 = envDistribution[mo + row + 1u];
  float dv = c1 > c0 ? (u.y - c0) / (c1 - c0) : 0.5f;
  uint co = envConditionalCdfOffset(height) + row * (width + 1u);
  uint col = envFindBin(VKMC_ENV_TABLE_ARG co, width, u.x);
  float d0 = envDistribution[co + col], d1 = envDistribution[co + col + 1u];
  float du = d1 > d0 ? (u.x - d0) / (d1 - d0) : 0.5f;
  float f = envDistribution[envFunctionOffset(width, height) + row * width + col];
  pdf = integral > 0.0f ? f / integral : 0.0f;
  return vec2(min((float(col) + du) / float(width), 0.99999994f), min((float(row) + dv) / float(height), 0.99999994f));
}

VKMC_FN float envDistributionPdf(VKMC_ENV_TABLE uint width, uint height, vec2 uv) {
  uint col = min(uint(uv.x * float(width)), width - 1u);
  uint row = min(uint(uv.y * float(height)), height - 1u);
  float integral = envDistribution[0];
  float f = envDistribution[envFunctionOffset(width, height) + row * width + col];
  return integral > 0.0f ? f / integral : 0.0f;
}

// The u that sampleEnvDistribution maps to uv (in a bin of non-zero probability).
VKMC_FN vec2 invertEnvDistributionSample(VKMC_ENV_TABLE uint width, uint height, vec2 uv) {
  uint col = min(uint(uv.x * float(width)), width - 1u);
  uint row = min(uint(uv.y * float(height)), height - 1u);
  uint mo = envMarginalCdfOffset();
  uint co = envConditionalCdfOffset(height) + row * (width + 1u);
  float dv = uv.y * float(height) - float(row), du = uv.x * float(width) - float(col);
  return vec2(mix(envDistribution[co + col], envDistribution[co + col + 1u], du),
              mix(envDistribution[mo + row], envDistribution[mo + row + 1u], dv));
}

// Map directions <-> image coordinates, rotation included.
VKMC_FN vec3 environmentDirection(EnvironmentHeader h, vec2 uv) {
  float theta = kPi * uv.y, phi = 2.0f * kPi * (uv.x - 0.5f);
  vec3 m = vec3(sin(theta) * sin(phi), cos(theta), -sin(theta) * cos(phi));
  return vec3(h.cosRotation * m.x + h.sinRotation * m.z, m.y, -h.sinRotation * m.x + h.cosRotation * m.z);
}
VKMC_FN vec2 environmentUv(EnvironmentHeader h, vec3 w) {
  vec3 m = vec3(h.cosRotation * w.x - h.sinRotation * w.z, w.y, h.sinRotation * w.x + h.cosRotation * w.z);
  float u = atan(m.x, -m.z) * (0.5f * kInvPi) + 0.5f;
  float v = atan(length(vec2(m.x, m.z)), m.y) * kInvPi;  // acos(y) loses precision near the poles
  return vec2(clamp(u, 0.0f, 0.99999994f), clamp(v, 0.0f, 0.99999994f));
}
VKMC_FN uint environmentPixel(EnvironmentHeader h, vec2 uv) {
  return min(uint(uv.y * float(h.height)), h.height - 1u) * h.width + min(uint(uv.x * float(h.width)), h.width - 1u);
}

VKMC_FN vec3 sampleUniformSphere(vec2 u) {
  float y = 1.0f - 2.0f * u.x;
  float r = sqrt(max(0.0f, 1.0f - y * y));
  float phi = 2.0f * kPi * u.y;
  return vec3(r * sin(phi), y, -r * cos(phi));
}
VKMC_CONST float kUniformSpherePdf = 0.25f * kInvPi;

// A world direction toward the environment and its solid-angle pdf: pdf(uv) / (2 pi^2 sin(theta)).
VKMC_FN vec3 sampleEnvironment(VKMC_ENV_TABLE EnvironmentHeader h, vec2 u, INOUT(float) pdf) {
  if (h.width == 1u && h.height == 1u) {
    pdf = kUniformSpherePdf;
    return sampleUniformSphere(u);
  }
  float pdfUv = 0.0f;
  vec2 uv = sampleEnvDistribution(VKMC_ENV_TABLE_ARG h.width, h.height, u, pdfUv);
  float sinTheta = sin(kPi * uv.y);
  pdf = sinTheta > 0.0f ? pdfUv / (2.0f * kPi * kPi * sinTheta) : 0.0f;
  return environmentDirection(h, uv);
}

VKMC_FN float environmentPdf(VKMC_ENV_TABLE EnvironmentHeader h, vec3 w) {
  if (h.width == 1u && h.height == 1u) return kUniformSpherePdf;
  vec2 uv = environmentUv(h, w);
  float sinTheta = length(vec2(w.x, w.z));  // sqrt(1 - y^2) would lose precision near the poles
  return sinTheta > 0.0f ? envDistributionPdf(VKMC_ENV_TABLE_ARG h.width, h.height, uv) / (2.0f * kPi * kPi * sinTheta) : 0.0f;
}

VKMC_END_NAMESPACE
#endif
