// BVH traversal, shaped by what llvmpipe (our CPU device) does with a shader: 8 lanes run as one SIMD program
// that never skips code, so the walk is one flat loop in which every lane takes one node step and one triangle
// test per iteration, with its stack in registers and a deep fallback. Why each choice, with the measurements:
// docs/journal/performance.md, "The traversal kernel's design". `complete` says whether a walk ended on its own (llvmpipe's
// loop limiter can end a shader loop silently); an incomplete walk never passes for a hit or a miss.
#include "bvh_layout.h"
#include "textures.glsl"
#define TRAVERSAL_STACK_SIZE 96
const uint kNoEntry = kBvhNoEntry;

// The key of the ray being walked, for stochastic alpha (surfacePresent): set by the caller before a walk.
uint walkRayKey = 0u;

// A candidate hit h = (t, b1, b2) on triangle tri counts unless the triangle is alpha-tested and absent there.
bool hitCounts(vec3 h, uint tri) { return h.x > 0.0 && (kHasAlpha == 0u || surfacePresent(tri, h.yz, walkRayKey)); }

uint leafFirst(uint entry) { return bvhLeafFirst(entry); }
uint leafEnd(uint entry) { return bvhLeafFirst(entry) + bvhLeafCount(entry); }
bool isLeaf(uint entry) { return bvhIsLeaf(entry); }

// The triangles of a leaf entry against the ray; true when one of them is the new closest hit (in best).
bool intersectLeaf(uint entry, RayShear shear, inout vec4 best) {
  bool found = false;
  for (uint tri = leafFirst(entry); tri < leafEnd(entry); ++tri) {
    vec3 v0, v1, v2;
    bool cullBack;
    triangleVertices(tri, v0, v1, v2, cullBack);
    vec3 h = intersectTriangle(shear, v0, v1, v2, best.x, cullBack);
    if (hitCounts(h, tri)) {
      best = vec4(h, uintBitsToFloat(tri));
      found = true;
    }
  }
  return found;
}

#ifndef VKMC_BVH2
// Adds a walk's step counts to Control.walkStats (only kernels built with SPEC_WALK_STATS = 1 call it).
void countWalkSteps(uvec3 steps) {
  atomicAdd(control.walkIterations, steps.x);
  atomicAdd(control.walkNodeSteps, steps.y);
  atomicAdd(control.walkTriangleTests, steps.z);
  uint slowest = subgroupMax(steps.x);
  if (subgroupElect()) atomicAdd(control.walkSlowestLaneIterations, slowest * gl_SubgroupSize);
}

// One compare-exchange of a sorting network on (distance, entry) pairs.
void orderPair(inout float da, inout uint ea, inout float db, inout uint eb) {
  bool swap = db < da;
  float d = da;
  uint e = ea;
  da = swap ? db : da;
  ea = swap ? eb : ea;
  db = swap ? d : db;
  eb = swap ? e : eb;
}

// min/max as compare and select: GLSL's carry NaN handling that costs llvmpipe two more instructions each.
vec4 maxSel(vec4 a, vec4 b) { return mix(b, a, greaterThan(a, b)); }
vec4 minSel(vec4 a, vec4 b) { return mix(b, a, lessThan(a, b)); }

// Child i's steps in byte i of each plane word (bvh_layout.h), as floats.
vec4 planeSteps(uint word) { return vec4(bvhWidePlaneSteps(word)); }

