// KHR_lights_punctual lights seen from a shading point: direction, shadow-ray length and the irradiance they
// deliver at normal incidence. Delta lights: reached by next-event estimation only, never by BSDF sampling.
#ifndef VKMC_PUNCTUAL_LIGHT_H
#define VKMC_PUNCTUAL_LIGHT_H
#include "glsl_cpp.h"
#include "layout.h"
#include "sampling.h"
VKMC_BEGIN_NAMESPACE

// The spec's smooth cone (KHR_lights_punctual appendix): linear in cos between the outer and inner cone, squared.
VKMC_FN float spotFalloff(float cosAngle, float cosOuter, float cosInner) {
  if (!(cosInner > cosOuter)) return cosAngle >= cosOuter ? 1.0f : 0.0f;
  float t = clamp((cosAngle - cosOuter) / (cosInner - cosOuter), 0.0f, 1.0f);
  return t * t;
}

struct PunctualLightSample {
  vec3 wi;          // unit direction from the shading point to the light
  float distance;   // length of the shadow ray (directional: past the scene's bounding sphere)
  vec3 irradiance;  // at normal incidence: I falloff / d^2 (point, spot) or E (directional)
};

VKMC_FN PunctualLightSample samplePunctualLight(PunctualLight light, vec3 p) {
  PunctualLightSample s;
  if (light.kind == kPunctualDirectional) {
    s.wi = -vec3(light.direction);
    s.distance = length(p - vec3(light.position)) + 2.0f * light.position.w;
    s.irradiance = vec3(light.intensity);
    return s;
  }
  vec3 d = vec3(light.position) - p;
  float dist2 = dot(d, d);
  s.distance = sqrt(dist2);
  s.wi = s.distance > 0.0f ? d / s.distance : vec3(0.0f, 0.0f, 1.0f);
  float falloff = 1.0f;
  if (light.kind == kPunctualSpot) falloff = spotFalloff(dot(-s.wi, vec3(light.direction)), light.cosOuter, light.cosInner);
  s.irradiance = dist2 > 0.0f ? vec3(light.intensity) * (falloff / dist2) : vec3(0.0f);
  return s;
}

// The spot's intensity integrated over the sphere, over I: 2 pi (1 - cosInner + (cosInner - cosOuter) / 3),
// exact for the falloff above (the square of a linear ramp in cos integrates to a third of the ramp's width).
VKMC_FN float spotSolidAngleFactor(float cosOuter, float cosInner) {
  return 2.0f * kPi * (1.0f - cosInner + (cosInner - cosOuter) / 3.0f);
}

VKMC_END_NAMESPACE
#endif
