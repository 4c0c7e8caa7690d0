#version 460
#extension GL_GOOGLE_include_directive : require
// The lecture's bad-pdf counterexample, on the device: f = 0.01 on [0, 0.01) and 1.01 on [0.01, 1] (its
// integral is 1), estimated by sampling p = 99.01 on [0, 0.01) and 0.01 elsewhere (shaped unlike f) and by
// uniform sampling. Each invocation sums pc.sampleIndex samples of both estimators: (sum, sum of squares) x 2.
#include "common.glsl"

layout(binding = BINDING_TEST_HITS, std430) writeonly buffer Sums { vec4 sums[]; };

float integrand(float x) { return x < 0.01 ? 0.01 : 1.01; }
float badPdf(float x) { return x < 0.01 ? 99.01 : 0.01; }
// Inversion of the bad pdf's CDF, which is 0.9901 at x = 0.01.
float sampleBadPdf(float u) { return u < 0.9901 ? u / 99.01 : 0.01 + (u - 0.9901) / 0.01; }

void main() {
  uint id = invocationIndex();
  if (id >= pc.pathCount) return;
  uint key = pathKey(pc.seed, id, 0u);
  vec4 acc = vec4(0.0);
  for (uint i = 0u; i < pc.sampleIndex; ++i) {
    float xb = sampleBadPdf(randomUnit(key, 2u * i));
    float bad = integrand(xb) / badPdf(xb);
    float uni = integrand(randomUnit(key, 2u * i + 1u));
    acc += vec4(bad, bad * bad, uni, uni * uni);
  }
  sums[id] = acc;
}
