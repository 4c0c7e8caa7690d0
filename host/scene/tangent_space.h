// Tangent frames for normal mapping, generated where a glTF file has no TANGENT attribute (the spec asks
// for MikkTSpace).
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace vkmc {

// MikkTSpace's tangent frames (the reference implementation, third_party/mikktspace), as glTF asks: unit
// tangents (xyz) with the bitangent sign (w = +-1, bitangent = cross(normal, tangent) * w), one per corner of an
// indexed triangle list (3 indices per triangle, each < positions.size()), so vertices shared across a mirrored
// uv seam get each side's own frame, as MikkTSpace splits them. `normals` and `uvs` are per vertex; empty normals
// get area-weighted face normals. Corners MikkTSpace cannot give a frame (degenerate or missing uvs) get an
// arbitrary unit tangent perpendicular to their normal and w = 1. glTF's v runs down the image: the sign is the
// opposite of MikkTSpace's OpenGL one, so a normal map's green channel points up the image.
std::vector<glm::vec4> generateTangents(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                                        const std::vector<glm::vec2>& uvs, const std::vector<uint32_t>& triangles);

// Some unit vector perpendicular to unit vector n (Duff et al. 2017's branchless basis).
glm::vec3 anyPerpendicular(const glm::vec3& n);

}  // namespace vkmc
