// KHR_materials_iridescence: the Fresnel term of a thin dielectric film over the base (Belcour and Barla 2017, in
// the approximation the extension's implementation notes give: phase shifts of 0 or pi, and the spectral integral
// done analytically in Fourier space with Gaussian fits of the CIE XYZ sensitivities; Schlick at the film-to-base
// interface, the exact dielectric equations at the outside-to-film one; the optical path through the film at its
// refracted angle).
// The film replaces F by mix(F, iridescentFresnel, iridescence); thicknesses in nanometres.
#ifndef VKMC_IRIDESCENCE_H
#define VKMC_IRIDESCENCE_H
#include "glsl_cpp.h"
#include "sampling.h"
VKMC_BEGIN_NAMESPACE

// The film's ior eases to the outside's below kFilmFadeNm, so a film of zero thickness is no film (the base's
// Fresnel), not a jump to a 0-nm film of a different ior.
VKMC_CONST float kFilmFadeNm = 30.0f;

VKMC_FN vec3 baseIorFromF0(vec3 f0) {
  vec3 s = sqrt(min(f0 + vec3(1e-4f), vec3(0.9999f)));  // the notes' guard against f0 = 1
  return (vec3(1.0f) + s) / (vec3(1.0f) - s);
}
VKMC_FN float f0FromIors(float transmitted, float incident) {
  float r = (transmitted - incident) / (transmitted + incident);
  return r * r;
}
VKMC_FN vec3 f0FromIors(vec3 transmitted, float incident) {
  vec3 r = (transmitted - vec3(incident)) / (transmitted + vec3(incident));
  return r * r;
}
// Unpolarized Fresnel reflectance of a dielectric step from n1 to n2 at cosine cos1 on n1's side: 0 where the
// indices match at every angle (Schlick's would rise toward grazing, and a film of the outside's ior would reflect).
VKMC_FN float dielectricFresnel(float n1, float n2, float cos1) {
  float sin2T = (n1 / n2) * (n1 / n2) * max(0.0f, 1.0f - cos1 * cos1);
  if (sin2T >= 1.0f) return 1.0f;
  float cos2 = sqrt(1.0f - sin2T);
  float rs = (n1 * cos1 - n2 * cos2) / (n1 * cos1 + n2 * cos2), rp = (n2 * cos1 - n1 * cos2) / (n2 * cos1 + n1 * cos2);
  return 0.5f * (rs * rs + rp * rp);
}
VKMC_FN vec3 schlick3(vec3 f0, float cosTheta) {
  float x = clamp(1.0f - cosTheta, 0.0f, 1.0f);
  float x2 = x * x;
  return f0 + (vec3(1.0f) - f0) * (x2 * x2 * x);
}

// The film's interference for an optical path difference (nm) and phase shift, integrated against the Gaussian fits
// of X, Y and Z and taken to linear Rec. 709 (the notes' evalSensitivity).
VKMC_FN vec3 filmSensitivity(float opd, vec3 shift) {
  float phase = 2.0f * kPi * opd * 1.0e-9f;
  vec3 val = vec3(5.4856e-13f, 4.4201e-13f, 5.2481e-13f);
  vec3 pos = vec3(1.6810e+06f, 1.7953e+06f, 2.2084e+06f);
  vec3 var = vec3(4.3278e+09f, 9.3046e+09f, 6.6121e+09f);
  vec3 xyz = val * sqrt(2.0f * kPi * var) * cos(pos * phase + shift) * exp(-(phase * phase) * var);
  xyz.x += 9.7470e-14f * sqrt(2.0f * kPi * 4.5282e+09f) * cos(2.2399e+06f * phase + shift.x) * exp(-4.5282e+09f * phase * phase);
  xyz /= 1.0685e-7f;
  return vec3(3.2404542f * xyz.x - 1.5371385f * xyz.y - 0.4985314f * xyz.z,
              -0.9692660f * xyz.x + 1.8760108f * xyz.y + 0.0415560f * xyz.z,
              0.0556434f * xyz.x - 0.2040259f * xyz.y + 1.0572252f * xyz.z);
}

// The film's reflectance for light arriving from a medium of outsideIor at cosine cosTheta1 to the facet, over a
// base whose reflectance at normal incidence is baseF0 (a dielectric's f0, or a metal's base colour).
VKMC_FN vec3 iridescentFresnel(float outsideIor, float filmIor, float cosTheta1, float thicknessNm, vec3 baseF0) {
  float ior = mix(outsideIor, filmIor, smoothstep(0.0f, kFilmFadeNm, thicknessNm));
  float sin2Theta2 = (outsideIor / ior) * (outsideIor / ior) * (1.0f - cosTheta1 * cosTheta1);
  if (sin2Theta2 >= 1.0f) return vec3(1.0f);  // total internal reflection at the film
  float cosTheta2 = sqrt(1.0f - sin2Theta2);
  // First interface (outside to film) by the dielectric Fresnel equations, second (film to base, a metal's ior
  // guessed from its f0 as the extension does) by Schlick.
  float r12 = dielectricFresnel(outsideIor, ior, cosTheta1);
  float t121 = 1.0f - r12;
  vec3 baseIor = baseIorFromF0(baseF0);
  vec3 r23 = schlick3(f0FromIors(baseIor, ior), cosTheta2);
  // Phase shifts: pi where light reflects off a lower ior.
  float phi12 = ior < outsideIor ? kPi : 0.0f;
  vec3 phi23 = vec3(baseIor.x < ior ? kPi : 0.0f, baseIor.y < ior ? kPi : 0.0f, baseIor.z < ior ? kPi : 0.0f);
  vec3 phi = vec3(kPi - phi12) + phi23;
  // The Airy sum: its mean (m = 0) and its first two harmonics.
  float opd = 2.0f * ior * thicknessNm * cosTheta2;
  vec3 r123 = clamp(r12 * r23, vec3(1e-5f), vec3(0.9999f));
  vec3 rs = t121 * t121 * r23 / (vec3(1.0f) - r123);
  vec3 reflectance = vec3(r12) + rs;
  vec3 cm = rs - vec3(t121);
  for (int m = 1; m <= 2; ++m) {
    cm *= sqrt(r123);
    reflectance += cm * 2.0f * filmSensitivity(float(m) * opd, float(m) * phi);
  }
  return clamp(reflectance, vec3(0.0f), vec3(1.0f));
}

VKMC_END_NAMESPACE
#endif
