// BVH traversal over the two-boxes-per-node layout, in while-while form (Aila & Laine 2009): each lane walks
// inner nodes until it holds a leaf, then the lanes test leaves together. On SIMD hardware (llvmpipe's 8
// lanes, a GPU's warp) this keeps lanes busy with the same kind of work. Leaves are stack entries too, tagged
// with the high bit and their size; the nearer child is visited first.
// llvmpipe has a hang guard that ends shader loops after 65535 iterations (LP_MAX_TGSI_LOOP_ITERATIONS) without
// any error; the analytic furnace probe lost paths to it. A walk of 400k leaves measured complete, but a walk
// that did not end on its own must never pass for a hit or a miss: `complete` says whether it did.
#define TRAVERSAL_STACK_SIZE 64
const uint kLeafTag = 0x80000000u;
const uint kNoEntry = 0xffffffffu;

uint leafEntry(uint first, uint count) { return kLeafTag | ((count - 1u) << 27u) | first; }

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
      uint first = current & 0x07ffffffu;
      uint last = first + ((current >> 27u) & 0xfu) + 1u;
      for (uint tri = first; tri < last; ++tri) {
        vec3 v0, v1, v2;
        triangleVertices(tri, v0, v1, v2);
        vec3 h = intersectTriangle(shear, v0, v1, v2, best.x);
        if (h.x > 0.0) {
          best = vec4(h, uintBitsToFloat(tri));
          if (anyHit) return best;
        }
      }
      current = sp > 0u ? stack[--sp] : kNoEntry;
    }
  }
  complete = current == kNoEntry;
  return best;
}