// The 4 child boxes of an inner node against the ray: returns how many are hit, their entries near to far
// first in e. A plane is origin + steps * step on the node's grid; the ray's distance to it is
// steps * (step * invDir) + (origin - rayOrigin) * invDir: one fma per plane. nearIsHigh picks, per axis,
// which plane the ray meets first (by its direction's sign).
uint hitChildren(uint node, vec3 invDir, vec3 origin, bvec3 nearIsHigh, float tMax, out uvec4 e) {
  int base = int(kBvhNodeTexels * node);
  uvec4 grid = imageLoad(bvhNodes, base + int(kBvhWideGridTexel));
  uvec4 xy = imageLoad(bvhNodes, base + int(kBvhWideXyPlanesTexel));
  uvec2 z = imageLoad(bvhNodes, base + int(kBvhWideZPlanesTexel)).xy;
  e = imageLoad(bvhNodes, base + int(kBvhWideChildTexel));
  vec3 step = bvhWideStep(grid.w);
  vec3 s = step * invDir;  // exact: step is a power of two
  vec3 o = (uintBitsToFloat(grid.xyz) - origin) * invDir;
  vec4 nx = fma(planeSteps(nearIsHigh.x ? xy.y : xy.x), vec4(s.x), vec4(o.x));
  vec4 fx = fma(planeSteps(nearIsHigh.x ? xy.x : xy.y), vec4(s.x), vec4(o.x));
  vec4 ny = fma(planeSteps(nearIsHigh.y ? xy.w : xy.z), vec4(s.y), vec4(o.y));
  vec4 fy = fma(planeSteps(nearIsHigh.y ? xy.z : xy.w), vec4(s.y), vec4(o.y));
  vec4 nz = fma(planeSteps(nearIsHigh.z ? z.y : z.x), vec4(s.z), vec4(o.z));
  vec4 fz = fma(planeSteps(nearIsHigh.z ? z.x : z.y), vec4(s.z), vec4(o.z));
  vec4 tNear = maxSel(maxSel(nx, ny), maxSel(nz, vec4(0.0)));
  // The far distance is widened by 2 gamma(3) (Ize 2013) so rounding never culls a box a ray grazes.
  vec4 tFar = minSel(minSel(minSel(fx, fy), fz) * kSlabWiden, vec4(tMax));
  bvec4 hit = bvec4(uvec4(lessThanEqual(tNear, tFar)) & uvec4(notEqual(e, uvec4(kBvhEmptySlot))));
  vec4 dist = mix(vec4(3.0e38), tNear, hit);
  orderPair(dist.x, e.x, dist.y, e.y);
  orderPair(dist.z, e.z, dist.w, e.w);
  orderPair(dist.x, e.x, dist.z, e.z);
  orderPair(dist.y, e.y, dist.w, e.w);
  orderPair(dist.y, e.y, dist.z, e.z);
  return uint(hit.x) + uint(hit.y) + uint(hit.z) + uint(hit.w);
}

// The register stack: up to 12 entries in three uvec4 (top = s0.x, empty slots = kNoEntry), of which the scene's
// kRegisterStackEntries (4, 8 or 12) are used: the unused uvec4 stay constant and the compiler drops their
// shifts. `shift` entries of (a, b, c) are pushed (1..3, a on top), or -shift entries popped (1..2), or nothing
// (0). Pushing past the bottom sets overflow; the walk then restarts with traceRayDeep, or is reported as cut where
// SPEC_DEEP_WALKS is 0 (the host's bound says no walk of the scene's BVH can overflow). (Why 12, and the smaller
// stacks: docs/journal/performance.md.)
struct RegisterStack {
  uvec4 s0, s1, s2;  // kBvhRegisterStackEntries
};

void shiftStack(inout RegisterStack st, int shift, uint a, uint b, uint c, inout bool overflow) {
  uvec4 s0 = st.s0, s1 = st.s1, s2 = st.s2;
  uvec4 bottom = kRegisterStackEntries <= 4u ? s0 : kRegisterStackEntries <= 8u ? s1 : s2;
  overflow = overflow || (shift >= 1 && bottom.w != kNoEntry) || (shift >= 2 && bottom.z != kNoEntry) ||
             (shift >= 3 && bottom.y != kNoEntry);
  uvec4 p1_0 = uvec4(a, s0.xyz), p1_1 = uvec4(s0.w, s1.xyz), p1_2 = uvec4(s1.w, s2.xyz);
  uvec4 p2_0 = uvec4(a, b, s0.xy), p2_1 = uvec4(s0.zw, s1.xy), p2_2 = uvec4(s1.zw, s2.xy);
  uvec4 p3_0 = uvec4(a, b, c, s0.x), p3_1 = uvec4(s0.yzw, s1.x), p3_2 = uvec4(s1.yzw, s2.x);
  uvec4 q1_0 = uvec4(s0.yzw, s1.x), q1_1 = uvec4(s1.yzw, s2.x), q1_2 = uvec4(s2.yzw, kNoEntry);
  uvec4 q2_0 = uvec4(s0.zw, s1.xy), q2_1 = uvec4(s1.zw, s2.xy), q2_2 = uvec4(s2.zw, uvec2(kNoEntry));
  st.s0 = shift == 1 ? p1_0 : shift == 2 ? p2_0 : shift == 3 ? p3_0 : shift == -1 ? q1_0 : shift == -2 ? q2_0 : s0;
  st.s1 = shift == 1 ? p1_1 : shift == 2 ? p2_1 : shift == 3 ? p3_1 : shift == -1 ? q1_1 : shift == -2 ? q2_1 : s1;
  st.s2 = shift == 1 ? p1_2 : shift == 2 ? p2_2 : shift == 3 ? p3_2 : shift == -1 ? q1_2 : shift == -2 ? q2_2 : s2;
  if (kRegisterStackEntries <= 8u) st.s2 = uvec4(kNoEntry);
  if (kRegisterStackEntries <= 4u) st.s1 = uvec4(kNoEntry);
}

