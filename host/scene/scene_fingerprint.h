// The identity of a loaded scene, as a render sees it: geometry, attributes, materials, textures, cameras, lights
// and the environment. A checkpoint records it so that a resumed render refuses a scene that changed since.
#pragma once
#include <cstdint>

#include "scene/scene.h"

namespace vkmc {

uint64_t sceneFingerprint(const Scene& scene);

}  // namespace vkmc
