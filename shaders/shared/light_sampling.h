// Sampling a point of an emissive triangle as seen from a shading point: uniformly on its area (pdf 1/A in
// area measure) or uniformly in its solid angle (Arvo 1995, pdf 1/Omega). Both return solid-angle pdfs.
#ifndef VKMC_LIGHT_SAMPLING_H
#define VKMC_LIGHT_SAMPLING_H
#include "glsl_cpp.h"
#include "sampling.h"
VKMC_BEGIN_NAMESPACE

// Below this solid angle the spherical construction loses precision; area sampling is used instead, and the
// same test decides the pdf, so sampling and evaluation always agree.
VKMC_CONST float kMinSphericalSolidAngle = 1e-5f;

// Solid angle of triangle (a, b, c) seen from p (Van Oosterom & Strackee 1983).
VKMC_FN float triangleSolidAngle(vec3 p, vec3 a, vec3 b, vec3 c) {
  vec3 ua = normalize(a - p), ub = normalize(b - p), uc = normalize(c - p);
  float num = abs(dot(ua, cross(ub, uc)));
  float den = 1.0f + dot(ua, ub) + dot(ub, uc) + dot(uc, ua);
  return 2.0f * atan(num, den);
}

VKMC_FN bool useSphericalSampling(float solidAngle) { return solidAngle >= kMinSphericalSolidAngle; }

// Arvo's spherical triangle sampling: a unit direction from p, uniform over the triangle's solid angle.
VKMC_FN vec3 sampleSphericalTriangle(vec3 p, vec3 a0, vec3 b0, vec3 c0, vec2 u, float solidAngle) {
  vec3 A = normalize(a0 - p), B = normalize(b0 - p), C = normalize(c0 - p);
  // Interior angle at A and side lengths via normals of the great circles.
  vec3 nAB = normalize(cross(A, B)), nAC = normalize(cross(A, C));
  float cosAlpha = clamp(dot(nAB, nAC), -1.0f, 1.0f);
  float alpha = acos(cosAlpha);
  float sinAlpha = sin(alpha);
  float cosC = clamp(dot(A, B), -1.0f, 1.0f);
  float areaHat = u.x * solidAngle;
  float s = sin(areaHat - alpha);
  float t = cos(areaHat - alpha);
  float uu = t - cosAlpha;
  float vv = s + sinAlpha * cosC;
  float den = (vv * s + uu * t) * sinAlpha;
  float q = den != 0.0f ? clamp(((vv * t - uu * s) * cosAlpha - vv) / den, -1.0f, 1.0f) : 1.0f;
  vec3 perp = C - dot(C, A) * A;
  float perpLen = length(perp);
  vec3 cHat = q * A + sqrt(max(0.0f, 1.0f - q * q)) * (perpLen > 0.0f ? perp / perpLen : vec3(0.0f));
  float z = 1.0f - u.y * (1.0f - dot(cHat, B));
  vec3 perp2 = cHat - dot(cHat, B) * B;
  float perp2Len = length(perp2);
  return normalize(z * B + sqrt(max(0.0f, 1.0f - z * z)) * (perp2Len > 0.0f ? perp2 / perp2Len : vec3(0.0f)));
}

// Point where the ray p + t w meets the plane of the triangle (for a direction known to hit it).
VKMC_FN vec3 pointOnTrianglePlane(vec3 p, vec3 w, vec3 a, vec3 n) {
  float dn = dot(w, n);
  return dn != 0.0f ? p + w * (dot(a - p, n) / dn) : a;
}

VKMC_END_NAMESPACE
#endif
