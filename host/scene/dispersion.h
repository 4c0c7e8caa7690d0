// KHR_materials_dispersion as vkmc renders it: a volume's ior at the wavelengths that stand for the red, green and
// blue channels (a path past a dispersive interface carries one of them: shading.glsl takeSpectralChannel).
#pragma once
#include <glm/glm.hpp>

namespace vkmc {

// The channels' wavelengths (nm): near the sRGB primaries' dominant wavelengths.
inline constexpr float kChannelWavelengthsNm[3] = {630.0f, 532.0f, 465.0f};

// The ior at `nm` of a glass whose ior at the Fraunhofer d line (587.6 nm) is `ior`, with the extension's
// dispersion = 20 / Abbe number: Cauchy's n = A + B / lambda^2 through n_d, with n_F - n_C = (n_d - 1) / V (the
// Abbe number's definition, F 486.1 nm and C 656.3 nm), as the extension's notes suggest; at least 1, as the
// extension clamps it (a strong dispersion would otherwise take red below 1).
float iorAtWavelength(float ior, float dispersion, float nm);

// The three channels' iors.
glm::vec3 channelIors(float ior, float dispersion);

}  // namespace vkmc
