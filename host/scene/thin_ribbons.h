// glTF points and lines as geometry a path tracer can hit: once the camera and the image are known, every segment
// becomes a ribbon one pixel wide facing the camera (a point: a square one pixel across), as a rasterizer
// draws them with its default width and size.
#pragma once
#include <cstdint>

#include "scene/scene.h"

namespace vkmc {

// Appends two triangles per Scene::thinSegments entry (then clears the list): width one pixel at each end's
// distance from `camera` for an image `height` pixels high, facing the camera, shading normal the face's. Ribbons
// of zero area are counted in degenerateTriangles. Returns how many segments were drawn.
uint64_t addThinRibbons(Scene& scene, const Camera& camera, uint32_t height);

}  // namespace vkmc