struct Walk {
  RegisterStack stack;
  uint node;             // the node unit's next entry: inner node, leaf waiting for the triangle unit, or none
  uint triNext, triEnd;  // the triangle unit's leaf: triangles [triNext, triEnd) still to test
  uint parked;           // a leaf the node unit set aside while the triangle unit was busy, or none
  bool overflow;
};

bool walking(Walk w) { return w.node != kNoEntry || w.triNext < w.triEnd || w.parked != kNoEntry; }

// The triangle unit: one triangle of its leaf against the ray. An any-hit query ends at its first hit. Only the
// distance and the triangle are carried through the walk (fewer live registers in the loop); hitRecord
// recomputes the barycentrics once at the end.
void triangleStep(inout Walk w, RayShear shear, bool anyHit, inout float bestT, inout uint bestTri) {
  if (w.triNext < w.triEnd) {
    vec3 v0, v1, v2;
    bool cullBack;
    triangleVertices(w.triNext, v0, v1, v2, cullBack);
    vec3 h = intersectTriangle(shear, v0, v1, v2, bestT, cullBack);
    if (hitCounts(h, w.triNext)) {
      bestT = h.x;
      bestTri = w.triNext;
      if (anyHit) {
        w.node = kNoEntry;
        w.parked = kNoEntry;
        w.triEnd = w.triNext;
      }
    }
    ++w.triNext;
  }
}

// vec4(t, b1, b2, triangle bits) of the walk's closest hit: the same test on the same inputs gives the same t.
vec4 hitRecord(RayShear shear, float tMax, uint bestTri) {
  if (bestTri == kMissPrimitive) return vec4(tMax, 0.0, 0.0, uintBitsToFloat(kMissPrimitive));
  vec3 v0, v1, v2;
  triangleVertices(bestTri, v0, v1, v2);
  return vec4(intersectTriangle(shear, v0, v1, v2, tMax), uintBitsToFloat(bestTri));
}

// The node unit: the 4 child boxes of an inner node against the ray (hit children sorted near to far, the
// nearest next, the others pushed), then the handoff of a leaf that comes up next to a free triangle unit.
void nodeStep(inout Walk w, vec3 invDir, vec3 origin, bvec3 nearIsHigh, float tMax) {
  int shift = 0;
  uint pushA = kNoEntry, pushB = kNoEntry, pushC = kNoEntry;
  uint next0 = w.node, next1 = w.stack.s0.x;  // the entries up next, for the handoff
  if (w.node != kNoEntry && !isLeaf(w.node)) {
    uvec4 e;
    uint n = hitChildren(w.node, invDir, origin, nearIsHigh, tMax, e);
    shift = int(n) - 1;
    next0 = n > 0u ? e.x : w.stack.s0.x;
    next1 = n > 1u ? e.y : n == 1u ? w.stack.s0.x : w.stack.s0.y;
    pushA = e.y;
    pushB = e.z;
    pushC = e.w;
  }
  // A free triangle unit takes the parked leaf first, else a leaf that comes up next; a leaf that finds the
  // triangle unit busy is parked (one slot), so the node unit goes on with the next entry instead of waiting.
  bool triFree = w.triNext >= w.triEnd;
  uint take = triFree ? w.parked : kNoEntry;
  bool advance = isLeaf(next0) && (triFree || w.parked == kNoEntry);
  if (take != kNoEntry) w.parked = kNoEntry;
  if (advance) {
    if (triFree && take == kNoEntry) take = next0;
    else w.parked = next0;
    next0 = next1;
    shift -= 1;
    pushA = pushB;
    pushB = pushC;
  }
  if (take != kNoEntry) {
    w.triNext = leafFirst(take);
    w.triEnd = leafEnd(take);
  }
  w.node = next0;
  shiftStack(w.stack, shift, pushA, pushB, pushC, w.overflow);
}

