// GGX microfacet pieces in a local frame (z = the facet distribution's normal), isotropic or anisotropic: D, Smith
// masking, visible-normal sampling (Heitz 2018) and the pdfs of reflecting and refracting about a sampled normal (Walter et al.
// 2007), with Schlick's Fresnel. Pure functions; bsdf_gltf.h builds the glTF lobes from them.
#ifndef VKMC_MICROFACET_H
#define VKMC_MICROFACET_H
#include "glsl_cpp.h"
#include "sampling.h"
VKMC_BEGIN_NAMESPACE

// Below this alpha a lobe is a delta (pbrt-v4's EffectivelySmooth): sampled exactly, never evaluated.
VKMC_CONST float kDeltaAlpha = 1e-3f;

VKMC_FN float pow5(float x) {
  float x2 = x * x;
  return x2 * x2 * x;
}

VKMC_FN vec3 schlickFresnel(vec3 f0, float f90, float cosTheta) {
  return f0 + (vec3(f90) - f0) * pow5(1.0f - clamp(cosTheta, 0.0f, 1.0f));
}

// Anisotropic GGX throughout (Heitz 2014): alpha.x along the local x axis (KHR_materials_anisotropy's direction),
// alpha.y along y; vec2(a) is the isotropic lobe, and every formula below reduces to the isotropic one there.

// GGX D from the half vector's local components, as 1 / (pi ax ay (hx^2/ax^2 + hy^2/ay^2 + hz^2)^2): no 1 - h.z^2,
// so tiny alphas stay exact.
VKMC_FN float ggxD(vec3 h, vec2 alpha) {
  float x = h.x / alpha.x, y = h.y / alpha.y;
  float d = x * x + y * y + h.z * h.z;
  return d > 0.0f ? 1.0f / (kPi * alpha.x * alpha.y * d * d) : 0.0f;
}

// The roughness a direction sees along its own azimuth (the alphas' ellipse there): Smith's Lambda of an
// anisotropic lobe is the isotropic one at this alpha.
VKMC_FN float projectedAlpha(vec3 w, vec2 alpha) {
  float s2 = w.x * w.x + w.y * w.y;
  if (!(s2 > 0.0f)) return alpha.x;  // straight up: Lambda is 0 for any alpha
  return sqrt((alpha.x * alpha.x * w.x * w.x + alpha.y * alpha.y * w.y * w.y) / s2);
}

VKMC_FN float smithG1(float cosTheta, float alpha) {
  float a2 = alpha * alpha;
  return 2.0f * cosTheta / (cosTheta + sqrt(a2 + (1.0f - a2) * cosTheta * cosTheta));
}

// Height-correlated Smith G2 / (4 n.l n.v), for reflection (both above the surface).
VKMC_FN float smithVisibility(vec3 wi, vec3 wo, vec2 alpha) {
  float cosL = wi.z, cosV = wo.z;
  float al = projectedAlpha(wi, alpha), av = projectedAlpha(wo, alpha);
  float gv = cosL * sqrt(cosV * cosV * (1.0f - av * av) + av * av);
  float gl = cosV * sqrt(cosL * cosL * (1.0f - al * al) + al * al);
  return 0.5f / (gv + gl);
}

// Height-correlated Smith G2 itself, 1 / (1 + Lambda(o) + Lambda(i)), for either side (absolute cosines).
VKMC_FN float smithLambda(float cosTheta, float alpha) {
  float c2 = max(cosTheta * cosTheta, 1e-12f);
  return 0.5f * (sqrt(1.0f + alpha * alpha * (1.0f - c2) / c2) - 1.0f);
}
VKMC_FN float smithG2(vec3 wo, vec3 wi, vec2 alpha) {
  return 1.0f / (1.0f + smithLambda(abs(wo.z), projectedAlpha(wo, alpha)) + smithLambda(abs(wi.z), projectedAlpha(wi, alpha)));
}

