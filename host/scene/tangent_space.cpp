// Tangent generation in the manner of MikkTSpace (see tangent_space.h for what differs).
#include "scene/tangent_space.h"

#include <cmath>

namespace vkmc {
namespace {

bool usable(const glm::vec3& v) {
  float l = glm::dot(v, v);
  return l > 1e-30f && std::isfinite(l);
}

glm::vec3 projectOnPlane(const glm::vec3& v, const glm::vec3& n) { return v - n * glm::dot(n, v); }

float cornerAngle(const glm::vec3& a, const glm::vec3& b) {
  if (!usable(a) || !usable(b)) return 0.0f;
  float c = glm::dot(glm::normalize(a), glm::normalize(b));
  return std::acos(glm::clamp(c, -1.0f, 1.0f));
}

std::vector<glm::vec3> faceNormals(const std::vector<glm::vec3>& p, const std::vector<uint32_t>& tri) {
  std::vector<glm::vec3> n(p.size(), glm::vec3(0.0f));
  for (size_t t = 0; t + 2 < tri.size(); t += 3) {
    glm::vec3 c = glm::cross(p[tri[t + 1]] - p[tri[t]], p[tri[t + 2]] - p[tri[t]]);  // area weighted
    for (int k = 0; k < 3; ++k) n[tri[t + k]] += c;
  }
  for (glm::vec3& v : n) v = usable(v) ? glm::normalize(v) : glm::vec3(0.0f, 0.0f, 1.0f);
  return n;
}

}  // namespace

glm::vec3 anyPerpendicular(const glm::vec3& n) {
  float sign = std::copysign(1.0f, n.z);
  float a = -1.0f / (sign + n.z), b = n.x * n.y * a;
  return glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
}

std::vector<glm::vec4> generateTangents(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normalsIn,
                                        const std::vector<glm::vec2>& uvs, const std::vector<uint32_t>& tri) {
  const std::vector<glm::vec3> normals = normalsIn.size() == positions.size() ? normalsIn : faceNormals(positions, tri);
  std::vector<glm::vec3> tangentSum(positions.size(), glm::vec3(0.0f)), bitangentSum(positions.size(), glm::vec3(0.0f));
  for (size_t t = 0; t + 2 < tri.size() && uvs.size() == positions.size(); t += 3) {
    const uint32_t v[3] = {tri[t], tri[t + 1], tri[t + 2]};
    glm::vec3 e1 = positions[v[1]] - positions[v[0]], e2 = positions[v[2]] - positions[v[0]];
    glm::vec2 d1 = uvs[v[1]] - uvs[v[0]], d2 = uvs[v[2]] - uvs[v[0]];
    float det = d1.x * d2.y - d2.x * d1.y;
    if (!(std::abs(det) > 1e-20f) || !std::isfinite(det)) continue;  // degenerate UVs: this face adds nothing
    // Solve [e1 e2] = [T B] [d1 d2]: T and B are dP/du and dP/dv; only their directions matter.
    glm::vec3 faceT = (e1 * d2.y - e2 * d1.y) / det, faceB = (e2 * d1.x - e1 * d2.x) / det;
    for (int k = 0; k < 3; ++k) {
      const glm::vec3& n = normals[v[k]];
      glm::vec3 pt = projectOnPlane(faceT, n), pb = projectOnPlane(faceB, n);
      float angle = cornerAngle(positions[v[(k + 1) % 3]] - positions[v[k]], positions[v[(k + 2) % 3]] - positions[v[k]]);
      if (usable(pt)) tangentSum[v[k]] += angle * glm::normalize(pt);
      if (usable(pb)) bitangentSum[v[k]] += angle * glm::normalize(pb);
    }
  }
  std::vector<glm::vec4> out(positions.size());
  for (size_t i = 0; i < positions.size(); ++i) {
    const glm::vec3 n = usable(normals[i]) ? glm::normalize(normals[i]) : glm::vec3(0.0f, 0.0f, 1.0f);
    glm::vec3 t = projectOnPlane(tangentSum[i], n);  // Gram-Schmidt against the vertex normal
    if (!usable(t)) {
      out[i] = glm::vec4(anyPerpendicular(n), 1.0f);
      continue;
    }
    t = glm::normalize(t);
    // glTF's v runs down the image while a normal map's +Y (green) points up it: the bitangent is -dP/dv.
    float w = glm::dot(glm::cross(n, t), bitangentSum[i]) > 0.0f ? -1.0f : 1.0f;
    out[i] = glm::vec4(t, w);
  }
  return out;
}

}  // namespace vkmc