// The same walk with its stack in a private array (96 entries; scratch memory on llvmpipe, a loop over the lanes
// per access): the fallback for the rare walk that outgrows the register stack. One flat loop, so lanes that do
// not need it pay a single pass.
vec4 traceRayDeep(vec3 origin, vec3 dir, float tMax, bool anyHit, out bool complete) {
  RayShear shear = makeRayShear(origin, dir);
  vec3 invDir = safeInverse(dir);
  bvec3 nearIsHigh = lessThan(invDir, vec3(0.0));
  float bestT = tMax;
  uint bestTri = kMissPrimitive;
  uint stack[TRAVERSAL_STACK_SIZE];
  uint sp = 0u;
  Walk w;
  w.node = 0u;
  w.triNext = w.triEnd = 0u;
  w.parked = kNoEntry;
  w.overflow = false;
  while (walking(w) && !w.overflow) {
    triangleStep(w, shear, anyHit, bestT, bestTri);
    bool pop = w.node == kNoEntry;
    if (isLeaf(w.node)) {
      if (w.triNext >= w.triEnd) {
        w.triNext = leafFirst(w.node);
        w.triEnd = leafEnd(w.node);
        pop = true;
      }
    } else if (w.node != kNoEntry) {
      uvec4 e;
      uint n = hitChildren(w.node, invDir, origin, nearIsHigh, bestT, e);
      w.overflow = sp + n > TRAVERSAL_STACK_SIZE;  // reported as an incomplete walk, never silently wrong
      if (n > 3u) stack[sp++] = e.w;
      if (n > 2u) stack[sp++] = e.z;
      if (n > 1u) stack[sp++] = e.y;
      w.node = e.x;
      pop = n == 0u;
    }
    if (pop) w.node = sp > 0u ? stack[--sp] : kNoEntry;
  }
  complete = !w.overflow;
  return hitRecord(shear, tMax, bestTri);
}

// The walk with the register stack alone. Returns vec4(t, b1, b2, triangle bits); triangle = kMissPrimitive when
// nothing is hit in (0, tMax). overflow: the walk outgrew the register stack and its result means nothing; it
// must be traced again with traceRayDeep (deferred_walk.glsl does that in a second dispatch).
vec4 traceRayShallow(vec3 origin, vec3 dir, float tMax, bool anyHit, out bool complete, out bool overflow) {
  RayShear shear = makeRayShear(origin, dir);
  vec3 invDir = safeInverse(dir);
  bvec3 nearIsHigh = lessThan(invDir, vec3(0.0));
  float bestT = tMax;
  uint bestTri = kMissPrimitive;
  Walk w;
  w.stack.s0 = w.stack.s1 = w.stack.s2 = uvec4(kNoEntry);
  w.node = 0u;
  w.triNext = w.triEnd = 0u;
  w.parked = kNoEntry;
  w.overflow = false;
  uvec3 steps = uvec3(0u);  // SPEC_WALK_STATS: iterations, node steps, triangle tests
  while (walking(w) && !w.overflow) {
    if (kWalkStats != 0u) steps += uvec3(1u, uint(w.node != kNoEntry && !isLeaf(w.node)), uint(w.triNext < w.triEnd));
    triangleStep(w, shear, anyHit, bestT, bestTri);
    nodeStep(w, invDir, origin, nearIsHigh, bestT);
  }
  if (kWalkStats != 0u) countWalkSteps(steps);
  complete = !walking(w);
  overflow = w.overflow;
  return hitRecord(shear, tMax, bestTri);
}

