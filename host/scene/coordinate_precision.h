// Whether a scene's coordinates are too large for float hit points at the scale of its own detail. A hit point
// interpolated from a triangle's vertices errs by about gamma(7) |v| (pbrt's bound), and the watertight test cannot
// tell a hit closer than about gamma times the triangle's size from the ray's origin (it reports a miss). A unit
// lamp beside a ground of half-size 1e5 renders as beside a small one; at 1e6 its mean is 26% low, and from 1e7
// the ground's far half is missed (tests/cli/cli_outputs_test.cpp, AGroundOfAnySize...). The loader accepts
// coordinates to +-1e11 (kMaxSceneCoordinate: beyond, float ray tests overflow); between, this says when shading
// is unreliable.
#pragma once
#include <optional>
#include <string>

#include "scene/scene.h"

namespace vkmc {

// The scale: the largest vertex coordinate or triangle extent over the small triangles' size (the 10th percentile
// of the triangles' longest edges, so that slivers do not set it). Above kPrecisionScaleLimit shading at the small
// triangles' size is unreliable.
inline constexpr double kPrecisionScaleLimit = 1e6;
double coordinateScale(const Scene& scene);

// One warning line where the scale passes the limit; nothing otherwise.
std::optional<std::string> coordinatePrecisionWarning(const Scene& scene);

}  // namespace vkmc
