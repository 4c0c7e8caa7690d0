// Triangle soups that have broken BVH builders: spheres and boxes centred at the origin (coordinates such as
// 6e-17 beside -1), power-of-two extents, flat and zero-thickness boxes, +-0 and denormals, scales from 1e-30
// to 1e30, geometry far from the origin, huge and tiny triangles in one scene; rays aimed at them; brute force.
#pragma once
#include <glm/glm.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "../shaders/shared/geometry.h"
#include "bvh/bvh.h"
#include "param_name.h"

namespace vkmc::test {

struct Soup {
  std::string name;
  std::vector<glm::vec3> positions;  // 3 per triangle
};

inline void addTriangle(Soup& s, glm::vec3 a, glm::vec3 b, glm::vec3 c) { s.positions.insert(s.positions.end(), {a, b, c}); }

// A UV sphere as modelling tools make it: sin/cos in double, so the poles and the seam carry coordinates like
// 6e-17 where a 0 was meant.
inline Soup uvSphere(double radius, int segments, int rings, glm::dvec3 centre = glm::dvec3(0.0), bool inward = false) {
  Soup s{"sphere r=" + shortNumber(radius) + " " + std::to_string(segments) + "x" + std::to_string(rings) +
         (inward ? " inward" : "")};
  auto point = [&](int i, int j) {
    double theta = M_PI * j / rings, phi = 2.0 * M_PI * i / segments;
    return glm::vec3(centre +
                     radius * glm::dvec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)));
  };
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < segments; ++i) {
      glm::vec3 a = point(i, j), b = point(i + 1, j), c = point(i + 1, j + 1), d = point(i, j + 1);
      if (inward) std::swap(b, d);
      if (j > 0) addTriangle(s, a, b, c);
      if (j + 1 < rings) addTriangle(s, a, c, d);
    }
  return s;
}

// An axis-aligned box [lo, hi] as 12 triangles; a zero extent gives a flat (zero-thickness) box.
inline Soup box(glm::vec3 lo, glm::vec3 hi, std::string name) {
  Soup s{std::move(name)};
  for (int axis = 0; axis < 3; ++axis)
    for (float side : {lo[axis], hi[axis]}) {
      int u = (axis + 1) % 3, v = (axis + 2) % 3;
      glm::vec3 p[4];
      for (int k = 0; k < 4; ++k) {
        p[k][axis] = side;
        p[k][u] = (k == 1 || k == 2) ? hi[u] : lo[u];
        p[k][v] = (k >= 2) ? hi[v] : lo[v];
      }
      addTriangle(s, p[0], p[1], p[2]);
      addTriangle(s, p[0], p[2], p[3]);
    }
  return s;
}

inline Soup randomSoup(int triangles, uint32_t seed, float scale, glm::vec3 shift, std::string name) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  Soup s{std::move(name)};
  for (int i = 0; i < triangles; ++i) {
    glm::vec3 c(u(rng), u(rng), u(rng));
    float size = 0.02f + 0.2f * std::abs(u(rng));
    glm::vec3 p[3];
    for (glm::vec3& v : p) v = shift + scale * (c + size * glm::vec3(u(rng), u(rng), u(rng)));
    addTriangle(s, p[0], p[1], p[2]);
  }
  return s;
}

inline Soup merged(std::string name, std::initializer_list<Soup> parts) {
  Soup s{std::move(name)};
  for (const Soup& p : parts) s.positions.insert(s.positions.end(), p.positions.begin(), p.positions.end());
  return s;
}

inline std::vector<Soup> adversarialSoups() {
  std::vector<Soup> out;
  for (double r : {0.5, 1.0, 2.0, 10.0, 1024.0}) out.push_back(uvSphere(r, 32, 16));
  out.push_back(uvSphere(1.0, 32, 16, glm::dvec3(0.0), true));
  out.push_back(uvSphere(1.0, 256, 128));
  out.push_back(uvSphere(1.0, 32, 16, glm::dvec3(0.1, 0.2, 0.3)));
  out.push_back(uvSphere(1.0, 48, 24, glm::dvec3(1e6, -3e5, 2e7)));
  out.push_back(box(glm::vec3(-1.0f), glm::vec3(1.0f), "box [-1,1]"));
  out.push_back(box(glm::vec3(0.0f), glm::vec3(1024.0f), "box [0,1024]"));
  out.push_back(box(glm::vec3(-0.0f, 0.0f, -0.0f), glm::vec3(0.25f, 0.5f, 0.125f), "box with -0 corners"));
  out.push_back(box(glm::vec3(-1.0f, -1.0f, 0.0f), glm::vec3(1.0f, 1.0f, 0.0f), "flat box z=0"));
  out.push_back(box(glm::vec3(-1.0f, 0.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f), "zero-area box (a segment)"));
  out.push_back(merged("stacked flat boxes", {box(glm::vec3(-1, -1, 0), glm::vec3(1, 1, 0), ""),
                                              box(glm::vec3(-1, -1, 1e-7f), glm::vec3(1, 1, 1e-7f), ""),
                                              box(glm::vec3(-1, -1, -1e-38f), glm::vec3(1, 1, -1e-38f), "")}));
  out.push_back(merged("denormals beside a unit box",
                       {box(glm::vec3(-1e-40f), glm::vec3(1e-39f), ""), box(glm::vec3(-1.0f), glm::vec3(1.0f), "")}));
  for (float scale : {1e-30f, 1e-20f, 1e-10f, 1e10f, 1e20f, 1e30f})
    out.push_back(randomSoup(400, 5, scale, glm::vec3(0.0f), "random soup x" + shortNumber(scale)));
  out.push_back(randomSoup(400, 6, 1.0f, glm::vec3(3e4f, -1e4f, 2e4f), "random soup far away"));
  out.push_back(
      merged("ground of half-size 3e9 and a unit sphere",
             {box(glm::vec3(-3e9f, 0.0f, -3e9f), glm::vec3(3e9f, 0.0f, 3e9f), ""), uvSphere(1.0, 16, 8, glm::dvec3(0, 1, 0))}));
  return out;
}

