// The studio (`--environment studio`, and the world of a file that declares none): a neutral photographic studio as an
// equirectangular map of radiance, built here (no file): a grey cyclorama darker below the horizon than above, a large key
// softbox above and to the front left of the default camera's view, a dimmer fill to its right, and a rim light behind. Lit by
// it, a model shows its shape and materials as in a model viewer; the camera sees it against a grey backdrop.
#pragma once
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace vkmc {

constexpr const char* kStudioEnvironment = "studio";  // the --environment value that names it

// 128 x 64 texels, in the equirectangular convention of --environment (+Y up, the centre column looking along -Z,
// u growing toward +X); radiance between 0.2 (the floor) and 6 (the key).
EnvironmentMap studioEnvironment();
// The direction of texel (x, y)'s centre in that convention.
glm::vec3 equirectangularDirection(uint32_t x, uint32_t y, uint32_t width, uint32_t height);

}  // namespace vkmc
