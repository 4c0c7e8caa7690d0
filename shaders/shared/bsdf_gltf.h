// The glTF 2.0 material as one layered BSDF in the local shading frame (z = normal, wo above):
//   f = coat + (1 - cc E_c) [ sheen + (1 - s E_s) base ]                 KHR_materials_clearcoat, _sheen
//   base = (1 - m) [ (1 - T) (1 - F) c / pi + F D V + T c (1 - F) btdf ] + m F_m D V
//   F = Schlick(f0, f90 = specularFactor) with f0 = min(((ior - 1) / (ior + 1))^2 specularColor, 1) specularFactor
//   F_m = c + (1 - c) (1 - v.h)^5, D = GGX, V = height-correlated Smith G2 / (4 n.l n.v), alpha = roughness^2;
//   KHR_materials_anisotropy stretches alpha along the local x axis (the shading frame's anisotropy direction).
// The coat and sheen scale what lies under them by one minus their directional albedo E (tabulated, bounded from
// above: layer_albedo.h), the smaller of wo's and wi's so f stays reciprocal. The transmission btdf is Walter et
// al. 2007's rough dielectric (volumetric: it refracts with eta) or, thin-walled (no KHR_materials_volume),
// GGX reflection mirrored through the surface, so light passes without bending. Radiance crossing into a medium
// of relative index eta is scaled by 1 / eta^2 (pbrt-v4's convention).
// Below kDeltaAlpha the base interface (and the coat) are delta lobes: sampled exactly, never evaluated; the
// diffuse under a smooth interface is then weighted by Fresnel in and out, (1 - F(wo.n)) (1 - F(wi.n)), so
// delta reflection plus diffuse stays <= 1. Sampling: a lobe chosen with probabilities from its weight at wo,
// GGX visible normals (Heitz 2018) for the interface and the coat, cosine for diffuse and sheen; the interface
// reflects or transmits with probabilities from its Fresnel at the sampled normal. Every sampler has its pdf.
#ifndef VKMC_BSDF_GLTF_H
#define VKMC_BSDF_GLTF_H
#include "glsl_cpp.h"
#include "layer_albedo.h"
#include "microfacet.h"
#include "sampling.h"
#include "iridescence.h"
#include "sheen.h"
VKMC_BEGIN_NAMESPACE

struct GltfMaterial {
  vec3 baseColor;
  float metallic;
  vec2 alpha;          // GGX alphas of the base's specular and transmission along local x and y; deltas below kDeltaAlpha
  float specular;      // KHR_materials_specular specularFactor: the dielectric's f90
  vec3 f0;             // the dielectric's reflectance at normal incidence (specularFactor included)
  float transmission;  // KHR_materials_transmission
  float eta;           // volumetric transmission: n(the side wi enters) / n(wo's side); 1 thin-walled or opaque
  bool thinWalled;     // transmission without KHR_materials_volume: straight through, no refraction
  float clearcoat;
  float clearcoatAlpha;
  vec3 clearcoatNormal;  // local frame
  vec3 sheenColor;
  float sheenAlpha;
  float iridescence;           // KHR_materials_iridescence: the film's weight in the Fresnel terms (0: no film)
  float iridescenceIor;        // the film's
  float iridescenceThickness;  // nm
  float iridescenceOutside;    // the ior above the film: the clearcoat's where there is one
};

VKMC_FN bool isDeltaAlpha(float alpha) { return alpha < kDeltaAlpha; }
VKMC_FN bool isDeltaAlpha(vec2 alpha) { return max(alpha.x, alpha.y) < kDeltaAlpha; }  // pbrt-v4's EffectivelySmooth

VKMC_FN GltfMaterial makeGltfMaterial(vec3 baseColor, float metallic, float roughness, float specular) {
  GltfMaterial m;
  m.baseColor = baseColor;
  m.metallic = clamp(metallic, 0.0f, 1.0f);
  m.alpha = vec2(roughness * roughness);
  m.specular = max(specular, 0.0f);
  m.f0 = vec3(0.04f * m.specular);  // ior 1.5
  m.transmission = 0.0f;
  m.eta = 1.0f;
  m.thinWalled = true;
  m.clearcoat = 0.0f;
  m.clearcoatAlpha = 1.0f;
  m.clearcoatNormal = vec3(0.0f, 0.0f, 1.0f);
  m.sheenColor = vec3(0.0f);
  m.sheenAlpha = 1.0f;
  m.iridescence = 0.0f;
  m.iridescenceIor = 1.3f;
  m.iridescenceThickness = 0.0f;
  m.iridescenceOutside = 1.0f;
  return m;
}

