// The back-face rule's camera half: a single-sided triangle the camera looks through is not in the scene for that
// render, for any ray. A viewer culls a face seen from behind; a path tracer that only culled it for the eye would
// show a room through its outer wall while the wall still kept the light out (docs/manual/scenes.md, "Single-sided
// faces"). Removed for every ray, the faces the eye passes let light pass too, the open dollhouse a viewer shows.
// A closed solid keeps every face: a camera ray meets its front before any back.
#pragma once
#include <cstdint>

#include "scene/scene.h"

namespace vkmc {

// The most camera rays across the image's longer side that look for such faces (a pixel-centre grid, scaled down
// from the image where it is larger): a face smaller than the grid's spacing can stay.
constexpr uint32_t kSeenThroughRaysAcross = 512;

struct SeenThrough {
  uint64_t triangles = 0;  // removed
  uint64_t rays = 0;       // camera rays cast to find them
};

// Removes every single-sided, non-emissive triangle (Material::culledFromBehind) that some camera ray meets from
// behind before the first surface the kernels' camera ray stops at (a front face, or a face of a two-sided or
// transmissive material). Single-sided emitters are passed from behind, as the kernels pass them, but stay: a lamp
// panel seen from behind still lights the room. The rays go through the centres of a grid over the image's field
// of view (width x height pixels, fewer where larger). Nothing is removed where everything would be (the eye sees
// only backs: the culled faces already show it the backdrop), nor in an alpha-tested face's cut-outs (a front face
// stops the walk wherever its texture would let the kernels' ray through).
// Scene::bounds is left as it was, a superset of what remains (the distant lights' disc and EARS's grid stay valid).
SeenThrough removeSeenThroughFaces(Scene& scene, const Camera& camera, uint32_t width, uint32_t height);

}  // namespace vkmc
