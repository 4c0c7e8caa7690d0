// Per-vertex tangent frames for normal mapping, generated where a glTF file has no TANGENT attribute (the spec asks
// for MikkTSpace).
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace vkmc {

// Unit tangents (xyz) with the bitangent sign (w = +-1, bitangent = cross(normal, tangent) * w) for an indexed
// triangle list (3 indices per triangle, each < positions.size()). `normals` and `uvs` are per vertex; empty
// normals get area-weighted face normals. Vertices whose faces have degenerate UVs get an arbitrary unit tangent
// perpendicular to their normal and w = 1.
//
// MikkTSpace's essentials: per-face tangent and bitangent from the UV derivatives, each projected onto the vertex
// normal's plane and accumulated weighted by the corner angle, Gram-Schmidt against the vertex normal, the sign
// from the accumulated bitangent's handedness, with the bitangent -dP/dv because glTF's v runs down the image
// while the normal map's +Y points up it (the sign files written by MikkTSpace exporters carry). What differs from the reference MikkTSpace: it welds vertices by
// position, normal and UV and splits a vertex whose faces disagree in handedness into separate tangent spaces;
// here every indexed vertex gets exactly one tangent (mirrored UV seams that share a vertex average across the
// seam), and faces are not grouped by smoothing. Files with such shared-vertex mirror seams should ship TANGENT.
std::vector<glm::vec4> generateTangents(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                                        const std::vector<glm::vec2>& uvs, const std::vector<uint32_t>& triangles);

// Some unit vector perpendicular to unit vector n (Duff et al. 2017's branchless basis).
glm::vec3 anyPerpendicular(const glm::vec3& n);

}  // namespace vkmc