// KHR_materials_ior and _specular's colour: f0 = min(((ior - 1) / (ior + 1))^2 specularColor, 1) specularFactor.
VKMC_FN void setIor(INOUT(GltfMaterial) m, float ior, vec3 specularColor) {
  float r = (ior - 1.0f) / (ior + 1.0f);
  m.f0 = min(vec3(r * r) * specularColor, vec3(1.0f)) * m.specular;
}

// KHR_materials_transmission; eta = n(inside) / n(outside) seen from wo's side (1 / ior on a back face) when
// volumetric, ignored when thin-walled.
VKMC_FN void setTransmission(INOUT(GltfMaterial) m, float transmission, float eta, bool thinWalled) {
  m.transmission = clamp(transmission, 0.0f, 1.0f);
  m.thinWalled = thinWalled;
  m.eta = thinWalled ? 1.0f : eta;
}

// KHR_materials_anisotropy: alpha along the anisotropy direction (local x) mix(alpha, 1, strength^2), across it
// alpha (the extension's alphaT and alphaB).
// A rough lobe keeps both alphas at least 1e-4 (pbrt-v4's clamp): a smooth base made rough along one axis would
// otherwise divide by alpha.y = 0 in D and in its visible normals (NaN samples).
VKMC_FN void setAnisotropy(INOUT(GltfMaterial) m, float strength) {
  float s = clamp(strength, 0.0f, 1.0f);
  m.alpha.x = mix(m.alpha.y, 1.0f, s * s);
  if (!isDeltaAlpha(m.alpha)) m.alpha = max(m.alpha, vec2(1e-4f));
}

VKMC_FN void setClearcoat(INOUT(GltfMaterial) m, float clearcoat, float roughness, vec3 normal) {
  m.clearcoat = clamp(clearcoat, 0.0f, 1.0f);
  m.clearcoatAlpha = roughness * roughness;
  m.clearcoatNormal = normal;
}

VKMC_FN void setSheen(INOUT(GltfMaterial) m, vec3 color, float roughness) {
  m.sheenColor = clamp(color, vec3(0.0f), vec3(1.0f));
  m.sheenAlpha = max(roughness * roughness, kMinSheenAlpha);
}

// KHR_materials_iridescence, after the clearcoat: under a coat the film's outside is the coat's ior 1.5 (the
// extension's rule), blended by the coat's factor.
VKMC_FN void setIridescence(INOUT(GltfMaterial) m, float iridescence, float ior, float thicknessNm) {
  m.iridescence = clamp(iridescence, 0.0f, 1.0f);
  m.iridescenceIor = max(ior, 1.0f);
  m.iridescenceThickness = max(thicknessNm, 0.0f);
  m.iridescenceOutside = mix(1.0f, 1.5f, m.clearcoat);
}

// The film's Fresnel mixed into a base's: F = mix(F, strength x iridescentFresnel(baseF0), iridescence), strength
// the dielectric's specularFactor (its f90) or 1 for the metal. cosTheta is in air; under a coat it is carried into
// the coat (Snell) before the film, whose outside the coat is.
VKMC_FN vec3 withFilm(GltfMaterial m, vec3 f, vec3 baseF0, float cosTheta, float strength) {
  if (m.iridescence <= 0.0f) return f;
  float n = m.iridescenceOutside;
  float cosOutside = sqrt(max(0.0f, 1.0f - max(0.0f, 1.0f - cosTheta * cosTheta) / (n * n)));
  vec3 film = iridescentFresnel(n, m.iridescenceIor, cosOutside, m.iridescenceThickness, baseF0);
  return mix(f, strength * film, m.iridescence);
}

