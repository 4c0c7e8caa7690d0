// Robust geometry: watertight ray/triangle intersection (Woop, Benthin, Wald 2013) and scale-aware ray
// origins (pbrt-v4: offset along the normal past the rounding-error bound of the interpolated hit point).
#ifndef VKMC_GEOMETRY_H
#define VKMC_GEOMETRY_H
#include "glsl_cpp.h"
VKMC_BEGIN_NAMESPACE

VKMC_CONST float kMachineEpsilon = 5.96046448e-08f;  // 2^-24
VKMC_FN float gammaBound(float n) { return (n * kMachineEpsilon) / (1.0f - n * kMachineEpsilon); }

// Per-ray constants of the watertight test: the dominant axis becomes z and the ray is sheared onto +z. The
// permutation is kept as two flags per axis and applied to a vertex with selects (fixed-index components, no
// lane-varying vector indexing, which llvmpipe turns into stack traffic; 27 instructions per triangle where
// three dot-product rows took 45). A vertex shared by two triangles transforms identically for both: edges
// stay watertight.
struct RayShear {
  vec3 origin;
  vec3 shear;        // Sx, Sy, Sz
  bvec2 kx, ky, kz;  // which axis becomes x, y, z: (axis == 0, axis == 1)
};

VKMC_FN bvec2 axisFlags(uint k) { return bvec2(k == 0u, k == 1u); }
VKMC_FN float pickAxis(vec3 v, bvec2 k) { return k.x ? v.x : (k.y ? v.y : v.z); }

VKMC_FN RayShear makeRayShear(vec3 origin, vec3 dir) {
  vec3 a = abs(dir);
  uint kz = (a.x > a.y) ? (a.x > a.z ? 0u : 2u) : (a.y > a.z ? 1u : 2u);
  uint kx = (kz + 1u) % 3u;
  uint ky = (kx + 1u) % 3u;
  if (dir[kz] < 0.0f) {
    uint tmp = kx;
    kx = ky;
    ky = tmp;
  }
  RayShear r;
  r.origin = origin;
  r.kx = axisFlags(kx);
  r.ky = axisFlags(ky);
  r.kz = axisFlags(kz);
  float dz = pickAxis(dir, r.kz);
  r.shear = vec3(pickAxis(dir, r.kx) / dz, pickAxis(dir, r.ky) / dz, 1.0f / dz);
  return r;
}

// max as a compare and a select: GLSL's max() carries a NaN rule that costs llvmpipe two more instructions, and
// the operands of the error bounds below are finite whenever a hit is reported.
VKMC_FN float maxFinite(float a, float b) { return a > b ? a : b; }

// Returns (t, b1, b2) with b1, b2 the weights of v1, v2, or t < 0 when there is no hit in (0, tMax).
// Edges are shared exactly between neighbours: no ray slips between two triangles. cullBack: a ray that meets
// the back (the side cross(v1 - v0, v2 - v0) points away from) misses.
VKMC_FN vec3 intersectTriangle(RayShear r, vec3 v0, vec3 v1, vec3 v2, float tMax, bool cullBack) {
  vec3 A = v0 - r.origin, B = v1 - r.origin, C = v2 - r.origin;
  float Az = pickAxis(A, r.kz), Bz = pickAxis(B, r.kz), Cz = pickAxis(C, r.kz);
  float ax = pickAxis(A, r.kx) - r.shear.x * Az, ay = pickAxis(A, r.ky) - r.shear.y * Az;
  float bx = pickAxis(B, r.kx) - r.shear.x * Bz, by = pickAxis(B, r.ky) - r.shear.y * Bz;
  float cx = pickAxis(C, r.kx) - r.shear.x * Cz, cy = pickAxis(C, r.ky) - r.shear.y * Cz;
  float U = cx * by - cy * bx;
  float V = ax * cy - ay * cx;
  float W = bx * ay - by * ax;
  vec3 miss = vec3(-1.0f, 0.0f, 0.0f);
  // Outside an edge; culled, the back (U, V, W all at most 0) counts as outside too.
  if ((U < 0.0f || V < 0.0f || W < 0.0f) && (cullBack || U > 0.0f || V > 0.0f || W > 0.0f)) return miss;
  float det = U + V + W;
  if (det == 0.0f) return miss;
  float az = r.shear.z * Az, bz = r.shear.z * Bz, cz = r.shear.z * Cz;
  float T = U * az + V * bz + W * cz;
  if (det < 0.0f) {  // seen from the back: all of U, V, W, det and T flip sign together
    T = -T;
    det = -det;
    U = -U;
    V = -V;
    W = -W;
  }
  if (T <= 0.0f || T >= tMax * det) return miss;
  float inv = 1.0f / det;
  float t = T * inv;
  // t must exceed its own rounding-error bound (pbrt-v4, after Woop et al.): a ray leaving a surface from an
  // origin offset by a few ulps would otherwise re-hit the same plane at a tiny positive t when its dominant
  // axis lies in that plane.
  float maxZ = maxFinite(abs(az), maxFinite(abs(bz), abs(cz)));
  float maxX = maxFinite(abs(ax), maxFinite(abs(bx), abs(cx)));
  float maxY = maxFinite(abs(ay), maxFinite(abs(by), abs(cy)));
  float deltaZ = gammaBound(3.0f) * maxZ;
  float deltaX = gammaBound(5.0f) * (maxX + maxZ);
  float deltaY = gammaBound(5.0f) * (maxY + maxZ);
  float deltaE = 2.0f * (gammaBound(2.0f) * maxX * maxY + deltaY * maxX + deltaX * maxY);
  float maxE = maxFinite(abs(U), maxFinite(abs(V), abs(W)));
  float deltaT = 3.0f * (gammaBound(3.0f) * maxE * maxZ + deltaE * maxZ + deltaZ * maxE) * inv;
  if (t <= deltaT) return miss;
  return vec3(t, V * inv, W * inv);
}
VKMC_FN vec3 intersectTriangle(RayShear r, vec3 v0, vec3 v1, vec3 v2, float tMax) {
  return intersectTriangle(r, v0, v1, v2, tMax, false);
}

