// The glTF 2.0 metallic-roughness BRDF (spec appendix B) in the local shading frame (z = normal):
//   f = (1 - m) [ (1 - F_d) c / pi + F_d D V ] + m F_m D V
//   F_d = s (0.04 + 0.96 (1 - v.h)^5)            dielectric, s = KHR_materials_specular specularFactor
//   F_m = c + (1 - c) (1 - v.h)^5                metal, c = baseColor
//   D = GGX, V = height-correlated Smith G2 / (4 n.l n.v), alpha = roughness^2.
// Sampling: the specular lobe by GGX visible normals (Heitz 2018), the diffuse lobe by cosine; the lobe is
// chosen with a probability estimated from its weight at the outgoing direction. Each sampler has its pdf.
#ifndef VKMC_BSDF_GLTF_H
#define VKMC_BSDF_GLTF_H
#include "glsl_cpp.h"
#include "sampling.h"
VKMC_BEGIN_NAMESPACE

VKMC_CONST float kMinAlpha = 1e-4f;  // below this GGX is treated as this sharp (no delta lobes yet)

struct GltfMaterial {
  vec3 baseColor;
  float metallic;
  float alpha;
  float specular;
};

VKMC_FN GltfMaterial makeGltfMaterial(vec3 baseColor, float metallic, float roughness, float specular) {
  GltfMaterial m;
  m.baseColor = baseColor;
  m.metallic = clamp(metallic, 0.0f, 1.0f);
  m.alpha = max(roughness * roughness, kMinAlpha);
  m.specular = max(specular, 0.0f);
  return m;
}

// A shading normal ns (a normal map's, or interpolated normals near a silhouette) can mirror wo below the
// geometric surface, where the specular lobe's paths die black (the ring round a normal-mapped mirror). As
// Cycles' ensure_valid_specular_reflection does, ns is turned toward ng just enough that the mirror direction
// rises to t = min(0.9 wo.ng, 0.01) above the surface; here built as the half vector of wo and the mirror
// direction raised to height t in its own azimuth, so the change is continuous (ns itself at height t).
// Unit vectors, wo and ns on ng's side. A deterministic function of wo: the BSDF stays one function per vertex.
VKMC_FN vec3 normalForValidReflection(vec3 ng, vec3 wo, vec3 ns) {
  float woZ = dot(wo, ng);
  vec3 r = 2.0f * dot(ns, wo) * ns - wo;
  float t = min(0.9f * woZ, 0.01f);
  float rz = dot(r, ng);
  if (rz >= t || !(woZ > 0.0f)) return ns;
  vec3 across = r - rz * ng;
  float len = length(across);
  if (!(len > 1e-6f)) {  // r straight down ng: rise toward ns's own tilt, or any direction across ng
    across = ns - dot(ns, ng) * ng;
    len = length(across);
    if (!(len > 1e-6f)) {
      across = basisFromNormal(ng)[0];
      len = 1.0f;
    }
  }
  vec3 raised = across * (sqrt(1.0f - t * t) / len) + t * ng;
  return normalize(wo + raised);
}

VKMC_FN float pow5(float x) {
  float x2 = x * x;
  return x2 * x2 * x;
}

// GGX D from the half vector's local components: h.x^2 + h.y^2 instead of 1 - h.z^2 keeps tiny alphas exact.
VKMC_FN float ggxD(vec3 h, float alpha) {
  float a2 = alpha * alpha;
  float d = h.z * h.z * a2 + (h.x * h.x + h.y * h.y);
  return d > 0.0f ? a2 / (kPi * d * d) : 0.0f;
}

VKMC_FN float smithG1(float cosTheta, float alpha) {
  float a2 = alpha * alpha;
  return 2.0f * cosTheta / (cosTheta + sqrt(a2 + (1.0f - a2) * cosTheta * cosTheta));
}

// Height-correlated Smith G2 / (4 n.l n.v).
VKMC_FN float smithVisibility(float cosL, float cosV, float alpha) {
  float a2 = alpha * alpha;
  float gv = cosL * sqrt(cosV * cosV * (1.0f - a2) + a2);
  float gl = cosV * sqrt(cosL * cosL * (1.0f - a2) + a2);
  return 0.5f / (gv + gl);
}

VKMC_FN vec3 gltfBsdfEval(GltfMaterial m, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return vec3(0.0f);
  vec3 h = normalize(wo + wi);
  float vh = max(dot(wo, h), 0.0f);
  float fw = pow5(1.0f - vh);
  float fd = m.specular * (0.04f + 0.96f * fw);
  vec3 fm = m.baseColor + (vec3(1.0f) - m.baseColor) * fw;
  float dv = ggxD(h, m.alpha) * smithVisibility(wi.z, wo.z, m.alpha);
  vec3 dielectric = (1.0f - fd) * m.baseColor * kInvPi + vec3(fd * dv);
  return (1.0f - m.metallic) * dielectric + m.metallic * fm * dv;
}

// Probability of sampling the specular lobe, from each lobe's weight at normal incidence of the half vector.
VKMC_FN float gltfSpecularProbability(GltfMaterial m, vec3 wo) {
  float fw = pow5(1.0f - clamp(wo.z, 0.0f, 1.0f));
  float fd = m.specular * (0.04f + 0.96f * fw);
  vec3 fm = m.baseColor + (vec3(1.0f) - m.baseColor) * fw;
  float specular = (1.0f - m.metallic) * fd + m.metallic * luminance(fm);
  float diffuse = (1.0f - m.metallic) * (1.0f - fd) * luminance(m.baseColor);
  if (diffuse <= 0.0f) return specular > 0.0f ? 1.0f : 0.5f;
  if (specular <= 0.0f) return 0.0f;
  // Never starve a lobe whose value is non-zero: the pdf must cover the BRDF's support.
  return clamp(specular / (specular + diffuse), 0.02f, 0.98f);
}

// Heitz 2018: a visible microfacet normal for view wo (upper hemisphere).
VKMC_FN vec3 sampleGgxVisibleNormal(vec3 wo, float alpha, vec2 u) {
  vec3 vh = normalize(vec3(alpha * wo.x, alpha * wo.y, wo.z));
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
  return normalize(vec3(alpha * nh.x, alpha * nh.y, max(0.0f, nh.z)));
}

// pdf of wi = reflect(-wo, h) with h from the visible normals: G1(wo) D(h) / (4 wo.z).
VKMC_FN float ggxReflectionPdf(vec3 wo, vec3 wi, float alpha) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  vec3 h = normalize(wo + wi);
  return smithG1(wo.z, alpha) * ggxD(h, alpha) / (4.0f * wo.z);
}

VKMC_FN float gltfBsdfPdf(GltfMaterial m, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  float ps = gltfSpecularProbability(m, wo);
  return ps * ggxReflectionPdf(wo, wi, m.alpha) + (1.0f - ps) * cosineHemispherePdf(wi.z);
}

// u.x picks the lobe, u.yz the direction. Returns wi (local); its pdf is gltfBsdfPdf(m, wo, wi).
VKMC_FN vec3 sampleGltfBsdf(GltfMaterial m, vec3 wo, vec3 u) {
  if (u.x < gltfSpecularProbability(m, wo)) {
    vec3 h = sampleGgxVisibleNormal(wo, m.alpha, vec2(u.y, u.z));
    return 2.0f * dot(wo, h) * h - wo;
  }
  return sampleCosineHemisphere(vec2(u.y, u.z));
}

VKMC_END_NAMESPACE
#endif
