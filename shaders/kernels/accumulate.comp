#version 460
#extension GL_GOOGLE_include_directive : require
// Stage 5: each finished path's estimate into its pixel's batch sums. One invocation per pixel walks that
// pixel's samples of the pass, so no atomics. Non-finite estimates are counted and left out, never written;
// finite ones always count, however large (FilmPixel's high sums). A filter other than the pixel's box weighs each
// estimate by its filter weight (pixel_filter.h; negative in a filter's negative lobes). Sample slot s is the
// pixel's sample pc.sampleIndex + s, so its replicate (sampler.h) is known here. Each sample's camera-path vertices
// add to the pixel's cost (split children are not counted). A pass of sample runs (adaptive
// sampling) has one invocation a run: its paths are consecutive.
#include "common.glsl"

void main() {
  uint i = invocationIndex();
  if (i >= pc.pixelCount) return;
  uint pixel = pc.firstPixel + i, firstPath = i, stride = pc.pixelCount, samples = pc.samplesPerPass;
  uint firstSample = pc.sampleIndex;
  if (pc.sampleRuns != 0u) {
    SampleRun run = loadSampleRun(i);
    pixel = run.pixel, firstPath = run.firstPath, stride = 1u, samples = run.paths, firstSample = run.firstSample;
  }
  FilmPixel f = film[pixel];
  for (uint s = 0u; s < samples; ++s) {
    vec4 estimate = loadRadiance(firstPath + s * stride);
    f.sumSqHigh.w += float(loadPathDepth(firstPath + s * stride) + 1u);  // every sample's cost, finite or not
    vec3 L = kPixelFilterSampling == kPixelFilterSamplingUniform ? estimate.rgb : estimate.rgb * estimate.w;
    if (allFinite(L)) {
      bvec3 high = greaterThanEqual(abs(L), vec3(kFilmHighThreshold));
      vec3 low = mix(L, vec3(0.0), high), scaled = mix(vec3(0.0), L * kFilmHighScale, high);
      f.sum += vec4(low, 1.0);
      f.sumSq.rgb += low * low;
      f.sumHigh += vec4(scaled, any(high) ? 1.0 : 0.0);  // w: samples kept in the high sums
      f.sumSqHigh.rgb += scaled * scaled;
      // Constant indices: a dynamically indexed private array is scratch memory on llvmpipe.
      uint replicate = (firstSample + s) % kSampleReplicates;
      for (uint r = 0u; r + 1u < kMaxSampleReplicates; ++r)
        if (replicate == r && r + 1u < kSampleReplicates) f.replicate[r] += vec4(L, 1.0);
    } else {
      f.sumSq.w += 1.0;
    }
  }
  storeFilmPixel(pixel, f);
}