// The metal's Fresnel: Schlick on the base colour, under the film where there is one.
VKMC_FN vec3 metalFresnel(GltfMaterial m, float cosTheta) {
  return withFilm(m, schlickFresnel(m.baseColor, 1.0f, cosTheta), m.baseColor, cosTheta, 1.0f);
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

// Fresnel of the base's dielectric interface for wo at cosine cosO to the facet: Schlick on the cosine in the
// outer medium; from inside a volume that is the refracted one, and past the critical angle all is reflected.
VKMC_FN vec3 interfaceFresnel(GltfMaterial m, float cosO) {
  float c = cosO;
  if (m.eta < 1.0f) {
    float sin2T = max(0.0f, 1.0f - c * c) / (m.eta * m.eta);
    if (sin2T >= 1.0f) return vec3(1.0f);
    c = sqrt(1.0f - sin2T);
  }
  return withFilm(m, schlickFresnel(m.f0, m.specular, c), m.f0, c, min(m.specular, 1.0f));
}

// What the coat and sheen leave to the layers under them for the pair (wo, wi): one minus weight x albedo, the
// smaller of the two directions'.
VKMC_FN float coatTransmittance(GltfMaterial m, vec3 wo, vec3 wi) {
  if (m.clearcoat <= 0.0f) return 1.0f;
  vec3 n = m.clearcoatNormal;
  float e = max(layerAlbedo(kLayerAlbedoCoat, dot(wo, n), m.clearcoatAlpha),
                layerAlbedo(kLayerAlbedoCoat, abs(dot(wi, n)), m.clearcoatAlpha));
  return 1.0f - m.clearcoat * e;
}
VKMC_FN float sheenTransmittance(GltfMaterial m, vec3 wo, vec3 wi) {
  float s = maxComponent(m.sheenColor);
  if (s <= 0.0f) return 1.0f;
  return 1.0f -
         s * max(layerAlbedo(kLayerAlbedoSheen, wo.z, m.sheenAlpha), layerAlbedo(kLayerAlbedoSheen, abs(wi.z), m.sheenAlpha));
}

// The base's reflection without its delta lobes: diffuse, and the dielectric and metal specular when rough.
VKMC_FN vec3 baseReflectionEval(GltfMaterial m, vec3 wo, vec3 wi) {
  vec3 h = normalize(wo + wi);
  float vh = max(dot(wo, h), 0.0f);
  vec3 fd = interfaceFresnel(m, vh);
  bool isSmooth = isDeltaAlpha(m.alpha);
  vec3 diffuseWeight =
      isSmooth ? (vec3(1.0f) - interfaceFresnel(m, wo.z)) * (vec3(1.0f) - interfaceFresnel(m, wi.z)) : vec3(1.0f) - fd;
  vec3 f = ((1.0f - m.metallic) * (1.0f - m.transmission) * kInvPi) * diffuseWeight * m.baseColor;
  if (!isSmooth) {
    float dv = ggxD(h, m.alpha) * smithVisibility(wi, wo, m.alpha);
    vec3 fm = metalFresnel(m, vh);
    f += ((1.0f - m.metallic) * fd + m.metallic * fm) * dv;
  }
  return f;
}

// The base's rough transmission (wi below): Walter's btdf, or thin-walled the GGX reflection mirrored through
// the surface; both tinted by the base colour.
VKMC_FN vec3 baseTransmissionEval(GltfMaterial m, vec3 wo, vec3 wi) {
  vec3 tint = ((1.0f - m.metallic) * m.transmission) * m.baseColor;
  if (m.thinWalled) {
    vec3 wr = vec3(wi.x, wi.y, -wi.z);
    vec3 h = normalize(wo + wr);
    return tint * (vec3(1.0f) - interfaceFresnel(m, dot(wo, h))) * (ggxD(h, m.alpha) * smithVisibility(wr, wo, m.alpha));
  }
  vec3 h = refractionHalfVector(wo, wi, m.eta);
  if (h == vec3(0.0f)) return vec3(0.0f);
  float d = dot(wi, h) + dot(wo, h) / m.eta;
  float value = ggxD(h, m.alpha) * smithG2(wo, wi, m.alpha) * abs(dot(wi, h) * dot(wo, h) / (d * d * wi.z * wo.z));
  return tint * (vec3(1.0f) - interfaceFresnel(m, dot(wo, h))) * (value / (m.eta * m.eta));
}

// The BSDF without its delta lobes, for wo above and wi anywhere.
VKMC_FN vec3 gltfBsdfEval(GltfMaterial m, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z == 0.0f) return vec3(0.0f);
  float coatT = coatTransmittance(m, wo, wi);
  float layers = coatT * sheenTransmittance(m, wo, wi);
  if (wi.z < 0.0f) {
    bool transmits = m.transmission > 0.0f && m.metallic < 1.0f && !isDeltaAlpha(m.alpha);
    return transmits ? layers * baseTransmissionEval(m, wo, wi) : vec3(0.0f);
  }
  vec3 f = layers * baseReflectionEval(m, wo, wi);
  if (maxComponent(m.sheenColor) > 0.0f) f += (coatT * sheenEval(wo, wi, m.sheenAlpha)) * m.sheenColor;
  if (m.clearcoat > 0.0f && !isDeltaAlpha(m.clearcoatAlpha)) {
    mat3 frame = basisFromNormal(m.clearcoatNormal);
    f += vec3(m.clearcoat * coatReflectionEval(wo * frame, wi * frame, m.clearcoatAlpha));
  }
  return f;
}

