// The tinybvh kernels' buffers, defined once for the host and both kernels. They sit on storage-buffer bindings of
// vkmc's shared descriptor set (layout.h) that no trace kernel reads, so the tool reuses vk::KernelLayout as is.
#ifndef VKMC_TINYBVH_BINDINGS_H
#define VKMC_TINYBVH_BINDINGS_H
#include "layout.h"

#define TINYBVH_BINDING_NODES BINDING_PATHS   // vec4[]: BVH_GPU::BVHNode (4 each) or CWBVH blocks (5 per node)
#define TINYBVH_BINDING_INDICES BINDING_HITS  // uint[]: BVH_GPU's primitive indices (Aila-Laine kernel only)
#define TINYBVH_BINDING_TRIANGLES \
  BINDING_RAY_QUEUES                            // vec4[]: Aila-Laine: the scene's vertices, 3 per triangle;
                                                // CWBVH: e1, e2, v0 (w: triangle index) per leaf slot
#define TINYBVH_BINDING_RAYS BINDING_TEST_RAYS  // TestRay[]
#define TINYBVH_BINDING_HITS BINDING_TEST_HITS  // vec4[]: t, u, v, triangle bits; t = kTinybvhFar on a miss
#define TINYBVH_BINDING_WALK_STATS \
  BINDING_DEEP_WALKS  // uvec2[]: loop iterations, triangle tests per ray (counting
                      // variants only, built with TINYBVH_WALK_STATS)

VKMC_BEGIN_NAMESPACE
VKMC_CONST float kTinybvhFar = 1e30f;  // tinybvh's BVH_FAR: the kernels' tmax, and t on a miss
VKMC_END_NAMESPACE
#endif
