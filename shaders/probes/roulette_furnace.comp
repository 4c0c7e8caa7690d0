#version 460
#extension GL_GOOGLE_include_directive : require
// Stability case 1 at 0.1%: the shade stage's continuation and roulette arithmetic on an analytic furnace, where
// every ray hits a Lambertian surface of albedo a that emits Le (L = Le / (1 - a)). Intersection is left out:
// a 5-sigma interval of 0.1% needs ~2.5e7 paths of ~1 / (1 - a) vertices each, hours through the wavefront on
// lavapipe, seconds here. What remains is exactly the per-vertex code of shade.comp for a Lambertian scene:
// cosine sampling and its pdf, the BRDF weight, the roulette decision (roulette.h's rouletteStep, as shade calls
// it), the random-number dimensions, float throughput over thousands of vertices.
//
// One flat loop, four vertices per iteration (unrolled by hand, no inner loop): a lane starts a new path when one
// ends until it has spent its vertex budget, then finishes the path in flight (dropping it would favour short
// paths). llvmpipe runs every statement for all 8 lanes of a SIMD program, so the loop's own overhead and the
// masked path restart are paid per iteration: four vertices an iteration took a vertex from 5.3-5.9 to 3.3 ns
// (eight: 3.1 ns). Nested loops ran into llvmpipe's silent loop limit (docs/journal/performance.md, "A lavapipe
// pitfall"); a lane whose loop is cut still has a path in flight, and says so.
// Output per invocation: FurnaceProbeLane.
#include "layout.h"
#include "rng.h"
#include "sampling.h"
#include "roulette.h"

layout(local_size_x_id = SPEC_WORKGROUP_SIZE) in;
layout(constant_id = SPEC_RR_MODE) const uint kRouletteMode = kRouletteThroughput;  // as in shade: no fixed mode here
layout(push_constant, std430) uniform Push { FurnaceProbePush probe; };
layout(binding = BINDING_ROULETTE_TABLE, std430) readonly buffer RouletteTable { float rouletteScale[]; };
layout(binding = BINDING_TEST_HITS, std430) writeonly buffer Lanes { FurnaceProbeLane lanes[]; };

// The efficiency scales, read once per lane: a storage-buffer load per vertex made llvmpipe's vertex 1.6x as
// expensive (docs/architecture.md, "What lavapipe does with these kernels": SSBO loads loop over the lanes). The same values shade reads from rouletteScale.
float scaleRows[kRouletteTableDepths];

// shade.comp's continuation at a Lambertian vertex with cosine (= BSDF) sampling, and its roulette. Written without
// early returns (a path that ends discards beta), which llvmpipe runs a little faster; the arithmetic is the same.
bool continuePath(uint key, uint depth, inout float beta) {
  vec2 u = vec2(randomUnit(key, bounceDim(depth, kDimBsdf)), randomUnit(key, bounceDim(depth, kDimBsdf + 1u)));
  vec3 wi = sampleCosineHemisphere(u);
  float pdf = cosineHemispherePdf(wi.z);
  bool continues = pdf > 0.0 && wi.z > 0.0;
  beta *= probe.albedo * kInvPi * (wi.z / pdf);
  bool applies = continues && rouletteApplies(depth, probe.rouletteDepth);
  float scale = kRouletteMode == kRouletteEfficiency ? scaleRows[min(depth, kRouletteTableDepths - 1u)] : 1.0;
  RouletteStep rr = rouletteStep(kRouletteMode, beta, scale, 0.0, randomUnit(key, bounceDim(depth, kDimRoulette)));
  beta /= applies ? rr.survival : 1.0;
  return continues && (!applies || rr.survives);
}

// One vertex of a path in flight: its emission, then its continuation.
void vertexStep(uint key, inout uint depth, inout float beta, inout float radiance, inout uint vertices, inout bool inFlight) {
  if (!inFlight) return;
  radiance += beta * probe.emission;
  ++vertices;
  inFlight = continuePath(key, depth, beta);
  ++depth;
}

void main() {
  uint id = gl_GlobalInvocationID.x;
  if (id >= probe.invocations) return;
  for (uint d = 0u; d < kRouletteTableDepths; ++d) scaleRows[d] = rouletteScale[d];
  // Kahan sums (precise: the compiler must not cancel the compensation away).
  precise float sum = 0.0, sumC = 0.0, sumSq = 0.0, sumSqC = 0.0;
  uint paths = 0u, vertices = 0u, depth = 0u;
  uint key = pathKey(probe.seed, id, 0u);
  float beta = 1.0;  // gray furnace: one channel stands for all three
  float radiance = 0.0;
  bool inFlight = true;
  for (;;) {
    vertexStep(key, depth, beta, radiance, vertices, inFlight);
    vertexStep(key, depth, beta, radiance, vertices, inFlight);
    vertexStep(key, depth, beta, radiance, vertices, inFlight);
    vertexStep(key, depth, beta, radiance, vertices, inFlight);
    if (inFlight) continue;
    precise float y = radiance - sumC;
    precise float t = sum + y;
    sumC = (t - sum) - y;
    sum = t;
    y = radiance * radiance - sumSqC;
    t = sumSq + y;
    sumSqC = (t - sumSq) - y;
    sumSq = t;
    ++paths;
    if (vertices >= probe.verticesPerInvocation) break;
    key = pathKey(probe.seed, id, paths);
    beta = 1.0;
    radiance = 0.0;
    depth = 0u;
    inFlight = true;
  }
  FurnaceProbeLane lane;
  lane.sum = sum;
  lane.sumSq = sumSq;
  lane.vertices = vertices;
  lane.paths = paths | (inFlight ? 0x80000000u : 0u);
  lanes[id] = lane;
}