// Lobe-selection probabilities at wo, from each lobe's weight there; a lobe that can contribute keeps at least
// 2% of the total, so the pdf covers the BSDF's support.
struct LobeProbabilities {
  float coat, sheen, specular, diffuse;  // specular: the base's interface (reflection and transmission)
};

VKMC_FN LobeProbabilities lobeProbabilities(GltfMaterial m, vec3 wo) {
  LobeProbabilities p;
  float cosCoat = dot(wo, m.clearcoatNormal);
  p.coat = m.clearcoat > 0.0f && cosCoat > 0.0f ? m.clearcoat * schlickFresnel(vec3(kCoatF0), 1.0f, cosCoat).x : 0.0f;
  float under = 1.0f - p.coat;
  p.sheen = under * luminance(m.sheenColor) * layerAlbedo(kLayerAlbedoSheen, wo.z, m.sheenAlpha);
  float base = under * sheenTransmittance(m, wo, wo);
  float f = luminance(interfaceFresnel(m, wo.z));
  float c = luminance(m.baseColor);
  p.specular =
      base * ((1.0f - m.metallic) * (f + m.transmission * (1.0f - f) * c) + m.metallic * luminance(metalFresnel(m, wo.z)));
  p.diffuse = base * (1.0f - m.metallic) * (1.0f - m.transmission) * (1.0f - f) * c;
  float total = p.coat + p.sheen + p.specular + p.diffuse;
  if (!(total > 0.0f)) return p;
  float least = 0.02f * total;
  if (p.coat > 0.0f) p.coat = max(p.coat, least);
  if (p.sheen > 0.0f) p.sheen = max(p.sheen, least);
  if (p.specular > 0.0f) p.specular = max(p.specular, least);
  if (p.diffuse > 0.0f) p.diffuse = max(p.diffuse, least);
  total = p.coat + p.sheen + p.specular + p.diffuse;
  p.coat /= total;
  p.sheen /= total;
  p.specular /= total;
  p.diffuse /= total;
  return p;
}

// Probability that the interface reflects (rather than transmits) about facet normal h.
VKMC_FN float reflectProbability(GltfMaterial m, vec3 wo, vec3 h) {
  if (m.transmission <= 0.0f || m.metallic >= 1.0f) return 1.0f;
  float vh = dot(wo, h);
  vec3 fd = interfaceFresnel(m, vh);
  float r = luminance((1.0f - m.metallic) * fd + m.metallic * metalFresnel(m, vh));
  float t = luminance(((1.0f - m.metallic) * m.transmission) * (vec3(1.0f) - fd) * m.baseColor);
  return r + t > 0.0f ? r / (r + t) : 1.0f;
}

// Density of the rough interface's sampling (visible normals, then reflect or transmit) at wi.
VKMC_FN float interfacePdf(GltfMaterial m, vec3 wo, vec3 wi) {
  if (wi.z > 0.0f) return reflectProbability(m, wo, normalize(wo + wi)) * ggxReflectionPdf(wo, wi, m.alpha);
  if (m.transmission <= 0.0f || m.metallic >= 1.0f) return 0.0f;
  if (m.thinWalled) {
    vec3 wr = vec3(wi.x, wi.y, -wi.z);
    return (1.0f - reflectProbability(m, wo, normalize(wo + wr))) * ggxReflectionPdf(wo, wr, m.alpha);
  }
  vec3 h = refractionHalfVector(wo, wi, m.eta);
  if (h == vec3(0.0f)) return 0.0f;
  return (1.0f - reflectProbability(m, wo, h)) * ggxVisibleNormalPdf(wo, h, m.alpha) * refractionJacobian(wo, wi, h, m.eta);
}

// The density of sampleGltfBsdf's non-delta directions (the delta lobes' choices carry no density).
VKMC_FN float gltfBsdfPdf(GltfMaterial m, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z == 0.0f) return 0.0f;
  LobeProbabilities p = lobeProbabilities(m, wo);
  float pdf = 0.0f;
  if (wi.z > 0.0f) {
    pdf += (p.sheen + p.diffuse) * cosineHemispherePdf(wi.z);
    if (p.coat > 0.0f && !isDeltaAlpha(m.clearcoatAlpha)) {
      mat3 frame = basisFromNormal(m.clearcoatNormal);
      pdf += p.coat * ggxReflectionPdf(wo * frame, wi * frame, vec2(m.clearcoatAlpha));
    }
  }
  if (p.specular > 0.0f && !isDeltaAlpha(m.alpha)) pdf += p.specular * interfacePdf(m, wo, wi);
  return pdf;
}

