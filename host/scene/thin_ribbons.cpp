// Points and lines as camera-facing ribbons.
#include "scene/thin_ribbons.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "../shaders/shared/geometry.h"
#include "scene/tangent_space.h"

namespace vkmc {
namespace {

struct RibbonFrame {
  glm::vec3 right, up, forward;
  bool orthographic;
  float pixelAtUnitDistance;  // perspective: a pixel's size at distance 1; orthographic: a pixel's size
};

RibbonFrame ribbonFrame(const Camera& camera, uint32_t height) {
  RibbonFrame f;
  f.forward = glm::normalize(camera.forward);
  f.right = glm::normalize(glm::cross(f.forward, camera.up));
  f.up = glm::cross(f.right, f.forward);
  f.orthographic = camera.kind == CameraKind::Orthographic;
  f.pixelAtUnitDistance = 2.0f * (f.orthographic ? camera.ymag : std::tan(0.5f * camera.yfov)) / float(height);
  return f;
}

// A pixel's size at p: in perspective it grows with the depth along the view axis, an affine function of the
// position, so a ribbon whose ends are a pixel wide is a pixel wide all along (the distance would not be).
float pixelWidthAt(const RibbonFrame& f, const Camera& camera, glm::vec3 p) {
  return f.orthographic ? f.pixelAtUnitDistance : f.pixelAtUnitDistance * glm::dot(p - camera.position, f.forward);
}

void appendCorner(Scene& scene, glm::vec3 p, glm::vec3 n, glm::vec4 color, bool coloured) {
  if (!scene.uv0.empty()) scene.uv0.emplace_back(0.0f);
  if (!scene.uv1.empty()) scene.uv1.emplace_back(0.0f);
  if (coloured) scene.colors.push_back(color);
  if (!scene.tangents.empty()) scene.tangents.emplace_back(anyPerpendicular(n), 1.0f);
  scene.positions.push_back(p);
  scene.normals.push_back(n);
}

// Triangle c0 c1 c2 unless its area is zero for the kernels too (the loader's rule); true when added.
bool appendTriangle(Scene& scene, const glm::vec3 (&c)[3], const glm::vec4 (&color)[3], uint32_t material, bool coloured) {
  glm::vec4 cross = gpu::scaledTriangleCross(c[0], c[1], c[2]);
  float area = 0.5f * glm::length(glm::vec3(cross)) * cross.w * cross.w;
  if (!(glm::dot(glm::vec3(cross), glm::vec3(cross)) >= std::numeric_limits<float>::min()) ||
      !(area >= std::numeric_limits<float>::min()) || !std::isfinite(area)) {
    ++scene.degenerateTriangles;
    return false;
  }
  glm::vec3 n = glm::normalize(glm::vec3(cross));
  for (int k = 0; k < 3; ++k) appendCorner(scene, c[k], n, color[k], coloured);
  scene.materialIds.push_back(material);
  return true;
}

}  // namespace

uint64_t addThinRibbons(Scene& scene, const Camera& camera, uint32_t height) {
  if (scene.thinSegments.empty()) return 0;
  const RibbonFrame f = ribbonFrame(camera, height);
  bool coloured = !scene.colors.empty();
  for (const ThinSegment& s : scene.thinSegments) coloured |= s.colorA != glm::vec4(1.0f) || s.colorB != glm::vec4(1.0f);
  if (coloured && scene.colors.empty()) scene.colors.assign(scene.positions.size(), glm::vec4(1.0f));
  uint64_t drawn = 0;
  for (ThinSegment s : scene.thinSegments) {
    if (!f.orthographic) {
      // In front of the camera only: a segment reaching behind it is cut where its depth is a thousandth of its
      // far end's (widths are proportional to depth), one wholly behind is not drawn.
      float da = glm::dot(s.a - camera.position, f.forward), db = glm::dot(s.b - camera.position, f.forward);
      float nearest = 1e-3f * std::max(da, db);
      if (!(nearest > 0.0f)) continue;
      if (da < nearest) s.a = s.b + (s.a - s.b) * ((db - nearest) / (db - da)), s.colorA = s.colorB;
      if (db < nearest) s.b = s.a + (s.b - s.a) * ((da - nearest) / (da - db)), s.colorB = s.colorA;
    }
    glm::vec3 mid = 0.5f * (s.a + s.b);
    glm::vec3 toCamera = f.orthographic ? -f.forward : camera.position - mid;
    glm::vec3 across = glm::cross(s.b - s.a, toCamera);
    float acrossLength = glm::length(across);
    glm::vec3 c[4];
    glm::vec4 color[4] = {s.colorA, s.colorA, s.colorB, s.colorB};
    if (acrossLength > 1e-6f * glm::length(s.b - s.a) * glm::length(toCamera) && std::isfinite(acrossLength)) {
      // A ribbon along the segment, across the view: corners a -+ side, b +- side, front towards the camera.
      glm::vec3 side = across / acrossLength;
      glm::vec3 ha = 0.5f * pixelWidthAt(f, camera, s.a) * side, hb = 0.5f * pixelWidthAt(f, camera, s.b) * side;
      c[0] = s.a - ha, c[1] = s.a + ha, c[2] = s.b + hb, c[3] = s.b - hb;
    } else {
      // A point (or a segment along the view): a square one pixel across in the image plane.
      float h = 0.5f * pixelWidthAt(f, camera, mid);
      glm::vec3 r = h * f.right, u = h * f.up;
      c[0] = mid - r - u, c[1] = mid + r - u, c[2] = mid + r + u, c[3] = mid - r + u;
      color[2] = color[3] = s.colorA;
    }
    bool first = appendTriangle(scene, {c[0], c[1], c[2]}, {color[0], color[1], color[2]}, s.material, coloured);
    bool second = appendTriangle(scene, {c[0], c[2], c[3]}, {color[0], color[2], color[3]}, s.material, coloured);
    drawn += (first || second) ? 1 : 0;
  }
  scene.thinSegments.clear();
  return drawn;
}

}  // namespace vkmc
