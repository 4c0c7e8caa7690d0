// What the automatic camera frames: the scene's bounds, less a huge flat ground. A ground or water plane many times
// wider than everything standing on it (100-400 m under a 2 m model, in real files) would otherwise shrink the
// subject to a few pixels; viewers frame the subject.
#pragma once
#include "scene/scene.h"

namespace vkmc {

// The ground: triangles facing up or down (|normal.y| > kGroundFlatness) below the middle of the rest (flat ones
// above it, a roof or a canopy, count with the rest). It is left out when leaving it out
// shrinks the bounds' horizontal extent more than kGroundShrink times; otherwise (or when nothing else is left),
// the bounds are the whole scene's, points and lines included.
constexpr float kGroundFlatness = 0.98f;
constexpr float kGroundShrink = 8.0f;

struct FramedBounds {
  Aabb bounds;
  bool groundLeftOut = false;
};
FramedBounds framingBounds(const Scene& scene);

}  // namespace vkmc
