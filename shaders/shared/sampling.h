// Pure sampling functions, each with its pdf; used by the kernels, the host and the statistical tests.
#ifndef VKMC_SAMPLING_H
#define VKMC_SAMPLING_H
#include "glsl_cpp.h"
VKMC_BEGIN_NAMESPACE

VKMC_CONST float kPi = 3.14159265358979323846f;
VKMC_CONST float kInvPi = 0.31830988618379067154f;

// (cos, sin) of (pi/4) t for t in [-1, 1]: Taylor polynomials to x^10 and x^9, whose remainders there (1e-10,
// 2e-9) are below float rounding. llvmpipe's general cos and sin reduce the range first: a cosine-sampled
// vertex of the furnace probe spent a third of its time in them (docs/journal/performance.md, "The furnace probe's vertex").
VKMC_FN vec2 cosSinQuarterPi(float t) {
  float x = (kPi / 4.0f) * t, x2 = x * x;
  float c = 1.0f + x2 * (-0.5f + x2 * (4.16666667e-2f + x2 * (-1.38888889e-3f + x2 * (2.48015873e-5f + x2 * -2.75573192e-7f))));
  float s = x * (1.0f + x2 * (-1.66666667e-1f + x2 * (8.33333333e-3f + x2 * (-1.98412698e-4f + x2 * 2.75573192e-6f))));
  return vec2(c, s);
}

// Shirley-Chiu concentric map: low distortion, so stratification survives. In the wedges where |o.y| >= |o.x|
// the angle is pi/2 - (pi/4) t, whose cosine and sine are the sine and cosine of (pi/4) t.
VKMC_FN vec2 sampleUniformDiskConcentric(vec2 u) {
  vec2 o = 2.0f * u - vec2(1.0f);
  if (o.x == 0.0f && o.y == 0.0f) return vec2(0.0f);
  bool xMajor = abs(o.x) > abs(o.y);
  float r = xMajor ? o.x : o.y;
  vec2 cs = cosSinQuarterPi(xMajor ? o.y / o.x : o.x / o.y);
  return r * (xMajor ? cs : vec2(cs.y, cs.x));
}

// Inverse of sampleUniformDiskConcentric (pbrt-v4's InvertUniformDiskConcentricSample).
VKMC_FN vec2 invertUniformDiskConcentricSample(vec2 p) {
  float theta = atan(p.y, p.x);  // -pi .. pi
  float r = sqrt(p.x * p.x + p.y * p.y);
  vec2 o;
  if (abs(theta) < kPi / 4.0f || abs(theta) > 3.0f * kPi / 4.0f) {
    r = p.x < 0.0f ? -r : r;
    o.x = r;
    if (p.x < 0.0f)
      o.y = (p.y < 0.0f ? kPi + theta : theta - kPi) * r / (kPi / 4.0f);
    else
      o.y = theta * r / (kPi / 4.0f);
  } else {
    r = p.y < 0.0f ? -r : r;
    o.y = r;
    o.x = (p.y < 0.0f ? -(kPi / 2.0f + theta) : kPi / 2.0f - theta) * r / (kPi / 4.0f);
  }
  return 0.5f * (o + vec2(1.0f));
}

// Local frame: z is the normal.
VKMC_FN vec3 sampleCosineHemisphere(vec2 u) {
  vec2 d = sampleUniformDiskConcentric(u);
  float z = sqrt(max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
  return vec3(d.x, d.y, z);
}
VKMC_FN float cosineHemispherePdf(float cosTheta) { return max(cosTheta, 0.0f) * kInvPi; }
VKMC_FN vec2 invertCosineHemisphereSample(vec3 w) { return invertUniformDiskConcentricSample(vec2(w.x, w.y)); }

VKMC_FN vec3 sampleUniformHemisphere(vec2 u) {
  float z = u.x;
  float r = sqrt(max(0.0f, 1.0f - z * z));
  float phi = 2.0f * kPi * u.y;
  return vec3(r * cos(phi), r * sin(phi), z);
}
VKMC_FN float uniformHemispherePdf(float cosTheta) { return cosTheta > 0.0f ? 0.5f * kInvPi : 0.0f; }
VKMC_FN vec2 invertUniformHemisphereSample(vec3 w) {
  float phi = atan(w.y, w.x);
  return vec2(w.z, (phi < 0.0f ? phi + 2.0f * kPi : phi) / (2.0f * kPi));
}

// Barycentrics (b0, b1, b2) uniform over the triangle's area; pdf = 1 / area.
VKMC_FN vec3 sampleUniformTriangle(vec2 u) {
  float su = sqrt(u.x);
  float b0 = 1.0f - su;
  float b1 = u.y * su;
  return vec3(b0, b1, 1.0f - b0 - b1);
}
VKMC_FN vec2 invertUniformTriangleSample(vec3 b) {
  float su = 1.0f - b.x;
  return vec2(su * su, su > 0.0f ? b.y / su : 0.0f);
}

// Duff et al. 2017: orthonormal basis without a branch on the normal's direction; columns are t, b, n.
VKMC_FN mat3 basisFromNormal(vec3 n) {
  float s = n.z >= 0.0f ? 1.0f : -1.0f;
  float a = -1.0f / (s + n.z);
  float b = n.x * n.y * a;
  vec3 t = vec3(1.0f + s * n.x * n.x * a, s * b, -s * n.x);
  vec3 bt = vec3(b, s + n.y * n.y * a, -n.y);
  return mat3(t, bt, n);
}

VKMC_FN float maxComponent(vec3 v) { return max(v.x, max(v.y, v.z)); }
VKMC_FN float luminance(vec3 c) { return dot(c, vec3(0.2126f, 0.7152f, 0.0722f)); }

VKMC_END_NAMESPACE
#endif