// The ordered positions of a soup under its BVH (GPU triangle i is input triangle bvh.triangleOrder[i]).
inline std::vector<glm::vec3> ordered(const Soup& s, const Bvh& bvh) {
  std::vector<glm::vec3> out;
  for (uint32_t t : bvh.triangleOrder)
    for (int k = 0; k < 3; ++k) out.push_back(s.positions[3 * t + k]);
  return out;
}

inline std::vector<Aabb> triangleBounds(const std::vector<glm::vec3>& positions) {
  std::vector<Aabb> b(positions.size() / 3);
  for (size_t i = 0; i < b.size(); ++i)
    for (int k = 0; k < 3; ++k) b[i].grow(positions[3 * i + k]);
  return b;
}

struct Ray {
  glm::vec3 origin, direction;
  float tMax;
};

// Rays from a sphere around the soup towards points on its triangles (so most hit), a few axis-aligned.
inline std::vector<Ray> raysAt(const Soup& s, int count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Aabb bounds;
  for (glm::vec3 p : s.positions) bounds.grow(p);
  glm::dvec3 centre = 0.5 * (glm::dvec3(bounds.min) + glm::dvec3(bounds.max));
  double radius = 0.5 * glm::length(glm::dvec3(bounds.max) - glm::dvec3(bounds.min));
  if (!(radius > 0.0)) radius = 1.0;
  std::vector<Ray> rays;
  size_t triangles = s.positions.size() / 3;
  for (int r = 0; r < count; ++r) {
    size_t t = std::min(triangles - 1, size_t(u(rng) * triangles));
    float b1 = u(rng), b2 = u(rng);
    if (b1 + b2 > 1.0f) b1 = 1.0f - b1, b2 = 1.0f - b2;
    glm::dvec3 target = glm::dvec3(s.positions[3 * t]) * double(1.0f - b1 - b2) +
                        glm::dvec3(s.positions[3 * t + 1]) * double(b1) + glm::dvec3(s.positions[3 * t + 2]) * double(b2);
    glm::dvec3 dir = glm::normalize(glm::dvec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
    if (r % 17 == 0) dir = glm::dvec3(0.0, 0.0, r % 2 ? 1.0 : -1.0);
    glm::dvec3 origin = target - 3.0 * radius * dir;
    if (r % 5 == 0) origin = centre;  // from inside
    glm::vec3 d = glm::vec3(glm::normalize(target - origin));
    if (!(glm::length(d) > 0.5f)) d = glm::vec3(dir);
    rays.push_back({glm::vec3(origin), d, r % 3 == 0 ? float(4.0 * radius) : 3e38f});
  }
  return rays;
}

inline HostHit bruteForce(const std::vector<glm::vec3>& pos, const Ray& ray) {
  gpu::RayShear shear = gpu::makeRayShear(ray.origin, ray.direction);
  HostHit best;
  float t = ray.tMax;
  for (uint32_t i = 0; i < pos.size() / 3; ++i) {
    glm::vec3 h = gpu::intersectTriangle(shear, pos[3 * i], pos[3 * i + 1], pos[3 * i + 2], t);
    if (h.x > 0.0f) {
      t = h.x;
      best = {h.x, h.y, h.z, i};
    }
  }
  return best;
}

// Whether a walk's closest hit is brute force's (two triangles within float rounding along the ray tie).
inline bool sameClosestHit(const HostHit& got, const HostHit& want) {
  if (got.triangle == want.triangle) return true;
  return got.triangle != 0xffffffffu && want.triangle != 0xffffffffu && std::abs(got.t - want.t) <= 1e-5f * want.t;
}

}  // namespace vkmc::test