// The whole walk in one call (the megakernel's): the rare overflowed walk starts over with the deep stack here,
// so every lane pays one idle pass of traceRayDeep; kernels with a second dispatch defer those walks instead.
vec4 traceRay(vec3 origin, vec3 dir, float tMax, bool anyHit, out bool complete) {
  bool overflow;
  vec4 best = traceRayShallow(origin, dir, tMax, anyHit, complete, overflow);
  // kDeepWalks 0: no walk can overflow (the host's bound); complete stays false if one ever did.
  if (overflow && kDeepWalks != 0u) best = traceRayDeep(origin, dir, tMax, anyHit, complete);
  return best;
}
#else
// Returns vec4(t, b1, b2, triangle bits); triangle = kMissPrimitive when nothing is hit in (0, tMax).
vec4 traceRay(vec3 origin, vec3 dir, float tMax, bool anyHit, out bool complete) {
  complete = true;
  RayShear shear = makeRayShear(origin, dir);
  vec3 invDir = safeInverse(dir);
  vec3 originScaled = origin * invDir;
  vec4 best = vec4(tMax, 0.0, 0.0, uintBitsToFloat(kMissPrimitive));
  uint stack[TRAVERSAL_STACK_SIZE];
  uint sp = 0u;
  uint current = 0u;
  while (current != kNoEntry) {
    while (current != kNoEntry && !bvhIsLeaf(current)) {
      int base = int(kBvhNodeTexels * current);
      vec4 a0 = uintBitsToFloat(imageLoad(bvhNodes, base)), a1 = uintBitsToFloat(imageLoad(bvhNodes, base + 1));
      vec4 b0 = uintBitsToFloat(imageLoad(bvhNodes, base + 2)), b1 = uintBitsToFloat(imageLoad(bvhNodes, base + 3));
      vec3 l0 = a0.xyz * invDir - originScaled, h0 = a1.xyz * invDir - originScaled;
      vec3 l1 = b0.xyz * invDir - originScaled, h1 = b1.xyz * invDir - originScaled;
      vec3 n0 = min(l0, h0), f0 = max(l0, h0), n1 = min(l1, h1), f1 = max(l1, h1);
      // The far distance is widened by 2 gamma(3) (Ize 2013) so rounding never culls a box a ray grazes.
      float near0 = max(max(n0.x, n0.y), max(n0.z, 0.0));
      float far0 = min(min(f0.x, f0.y) * kSlabWiden, min(f0.z * kSlabWiden, best.x));
      float near1 = max(max(n1.x, n1.y), max(n1.z, 0.0));
      float far1 = min(min(f1.x, f1.y) * kSlabWiden, min(f1.z * kSlabWiden, best.x));
      bool hit0 = near0 <= far0, hit1 = near1 <= far1;
      uint count0 = floatBitsToUint(a1.w), count1 = floatBitsToUint(b1.w);
      uint e0 = count0 > 0u ? bvhLeafEntry(floatBitsToUint(a0.w), count0) : floatBitsToUint(a0.w);
      uint e1 = count1 > 0u ? bvhLeafEntry(floatBitsToUint(b0.w), count1) : floatBitsToUint(b0.w);
      if (hit0 && hit1) {
        bool oneFirst = near1 < near0;
        current = oneFirst ? e1 : e0;
        stack[sp++] = oneFirst ? e0 : e1;
      } else if (hit0) {
        current = e0;
      } else if (hit1) {
        current = e1;
      } else {
        current = sp > 0u ? stack[--sp] : kNoEntry;
      }
    }
    while (current != kNoEntry && bvhIsLeaf(current)) {
      if (intersectLeaf(current, shear, best) && anyHit) return best;
      current = sp > 0u ? stack[--sp] : kNoEntry;
    }
  }
  complete = current == kNoEntry;
  return best;
}

vec4 traceRayShallow(vec3 origin, vec3 dir, float tMax, bool anyHit, out bool complete, out bool overflow) {
  overflow = false;  // the binary walk keeps its stack in memory: it never defers
  return traceRay(origin, dir, tMax, anyHit, complete);
}
vec4 traceRayDeep(vec3 origin, vec3 dir, float tMax, bool anyHit, out bool complete) {
  return traceRay(origin, dir, tMax, anyHit, complete);
}
#endif