// Bound on the rounding error of b0*v0 + b1*v1 + b2*v2: relative to the coordinates, so scaling or
// translating a scene scales the offset with it.
VKMC_FN vec3 barycentricError(vec3 b, vec3 v0, vec3 v1, vec3 v2) {
  return gammaBound(7.0f) * (abs(b.x * v0) + abs(b.y * v1) + abs(b.z * v2));
}

VKMC_FN float nextFloatUp(float v) {
  if (isinf(v) && v > 0.0f) return v;
  if (v == -0.0f) v = 0.0f;
  uint bits = floatBitsToUint(v);
  bits = v >= 0.0f ? bits + 1u : bits - 1u;
  return uintBitsToFloat(bits);
}
VKMC_FN float nextFloatDown(float v) {
  if (isinf(v) && v < 0.0f) return v;
  if (v == 0.0f) v = -0.0f;
  uint bits = floatBitsToUint(v);
  bits = v > 0.0f ? bits - 1u : bits + 1u;
  return uintBitsToFloat(bits);
}

// Moves p off its surface to the side of w, past the error bound, rounding away from the surface.
VKMC_FN vec3 offsetRayOrigin(vec3 p, vec3 pError, vec3 n, vec3 w) {
  float d = dot(abs(n), pError);
  vec3 offset = d * n;
  if (dot(w, n) < 0.0f) offset = -offset;
  vec3 po = p + offset;
  for (int i = 0; i < 3; ++i) {
    if (offset[i] > 0.0f)
      po[i] = nextFloatUp(po[i]);
    else if (offset[i] < 0.0f)
      po[i] = nextFloatDown(po[i]);
  }
  return po;
}

VKMC_CONST float kSlabWiden = 1.0000004f;  // 1 + 2 gamma(3), rounded up
// Vertex and camera coordinates beyond this are refused: the watertight test's products grow as distance cubed
// and overflow float past ~7e12, and slab distances (below) must stay finite.
VKMC_CONST float kMaxSceneCoordinate = 1e11f;

// A triangle's edge cross product divided by s^2, s = the edges' largest component (.w): finite for any edges
// within the coordinate range, where a plain cross of edges over ~4e9 overflows float once squared (a huge ground
// plane would get a zero normal and an infinite area). Normal: normalize(c.xyz); area: 0.5 * length(c.xyz) * s * s.
VKMC_FN vec4 scaledTriangleCross(vec3 v0, vec3 v1, vec3 v2) {
  vec3 e1 = v1 - v0, e2 = v2 - v0;
  vec3 m = max(abs(e1), abs(e2));
  float s = max(max(m.x, m.y), max(m.z, 1e-30f));
  float inv = 1.0f / s;
  return vec4(cross(e1 * inv, e2 * inv), s);
}
VKMC_FN float scaledCrossArea(vec4 c) { return 0.5f * length(vec3(c.x, c.y, c.z)) * c.w * c.w; }

// Directions with a zero component would give 0 * inf = NaN in the slab test. The bound keeps every slab
// distance finite in scenes within the loader's coordinate range (kMaxSceneCoordinate: 2e11 * 1e26 < FLT_MAX), so
// the node step's fma never meets inf - inf.
VKMC_FN vec3 safeInverse(vec3 d) {
  const float tiny = 1e-26f;
  vec3 s = vec3(abs(d.x) < tiny ? (d.x < 0.0f ? -tiny : tiny) : d.x, abs(d.y) < tiny ? (d.y < 0.0f ? -tiny : tiny) : d.y,
                abs(d.z) < tiny ? (d.z < 0.0f ? -tiny : tiny) : d.z);
  return 1.0f / s;
}

VKMC_END_NAMESPACE
#endif
