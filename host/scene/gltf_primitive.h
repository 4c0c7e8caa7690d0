// One glTF mesh primitive in its local space as indexed vertices: attributes read and defaulted, morph targets
// applied at their weights, strips and fans turned into triangle lists, tangents generated where needed.
#pragma once
#include <tiny_gltf.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace vkmc {

struct PrimitiveData {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;   // empty when the primitive has no NORMAL
  std::vector<glm::vec2> uv0, uv1;  // empty when absent
  std::vector<glm::vec4> tangents;  // TANGENT, generated ones, or empty (see PrimitiveRequest::generateTangents)
  bool tangentsPerCorner = false;   // generated (MikkTSpace): one per corner of `triangles`, not per vertex
  std::vector<glm::vec4> colors;    // COLOR_0 as RGBA, empty when absent
  std::vector<glm::uvec4> joints;   // JOINTS_n and WEIGHTS_n, set after set (n vertices each), for a skinned mesh only
  std::vector<glm::vec4> weights;
  std::vector<uint32_t> triangles;  // 3 vertex indices per triangle, each checked < positions.size()
  std::vector<uint32_t> segments;   // points and lines: 2 vertex indices per segment (a point: the same twice)
};

struct PrimitiveRequest {
  std::vector<double> weights;    // morph target weights (the node's, else the mesh's); missing ones are 0
  bool generateTangents = false;  // when TANGENT is absent: MikkTSpace-style from the UV set below
  int tangentUvSet = 0;           // the normal texture's texCoord
  uint64_t maxElements = 0;       // per accessor (view-less accessors have no data to bound their count)
  // A skinned mesh's joint matrices (scene/gltf_skin.h): the primitive is skinned into world space after its morph
  // targets and before tangents are generated. Null for a mesh without a skin.
  const std::vector<glm::mat4>* joints = nullptr;
};

// Whether glTF draws `mode` as triangles (lists, strips, fans), or as points and lines (POINTS, LINES, LINE_LOOP,
// LINE_STRIP: vkmc draws them as thin ribbons, scene/thin_ribbons.h).
bool isTriangleMode(int mode);
bool isPointOrLineMode(int mode);
// How many segments a point or line primitive of `elements` vertices (or indices) makes.
size_t segmentCount(int mode, size_t elements);
// How many triangles a primitive of `elements` vertices (or indices) makes.
size_t triangleCount(int mode, size_t elements);

// Throws vkmc::Error naming the accessor or index at fault.
PrimitiveData readPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& prim, const PrimitiveRequest& request);

}  // namespace vkmc
