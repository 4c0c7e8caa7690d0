#include "scene/dispersion.h"

#include <algorithm>

namespace vkmc {

float iorAtWavelength(float ior, float dispersion, float nm) {
  if (!(dispersion > 0.0f)) return ior;
  const double abbe = 20.0 / double(dispersion);
  const double f = 486.1, c = 656.3, d = 587.6;
  const double b = (double(ior) - 1.0) / (abbe * (1.0 / (f * f) - 1.0 / (c * c)));
  return float(std::max(1.0, double(ior) + b * (1.0 / (double(nm) * nm) - 1.0 / (d * d))));  // the extension's clamp
}

glm::vec3 channelIors(float ior, float dispersion) {
  glm::vec3 out;
  for (int i = 0; i < 3; ++i) out[i] = iorAtWavelength(ior, dispersion, kChannelWavelengthsNm[i]);
  return out;
}

}  // namespace vkmc
