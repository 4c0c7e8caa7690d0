// BVH traversal over the two-boxes-per-node layout: both children's slabs are tested at once, leaves are
// intersected as soon as they are hit (tMax shrinks early), the nearer inner child is visited first.
#define TRAVERSAL_STACK_SIZE 64

// Returns vec4(t, b1, b2, triangle bits); triangle = kMissPrimitive when nothing is hit in (0, tMax).
vec4 traceRay(vec3 origin, vec3 dir, float tMax, bool anyHit) {
  RayShear shear = makeRayShear(origin, dir);
  vec3 invDir = safeInverse(dir);
  vec3 originScaled = origin * invDir;
  vec4 best = vec4(tMax, 0.0, 0.0, uintBitsToFloat(kMissPrimitive));
  uint stack[TRAVERSAL_STACK_SIZE];
  uint sp = 0u;
  uint node = 0u;
  while (true) {
    int base = int(4u * node);
    vec4 a0 = texelFetch(bvhNodes, base), a1 = texelFetch(bvhNodes, base + 1);
    vec4 b0 = texelFetch(bvhNodes, base + 2), b1 = texelFetch(bvhNodes, base + 3);
    vec3 l0 = a0.xyz * invDir - originScaled, h0 = a1.xyz * invDir - originScaled;
    vec3 l1 = b0.xyz * invDir - originScaled, h1 = b1.xyz * invDir - originScaled;
    vec3 n0 = min(l0, h0), f0 = max(l0, h0), n1 = min(l1, h1), f1 = max(l1, h1);
    // The far distance is widened by 2 gamma(3) (Ize 2013) so rounding never culls a box a ray grazes.
    float near0 = max(max(n0.x, n0.y), max(n0.z, 0.0)), far0 = min(min(f0.x, f0.y) * kSlabWiden, min(f0.z * kSlabWiden, best.x));
    float near1 = max(max(n1.x, n1.y), max(n1.z, 0.0)), far1 = min(min(f1.x, f1.y) * kSlabWiden, min(f1.z * kSlabWiden, best.x));
    bool hit0 = near0 <= far0, hit1 = near1 <= far1;
    uint ref0 = floatBitsToUint(a0.w), count0 = floatBitsToUint(a1.w);
    uint ref1 = floatBitsToUint(b0.w), count1 = floatBitsToUint(b1.w);
    for (int c = 0; c < 2; ++c) {
      bool isLeafHit = c == 0 ? (hit0 && count0 > 0u) : (hit1 && count1 > 0u);
      if (!isLeafHit) continue;
      uint first = c == 0 ? ref0 : ref1;
      uint last = first + (c == 0 ? count0 : count1);
      for (uint tri = first; tri < last; ++tri) {
        vec3 v0, v1, v2;
        triangleVertices(tri, v0, v1, v2);
        vec3 h = intersectTriangle(shear, v0, v1, v2, best.x);
        if (h.x > 0.0) {
          best = vec4(h, uintBitsToFloat(tri));
          if (anyHit) return best;
        }
      }
    }
    hit0 = hit0 && count0 == 0u;
    hit1 = hit1 && count1 == 0u;
    if (hit0 && hit1) {
      bool firstIsNear = near0 <= near1;
      stack[sp++] = firstIsNear ? ref1 : ref0;
      node = firstIsNear ? ref0 : ref1;
    } else if (hit0) {
      node = ref0;
    } else if (hit1) {
      node = ref1;
    } else {
      if (sp == 0u) break;
      node = stack[--sp];
    }
  }
  return best;
}