// Heitz 2018: a visible microfacet normal for view wo (upper hemisphere).
VKMC_FN vec3 sampleGgxVisibleNormal(vec3 wo, vec2 alpha, vec2 u) {
  vec3 vh = normalize(vec3(alpha.x * wo.x, alpha.y * wo.y, wo.z));
  float lensq = vh.x * vh.x + vh.y * vh.y;
  vec3 t1 = lensq > 0.0f ? vec3(-vh.y, vh.x, 0.0f) * inversesqrt(lensq) : vec3(1.0f, 0.0f, 0.0f);
  vec3 t2 = cross(vh, t1);
  float r = sqrt(u.x);
  float phi = 2.0f * kPi * u.y;
  float p1 = r * cos(phi);
  float p2 = r * sin(phi);
  float s = 0.5f * (1.0f + vh.z);
  p2 = (1.0f - s) * sqrt(max(0.0f, 1.0f - p1 * p1)) + s * p2;
  vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
  return normalize(vec3(alpha.x * nh.x, alpha.y * nh.y, max(0.0f, nh.z)));
}

// Density of the visible normal h for view wo: G1(wo) max(0, wo.h) D(h) / wo.z.
VKMC_FN float ggxVisibleNormalPdf(vec3 wo, vec3 h, vec2 alpha) {
  float woh = dot(wo, h);
  if (wo.z <= 0.0f || woh <= 0.0f || h.z <= 0.0f) return 0.0f;
  return smithG1(wo.z, projectedAlpha(wo, alpha)) * woh * ggxD(h, alpha) / wo.z;
}

// pdf of wi = reflect(-wo, h) with h from the visible normals: G1(wo) D(h) / (4 wo.z).
VKMC_FN float ggxReflectionPdf(vec3 wo, vec3 wi, vec2 alpha) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  vec3 h = normalize(wo + wi);
  return smithG1(wo.z, projectedAlpha(wo, alpha)) * ggxD(h, alpha) / (4.0f * wo.z);
}

// Refraction of wo about normal h (on wo's side) into the medium of relative index eta = n_t / n_i; false at total
// internal reflection.
VKMC_FN bool refractAbout(vec3 wo, vec3 h, float eta, INOUT(vec3) wi) {
  float cosI = dot(wo, h);
  float sin2T = max(0.0f, 1.0f - cosI * cosI) / (eta * eta);
  if (sin2T >= 1.0f) return false;
  float cosT = sqrt(1.0f - sin2T);
  wi = -wo / eta + (cosI / eta - cosT) * h;
  return true;
}

// The microfacet normal that refracts wo into wi (wi below, wo above; eta = n_t / n_i): Walter's generalized half
// vector, on the upper side; zero when no such facet faces both directions the right way.
VKMC_FN vec3 refractionHalfVector(vec3 wo, vec3 wi, float eta) {
  vec3 h = wo + eta * wi;
  float len2 = dot(h, h);
  if (!(len2 > 0.0f)) return vec3(0.0f);
  h *= inversesqrt(len2);
  if (h.z < 0.0f) h = -h;
  if (dot(h, wo) <= 0.0f || dot(h, wi) >= 0.0f) return vec3(0.0f);
  return h;
}

// d(h) / d(wi) for refraction: |wi.h| / (wi.h + wo.h / eta)^2, in pbrt-v4's form (eta^2 folded into the square).
VKMC_FN float refractionJacobian(vec3 wo, vec3 wi, vec3 h, float eta) {
  float d = dot(wi, h) + dot(wo, h) / eta;
  return abs(dot(wi, h)) / (d * d);
}

// A smooth-dielectric coat's reflection (KHR_materials_clearcoat: ior 1.5, f0 0.04): Schlick F(wo.h) D V.
VKMC_CONST float kCoatF0 = 0.04f;
VKMC_FN float coatReflectionEval(vec3 wo, vec3 wi, float alpha) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  vec3 h = normalize(wo + wi);
  return schlickFresnel(vec3(kCoatF0), 1.0f, dot(wo, h)).x * ggxD(h, vec2(alpha)) * smithVisibility(wi, wo, vec2(alpha));
}

VKMC_END_NAMESPACE
#endif
