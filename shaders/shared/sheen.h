// KHR_materials_sheen's lobe: the "Charlie" distribution with the Estevez-Kulla 2017 visibility (the spec's
// reference, as in Khronos' sample viewer), in the local frame (z = normal). alpha = sheenRoughness^2.
#ifndef VKMC_SHEEN_H
#define VKMC_SHEEN_H
#include "glsl_cpp.h"
#include "sampling.h"
VKMC_BEGIN_NAMESPACE

VKMC_CONST float kMinSheenAlpha = 1e-4f;  // the distribution's exponent 1/alpha stays finite

VKMC_FN float charlieD(vec3 h, float alpha) {
  float inv = 1.0f / alpha;
  float sin2 = max(h.x * h.x + h.y * h.y, 0.0f);
  return (2.0f + inv) * pow(sin2, 0.5f * inv) / (2.0f * kPi);
}

// Estevez-Kulla's fit of the masking exponent, interpolated in (1 - alpha)^2 between their two tabulated alphas.
VKMC_FN float charlieL(float x, float alpha) {
  float t = (1.0f - alpha) * (1.0f - alpha);
  float a = mix(21.5473f, 25.3245f, t), b = mix(3.82987f, 3.32435f, t), c = mix(0.19823f, 0.16801f, t);
  float d = mix(-1.97760f, -1.27393f, t), e = mix(-4.32054f, -4.85967f, t);
  return a / (1.0f + b * pow(x, c)) + d * x + e;
}
VKMC_FN float charlieLambda(float cosTheta, float alpha) {
  return cosTheta < 0.5f ? exp(charlieL(cosTheta, alpha)) : exp(2.0f * charlieL(0.5f, alpha) - charlieL(1.0f - cosTheta, alpha));
}

// f = D V with V = G2 / (4 n.l n.v), G2 = 1 / (1 + Lambda(l) + Lambda(v)); both directions above the surface.
VKMC_FN float sheenEval(vec3 wo, vec3 wi, float alpha) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  vec3 h = normalize(wo + wi);
  float g = 1.0f / (1.0f + charlieLambda(wo.z, alpha) + charlieLambda(wi.z, alpha));
  return charlieD(h, alpha) * g / (4.0f * wo.z * wi.z);
}

VKMC_END_NAMESPACE
#endif
