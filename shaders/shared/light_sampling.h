// Sampling a point of an emissive triangle as seen from a shading point: uniformly on its area (pdf 1/A in
// area measure) or uniformly in its solid angle (Arvo 1995, pdf 1/Omega). Both return solid-angle pdfs.
#ifndef VKMC_LIGHT_SAMPLING_H
#define VKMC_LIGHT_SAMPLING_H
#include "glsl_cpp.h"
#include "geometry.h"
#include "layout.h"
#include "sampling.h"
VKMC_BEGIN_NAMESPACE

// Spherical sampling is used only where it is well conditioned (pbrt-v4's bounds): tiny triangles lose
// precision in the spherical construction and near-hemispherical ones in its angles. Outside, area sampling;
// the same test decides the pdf, so sampling and evaluation always agree.
VKMC_CONST float kMinSphericalSolidAngle = 3e-4f;
VKMC_CONST float kMaxSphericalSolidAngle = 6.22f;

// Solid angle of triangle (a, b, c) seen from p (Van Oosterom & Strackee 1983).
VKMC_FN float triangleSolidAngle(vec3 p, vec3 a, vec3 b, vec3 c) {
  vec3 ua = normalize(a - p), ub = normalize(b - p), uc = normalize(c - p);
  float num = abs(dot(ua, cross(ub, uc)));
  float den = 1.0f + dot(ua, ub) + dot(ub, uc) + dot(uc, ua);
  return 2.0f * atan(num, den);
}

VKMC_FN bool useSphericalSampling(float solidAngle) {
  return solidAngle >= kMinSphericalSolidAngle && solidAngle <= kMaxSphericalSolidAngle;
}

VKMC_FN float safeAsin(float x) { return asin(clamp(x, -1.0f, 1.0f)); }
VKMC_FN float safeSqrt(float x) { return sqrt(max(x, 0.0f)); }

// Angle between unit vectors from half the chord: precise near 0 and pi, where acos of a dot product is not
// (and GPUs' acos is looser still).
VKMC_FN float angleBetween(vec3 v1, vec3 v2) {
  bool obtuse = dot(v1, v2) < 0.0f;  // one asin of the selected chord: llvmpipe runs both sides of a branch
  float angle = 2.0f * safeAsin(0.5f * length(obtuse ? v1 + v2 : v2 - v1));
  return obtuse ? kPi - angle : angle;
}

VKMC_FN vec3 orthogonalUnit(vec3 v, vec3 w) {
  vec3 o = v - dot(v, w) * w;
  float l = length(o);
  return l > 0.0f ? o / l : vec3(0.0f);
}

// Arvo 1995 in pbrt-v4's arrangement: a unit direction from p, uniform over the triangle's solid angle. The
// vertex angles and the sampled area come from the same computation, so the map is uniform to rounding.
VKMC_FN vec3 sampleSphericalTriangle(vec3 p, vec3 v0, vec3 v1, vec3 v2, vec2 u, float solidAngle) {
  vec3 a = normalize(v0 - p), b = normalize(v1 - p), c = normalize(v2 - p);
  vec3 nab = cross(a, b), nbc = cross(b, c), nca = cross(c, a);
  if (dot(nab, nab) == 0.0f || dot(nbc, nbc) == 0.0f || dot(nca, nca) == 0.0f) return a;
  nab = normalize(nab);
  nbc = normalize(nbc);
  nca = normalize(nca);
  float alpha = angleBetween(nab, -nca);
  float beta = angleBetween(nbc, -nab);
  float gamma = angleBetween(nca, -nbc);
  float apPi = mix(kPi, alpha + beta + gamma, u.x);  // sampled sub-triangle area + pi
  float cosAlpha = cos(alpha), sinAlpha = sin(alpha);
  float sinPhi = sin(apPi) * cosAlpha - cos(apPi) * sinAlpha;
  float cosPhi = cos(apPi) * cosAlpha + sin(apPi) * sinAlpha;
  float k1 = cosPhi + cosAlpha;
  float k2 = sinPhi - sinAlpha * dot(a, b);
  float den = (k2 * sinPhi + k1 * cosPhi) * sinAlpha;
  float cosBp = den != 0.0f ? clamp((k2 + (k2 * cosPhi - k1 * sinPhi) * cosAlpha) / den, -1.0f, 1.0f) : 1.0f;
  float sinBp = safeSqrt(1.0f - cosBp * cosBp);
  vec3 cp = cosBp * a + sinBp * orthogonalUnit(c, a);
  float cosTheta = 1.0f - u.y * (1.0f - dot(cp, b));
  float sinTheta = safeSqrt(1.0f - cosTheta * cosTheta);
  return normalize(cosTheta * b + sinTheta * orthogonalUnit(cp, b));
}

