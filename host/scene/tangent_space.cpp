// Tangent generation by the reference MikkTSpace (third_party/mikktspace).
#include "scene/tangent_space.h"

#include <cmath>

extern "C" {
#include "mikktspace.h"
}

namespace vkmc {
namespace {

bool usable(const glm::vec3& v) {
  float l = glm::dot(v, v);
  return l > 1e-30f && std::isfinite(l);
}

glm::vec3 projectOnPlane(const glm::vec3& v, const glm::vec3& n) { return v - n * glm::dot(n, v); }

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

namespace {

// MikkTSpace's view of an indexed triangle list, its faces those of `faces` (triangles of non-zero area); its
// results land per corner of the whole list.
struct MikkMesh {
  const std::vector<glm::vec3>& positions;
  const std::vector<glm::vec3>& normals;
  const std::vector<glm::vec2>& uvs;
  const std::vector<uint32_t>& triangles;
  const std::vector<uint32_t>& faces;
  std::vector<glm::vec4>& out;
  static MikkMesh& of(const SMikkTSpaceContext* c) { return *static_cast<MikkMesh*>(c->m_pUserData); }
  size_t corner(int face, int k) const { return 3 * size_t(faces[size_t(face)]) + size_t(k); }
  uint32_t vertex(int face, int k) const { return triangles[corner(face, k)]; }
};

int faceCount(const SMikkTSpaceContext* c) { return int(MikkMesh::of(c).faces.size()); }
int cornersOfFace(const SMikkTSpaceContext*, const int) { return 3; }
void position(const SMikkTSpaceContext* c, float out[], const int face, const int corner) {
  const MikkMesh& m = MikkMesh::of(c);
  const glm::vec3& p = m.positions[m.vertex(face, corner)];
  out[0] = p.x, out[1] = p.y, out[2] = p.z;
}
void normal(const SMikkTSpaceContext* c, float out[], const int face, const int corner) {
  const MikkMesh& m = MikkMesh::of(c);
  const glm::vec3& n = m.normals[m.vertex(face, corner)];
  out[0] = n.x, out[1] = n.y, out[2] = n.z;
}
void texCoord(const SMikkTSpaceContext* c, float out[], const int face, const int corner) {
  const MikkMesh& m = MikkMesh::of(c);
  glm::vec2 uv = m.uvs.empty() ? glm::vec2(0.0f) : m.uvs[m.vertex(face, corner)];
  out[0] = uv.x, out[1] = uv.y;
}
void setTangent(const SMikkTSpaceContext* c, const float t[], const float sign, const int face, const int corner) {
  MikkMesh& m = MikkMesh::of(c);
  // glTF's v runs down the image while a normal map's +Y (green) points up it: the bitangent is -dP/dv, the
  // opposite of MikkTSpace's (OpenGL's) sign, as three.js's computeMikkTSpaceTangents(negateSign) does for glTF.
  m.out[m.corner(face, corner)] = glm::vec4(t[0], t[1], t[2], sign < 0.0f ? 1.0f : -1.0f);
}

}  // namespace

std::vector<glm::vec4> generateTangents(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normalsIn,
                                        const std::vector<glm::vec2>& uvs, const std::vector<uint32_t>& tri) {
  std::vector<glm::vec3> normals = normalsIn.size() == positions.size() ? normalsIn : faceNormals(positions, tri);
  for (glm::vec3& n : normals) n = usable(n) ? glm::normalize(n) : glm::vec3(0.0f, 0.0f, 1.0f);
  const size_t corners = tri.size() / 3 * 3;
  std::vector<glm::vec4> out(corners, glm::vec4(0.0f));
  const std::vector<glm::vec2> noUvs;
  // Triangles without a surface to orient (a cross product of exactly zero, or not finite) stay out: MikkTSpace
  // welds corners of equal position by comparing each with all before it, so a primitive whose positions are all
  // equal (an accessor without a buffer view reads zeros) took it 10 s for 15k triangles (found by the fuzzer).
  std::vector<uint32_t> faces;
  for (size_t t = 0; t < corners; t += 3) {
    glm::vec3 c = glm::cross(positions[tri[t + 1]] - positions[tri[t]], positions[tri[t + 2]] - positions[tri[t]]);
    if (c != glm::vec3(0.0f) && std::isfinite(glm::dot(c, c))) faces.push_back(uint32_t(t / 3));
  }
  MikkMesh mesh{positions, normals, uvs.size() == positions.size() ? uvs : noUvs, tri, faces, out};
  SMikkTSpaceInterface callbacks{};
  callbacks.m_getNumFaces = faceCount;
  callbacks.m_getNumVerticesOfFace = cornersOfFace;
  callbacks.m_getPosition = position;
  callbacks.m_getNormal = normal;
  callbacks.m_getTexCoord = texCoord;
  callbacks.m_setTSpaceBasic = setTangent;
  SMikkTSpaceContext context{&callbacks, &mesh};
  if (!faces.empty()) genTangSpaceDefault(&context);
  // MikkTSpace leaves what it cannot build (degenerate or missing uvs) as it found it or not unit: some unit
  // perpendicular of the corner's normal instead, sign +1.
  for (size_t i = 0; i < corners; ++i) {
    const glm::vec3& n = normals[tri[i]];
    glm::vec3 t = projectOnPlane(glm::vec3(out[i]), n);
    out[i] = usable(t) ? glm::vec4(glm::normalize(t), out[i].w < 0.0f ? -1.0f : 1.0f) : glm::vec4(anyPerpendicular(n), 1.0f);
  }
  return out;
}

}  // namespace vkmc
