// Robust geometry: watertight ray/triangle intersection (Woop, Benthin, Wald 2013) and scale-aware ray
// origins (pbrt-v4: offset along the normal past the rounding-error bound of the interpolated hit point).
#ifndef VKMC_GEOMETRY_H
#define VKMC_GEOMETRY_H
#include "glsl_cpp.h"
VKMC_BEGIN_NAMESPACE

VKMC_CONST float kMachineEpsilon = 5.96046448e-08f;  // 2^-24
VKMC_FN float gammaBound(float n) { return (n * kMachineEpsilon) / (1.0f - n * kMachineEpsilon); }

// Per-ray constants of the watertight test: the dominant axis becomes z and the ray is sheared onto +z.
// Permutation and shear are folded into three rows, so a vertex is transformed by three dot products instead
// of lane-varying component indexing (which llvmpipe turns into stack traffic). Every factor but the shear is
// 0 or 1, so the transformed coordinates round exactly as in the paper's formulation, and a vertex shared by
// two triangles transforms identically for both: edges stay watertight.
struct RayShear {
  vec3 origin;
  vec3 row0;  // e_kx - Sx e_kz
  vec3 row1;  // e_ky - Sy e_kz
  vec3 row2;  // Sz e_kz
};

VKMC_FN vec3 unitAxis(uint k) { return vec3(k == 0u ? 1.0f : 0.0f, k == 1u ? 1.0f : 0.0f, k == 2u ? 1.0f : 0.0f); }

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
  float dz = dir[kz];
  RayShear r;
  r.origin = origin;
  r.row0 = unitAxis(kx) - (dir[kx] / dz) * unitAxis(kz);
  r.row1 = unitAxis(ky) - (dir[ky] / dz) * unitAxis(kz);
  r.row2 = (1.0f / dz) * unitAxis(kz);
  return r;
}

// max as a compare and a select: GLSL's max() carries a NaN rule that costs llvmpipe two more instructions, and
// the operands of the error bounds below are finite whenever a hit is reported.
VKMC_FN float maxFinite(float a, float b) { return a > b ? a : b; }

// Returns (t, b1, b2) with b1, b2 the weights of v1, v2, or t < 0 when there is no hit in (0, tMax).
// Edges are shared exactly between neighbours: no ray slips between two triangles.
VKMC_FN vec3 intersectTriangle(RayShear r, vec3 v0, vec3 v1, vec3 v2, float tMax) {
  vec3 A = v0 - r.origin, B = v1 - r.origin, C = v2 - r.origin;
  float ax = dot(r.row0, A), ay = dot(r.row1, A);
  float bx = dot(r.row0, B), by = dot(r.row1, B);
  float cx = dot(r.row0, C), cy = dot(r.row1, C);
  float U = cx * by - cy * bx;
  float V = ax * cy - ay * cx;
  float W = bx * ay - by * ax;
  vec3 miss = vec3(-1.0f, 0.0f, 0.0f);
  if ((U < 0.0f || V < 0.0f || W < 0.0f) && (U > 0.0f || V > 0.0f || W > 0.0f)) return miss;
  float det = U + V + W;
  if (det == 0.0f) return miss;
  float az = dot(r.row2, A), bz = dot(r.row2, B), cz = dot(r.row2, C);
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
    if (offset[i] > 0.0f) po[i] = nextFloatUp(po[i]);
    else if (offset[i] < 0.0f) po[i] = nextFloatDown(po[i]);
  }
  return po;
}

VKMC_CONST float kSlabWiden = 1.0000004f;  // 1 + 2 gamma(3), rounded up

// Directions with a zero component would give 0 * inf = NaN in the slab test.
VKMC_FN vec3 safeInverse(vec3 d) {
  const float tiny = 1e-30f;
  vec3 s = vec3(abs(d.x) < tiny ? (d.x < 0.0f ? -tiny : tiny) : d.x,
                abs(d.y) < tiny ? (d.y < 0.0f ? -tiny : tiny) : d.y,
                abs(d.z) < tiny ? (d.z < 0.0f ? -tiny : tiny) : d.z);
  return 1.0f / s;
}

VKMC_END_NAMESPACE
#endif