// Barycentrics (of v0, v1, v2) of the point where the ray p + t w meets the triangle's plane (Moller-Trumbore; for
// a direction known to point at the triangle).
VKMC_FN vec3 rayTriangleBarycentrics(vec3 p, vec3 w, vec3 v0, vec3 v1, vec3 v2) {
  vec3 e1 = v1 - v0, e2 = v2 - v0, s = p - v0;
  vec3 s1 = cross(w, e2);
  float divisor = dot(s1, e1);
  if (divisor == 0.0f) return vec3(1.0f, 0.0f, 0.0f);
  float b1 = dot(s, s1) / divisor, b2 = dot(w, cross(s, e1)) / divisor;
  return vec3(1.0f - b1 - b2, b1, b2);
}

// Barycentrics moved onto the triangle (pbrt-v4's clamp). A spherical sample of a small triangle lands outside it by
// rounding far more often in float than its area suggests: on the 1280-triangle furnace sphere, seen from its own
// surface, 8e-5 of the light (host libm; llvmpipe's looser sin, cos and asin lose more), and a shadow ray to a point
// past an edge is blocked by the neighbour, so that light was lost (the furnace read 0.18% low). On the edge instead,
// it counts where it nearly is.
VKMC_FN vec3 clampToTriangle(vec3 b) {
  float b1 = clamp(b.y, 0.0f, 1.0f), b2 = clamp(b.z, 0.0f, 1.0f);
  float sum = b1 + b2;
  if (sum > 1.0f) {
    b1 /= sum;
    b2 /= sum;
  }
  return vec3(1.0f - b1 - b2, b1, b2);
}

// Light sampling of one emissive triangle (v0, v1, v2) from p: the sampled point, a bound on its
// rounding error, and which technique drew it. kLightSamplingSolidAngle falls back to area sampling where the
// spherical construction is ill-conditioned (useSphericalSampling); triangleLightPdf gives the pdf of the pair.
struct TriangleLightSample {
  vec3 point;
  vec3 pointError;
  bool spherical;
  float solidAngle;  // the triangle's, from p (when spherical)
};

VKMC_FN TriangleLightSample sampleTriangleLight(uint technique, vec3 p, vec3 v0, vec3 v1, vec3 v2, vec2 u) {
  TriangleLightSample s;
  s.spherical = false;
  s.solidAngle = 0.0f;
  if (technique == kLightSamplingSolidAngle) {
    s.solidAngle = triangleSolidAngle(p, v0, v1, v2);
    s.spherical = useSphericalSampling(s.solidAngle);
  }
  vec3 b = sampleUniformTriangle(u);
  if (s.spherical) {
    vec3 w = sampleSphericalTriangle(p, v0, v1, v2, u, s.solidAngle);
    b = clampToTriangle(rayTriangleBarycentrics(p, w, v0, v1, v2));
  }
  s.point = b.x * v0 + b.y * v1 + b.z * v2;
  s.pointError = barycentricError(b, v0, v1, v2);
  return s;
}

// A point on an emitter quad from u in the unit square (render/emitter_pairs.h): the first half (p0, p1, p2), apex
// p1 and shared edge p0-p2, below the diagonal u.x + u.y = 1, the second (p0, p2, w) above it. Both are the point
// p1 + u.x (p0 - p1) + u.y (p2 - p1) of the parallelogram, written as weights of (p0, p2, x), x = p1 on the first
// half and w on the second, all in [0, 1], so that the point lies on the half's own triangle even where w is not
// exactly p0 + p2 - p1. Each half: probability 1/2, uniform on it.
VKMC_FN bool emitterQuadSecondHalf(vec2 u) { return u.x + u.y > 1.0f; }
VKMC_FN vec3 emitterQuadWeights(vec2 u) {
  return emitterQuadSecondHalf(u) ? vec3(1.0f - u.y, 1.0f - u.x, u.x + u.y - 1.0f) : vec3(u.x, u.y, 1.0f - u.x - u.y);
}

// The solid-angle pdf of a sample times the triangle's selection pmf: pmf / solid angle when sampled spherically,
// else pmf dist^2 / (area cos) for a point at squared distance dist2 seen under cosLight.
VKMC_FN float triangleLightPdf(bool spherical, float solidAngle, float pmf, float area, float dist2, float cosLight) {
  return spherical ? pmf / solidAngle : pmf * dist2 / (area * cosLight);
}

// The same pdf for a point found otherwise (a BSDF-sampled ray, for MIS): the technique decided as sampling does.
VKMC_FN float triangleLightPdfAt(uint technique, vec3 p, vec3 v0, vec3 v1, vec3 v2, float pmf, float area, float dist2,
                                 float cosLight) {
  float omega = technique == kLightSamplingSolidAngle ? triangleSolidAngle(p, v0, v1, v2) : 0.0f;
  bool spherical = technique == kLightSamplingSolidAngle && useSphericalSampling(omega);
  return triangleLightPdf(spherical, omega, pmf, area, dist2, cosLight);
}

VKMC_END_NAMESPACE
#endif