// A sampled direction: weight = f |cos| / pdf; pdf is the non-delta density (for MIS), 0 for a delta lobe, whose
// weight is its value over the probability of having chosen it. A zero weight ends the path.
struct BsdfSample {
  vec3 wi;
  vec3 weight;
  float pdf;
  bool delta;
};

VKMC_FN BsdfSample deltaSample(vec3 wi, vec3 weight) {
  BsdfSample s;
  s.wi = wi;
  s.weight = weight;
  s.pdf = 0.0f;
  s.delta = true;
  return s;
}

// The smooth interface: mirror reflection or transmission (refracted, or straight through thin-walled), chosen by
// their Fresnel weights with x; pLobe is the probability of having picked the interface.
VKMC_FN BsdfSample sampleSmoothInterface(GltfMaterial m, vec3 wo, float x, float pLobe) {
  vec3 fd = interfaceFresnel(m, wo.z);
  vec3 r = (1.0f - m.metallic) * fd + m.metallic * metalFresnel(m, wo.z);
  vec3 t = ((1.0f - m.metallic) * m.transmission) * (vec3(1.0f) - fd) * m.baseColor;
  float pr = luminance(r) + luminance(t) > 0.0f ? luminance(r) / (luminance(r) + luminance(t)) : 1.0f;
  vec3 wi = vec3(-wo.x, -wo.y, wo.z);
  if (x < pr) return deltaSample(wi, r * (coatTransmittance(m, wo, wi) * sheenTransmittance(m, wo, wi) / (pLobe * pr)));
  float eta = 1.0f;
  if (m.thinWalled) {
    wi = -wo;
  } else {
    eta = m.eta;
    if (!refractAbout(wo, vec3(0.0f, 0.0f, 1.0f), eta, wi)) return deltaSample(wi, vec3(0.0f));
  }
  float layers = coatTransmittance(m, wo, wi) * sheenTransmittance(m, wo, wi);
  return deltaSample(wi, t * (layers / (pLobe * (1.0f - pr) * eta * eta)));
}

// u.x picks the lobe (and, rescaled, reflection or transmission), u.yz the direction.
VKMC_FN BsdfSample sampleGltfBsdf(GltfMaterial m, vec3 wo, vec3 u) {
  BsdfSample s = deltaSample(vec3(0.0f), vec3(0.0f));
  s.delta = false;
  if (wo.z <= 0.0f) return s;
  LobeProbabilities p = lobeProbabilities(m, wo);
  vec2 v = vec2(u.y, u.z);
  float x = u.x;
  vec3 wi;
  if (x < p.coat) {
    mat3 frame = basisFromNormal(m.clearcoatNormal);
    vec3 woC = wo * frame;
    vec3 h = isDeltaAlpha(m.clearcoatAlpha) ? vec3(0.0f, 0.0f, 1.0f) : sampleGgxVisibleNormal(woC, vec2(m.clearcoatAlpha), v);
    wi = frame * (2.0f * dot(woC, h) * h - woC);
    if (isDeltaAlpha(m.clearcoatAlpha)) {
      float f = m.clearcoat * schlickFresnel(vec3(kCoatF0), 1.0f, woC.z).x;
      return deltaSample(wi, vec3(wi.z > 0.0f ? f / p.coat : 0.0f));
    }
    if (wi.z <= 0.0f) return s;  // below the base: the coat has no density there (gltfBsdfPdf)
  } else if (x < p.coat + p.sheen + p.specular && x >= p.coat + p.sheen) {
    float xr = (x - p.coat - p.sheen) / p.specular;
    if (isDeltaAlpha(m.alpha)) return sampleSmoothInterface(m, wo, xr, p.specular);
    vec3 h = sampleGgxVisibleNormal(wo, m.alpha, v);
    wi = 2.0f * dot(wo, h) * h - wo;
    bool reflects = xr < reflectProbability(m, wo, h);
    if (wi.z <= 0.0f && (reflects || m.thinWalled)) return s;  // a reflection below the surface: no density there
    if (!reflects) {
      if (m.thinWalled)
        wi.z = -wi.z;
      else if (!refractAbout(wo, h, m.eta, wi) || wi.z >= 0.0f)
        return s;
    }
  } else {
    wi = sampleCosineHemisphere(v);  // the sheen and the diffuse lobe
  }
  s.wi = wi;
  s.pdf = gltfBsdfPdf(m, wo, wi);
  if (s.pdf > 0.0f) s.weight = gltfBsdfEval(m, wo, wi) * (abs(wi.z) / s.pdf);
  return s;
}

VKMC_END_NAMESPACE
#endif
