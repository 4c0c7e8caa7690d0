// BVH traversal in while-while form (Aila & Laine 2009): each lane walks inner nodes until it holds a leaf, then
// the lanes test leaves together. On SIMD hardware (llvmpipe's 8 lanes, a GPU's warp) this keeps lanes busy
// with the same kind of work. Leaves are stack entries too, tagged with the high bit and their size; nearer
// children are visited first. Two node layouts (host/bvh/bvh.h): 4-wide nodes (the default: 4 box tests as vec4
// arithmetic, half the steps) and, with VKMC_BVH2, the binary one (kept for side-by-side benchmarks).
// llvmpipe has a hang guard that ends shader loops after 65535 iterations (LP_MAX_TGSI_LOOP_ITERATIONS) without
// any error; the analytic furnace probe lost paths to it. A walk of 400k leaves measured complete, but a walk
// that did not end on its own must never pass for a hit or a miss: `complete` says whether it did.
#define TRAVERSAL_STACK_SIZE 96
const uint kLeafTag = 0x80000000u;
const uint kNoEntry = 0xffffffffu;

uint leafEntry(uint first, uint count) { return kLeafTag | ((count - 1u) << 27u) | first; }

// The triangles of a leaf entry against the ray; true when one of them is the new closest hit (in best).
bool intersectLeaf(uint entry, RayShear shear, inout vec4 best) {
  uint first = entry & 0x07ffffffu;
  uint last = first + ((entry >> 27u) & 0xfu) + 1u;
  bool found = false;
  for (uint tri = first; tri < last; ++tri) {
    vec3 v0, v1, v2;
    triangleVertices(tri, v0, v1, v2);
    vec3 h = intersectTriangle(shear, v0, v1, v2, best.x);
    if (h.x > 0.0) {
      best = vec4(h, uintBitsToFloat(tri));
      found = true;
    }
  }
  return found;
}

#ifndef VKMC_BVH2
const uint kEmptySlot = 0x7f7fffffu;

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

// Returns vec4(t, b1, b2, triangle bits); triangle = kMissPrimitive when nothing is hit in (0, tMax).
vec4 traceRay(vec3 origin, vec3 dir, float tMax, bool anyHit, out bool complete) {
  RayShear shear = makeRayShear(origin, dir);
  vec3 invDir = safeInverse(dir);
  vec3 os = origin * invDir;
  vec4 best = vec4(tMax, 0.0, 0.0, uintBitsToFloat(kMissPrimitive));
  uint stack[TRAVERSAL_STACK_SIZE];
  uint sp = 0u;
  uint current = 0u;
  bool overflow = false;
  complete = true;
  while (current != kNoEntry) {
    while (current != kNoEntry && (current & kLeafTag) == 0u) {
      int base = int(7u * current);
      vec4 lx = texelFetch(bvhNodes, base) * invDir.x - os.x, hx = texelFetch(bvhNodes, base + 1) * invDir.x - os.x;
      vec4 ly = texelFetch(bvhNodes, base + 2) * invDir.y - os.y, hy = texelFetch(bvhNodes, base + 3) * invDir.y - os.y;
      vec4 lz = texelFetch(bvhNodes, base + 4) * invDir.z - os.z, hz = texelFetch(bvhNodes, base + 5) * invDir.z - os.z;
      uvec4 e = floatBitsToUint(texelFetch(bvhNodes, base + 6));
      vec4 tNear = max(max(min(lx, hx), min(ly, hy)), max(min(lz, hz), vec4(0.0)));
      // The far distance is widened by 2 gamma(3) (Ize 2013) so rounding never culls a box a ray grazes.
      vec4 tFar = min(min(max(lx, hx), max(ly, hy)) * kSlabWiden, min(max(lz, hz) * kSlabWiden, vec4(best.x)));
      bvec4 hit = bvec4(uvec4(lessThanEqual(tNear, tFar)) & uvec4(notEqual(e, uvec4(kEmptySlot))));
      vec4 d = mix(vec4(3.0e38), tNear, hit);
      orderPair(d.x, e.x, d.y, e.y);
      orderPair(d.z, e.z, d.w, e.w);
      orderPair(d.x, e.x, d.z, e.z);
      orderPair(d.y, e.y, d.w, e.w);
      orderPair(d.y, e.y, d.z, e.z);
      uint n = uint(hit.x) + uint(hit.y) + uint(hit.z) + uint(hit.w);
      if (n == 0u) {
        current = sp > 0u ? stack[--sp] : kNoEntry;
      } else if (sp + n > TRAVERSAL_STACK_SIZE) {
        overflow = true;  // reported as an incomplete walk, never silently wrong
        current = kNoEntry;
      } else {
        if (n > 3u) stack[sp++] = e.w;
        if (n > 2u) stack[sp++] = e.z;
        if (n > 1u) stack[sp++] = e.y;
        current = e.x;
      }
    }
    while (current != kNoEntry && (current & kLeafTag) != 0u) {
      if (intersectLeaf(current, shear, best) && anyHit) return best;
      current = sp > 0u ? stack[--sp] : kNoEntry;
    }
  }
  complete = !overflow && current == kNoEntry;
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
    while (current != kNoEntry && (current & kLeafTag) == 0u) {
      int base = int(4u * current);
      vec4 a0 = texelFetch(bvhNodes, base), a1 = texelFetch(bvhNodes, base + 1);
      vec4 b0 = texelFetch(bvhNodes, base + 2), b1 = texelFetch(bvhNodes, base + 3);
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
      uint e0 = count0 > 0u ? leafEntry(floatBitsToUint(a0.w), count0) : floatBitsToUint(a0.w);
      uint e1 = count1 > 0u ? leafEntry(floatBitsToUint(b0.w), count1) : floatBitsToUint(b0.w);
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
    while (current != kNoEntry && (current & kLeafTag) != 0u) {
      if (intersectLeaf(current, shear, best) && anyHit) return best;
      current = sp > 0u ? stack[--sp] : kNoEntry;
    }
  }
  complete = current == kNoEntry;
  return best;
}
#endif
