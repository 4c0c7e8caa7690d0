// The camera path of path id's pixel and sample (common.glsl cameraPathSample: a pixel's samples are ids accumulate
// can walk). Camera-ray roulette (the lecture's bad
// example): with probability q a sample is 0 (throughput 0), survivors weigh 1/(1-q). The pixel filter places the
// sample in its pixel and weighs it (radiance.w, applied by accumulate, so paths and roulette never see a sign).
#include "roulette.h"
#include "pixel_filter.glsl"

PathState cameraPath(uint id) {
  uvec2 pixelSample = cameraPathSample(id);
  uint pixel = pixelSample.x;
  uint sampleIndex = pixelSample.y;
  SampleStream stream = SampleStream(streamKey(kSampler, pc.seed, pixel, sampleIndex, kSampleReplicates), sampleIndex, pixel);
  vec2 u = sampleU2(stream, 0u);
  FilterSample fs = samplePixelFilter(u);
  vec2 jitter = fs.point;
  vec2 ndc = vec2(float(pixel % pc.width) + jitter.x, float(pixel / pc.width) + jitter.y) /
             vec2(float(pc.width), float(pc.height));
  vec2 screen = vec2(2.0 * ndc.x - 1.0, 1.0 - 2.0 * ndc.y);
  vec3 origin = pc.cameraOrigin.xyz;
  vec3 dir;
  if (pc.cameraOrigin.w == float(kCameraOrthographic)) {
    origin += screen.x * pc.cameraRight.xyz + screen.y * pc.cameraUp.xyz;
    dir = pc.cameraForward.xyz;
  } else {
    dir = normalize(pc.cameraForward.xyz + screen.x * pc.cameraRight.xyz + screen.y * pc.cameraUp.xyz);
  }
  PathState p;
  p.origin = vec4(origin, 1.0);  // w: pbrt-v4's etaScale (shading.glsl continuePath)
  p.direction = vec4(dir, 0.0);
  p.throughput = vec4(1.0);
  p.radiance = vec4(0.0, 0.0, 0.0, fs.weight);
  p.pixel = pixel;
  if (kHasDispersion != 0u) p.pixel |= min(uint(sampleU(stream, kDimSpectralChannel) * 3.0), 2u) << kPathPixelBits;
  p.rngKey = stream.key;
  p.depth = 0u;
  p.rootPath = id;
  if (kCameraRouletteQ > 0.0) {
    RouletteStep rr = fixedRoulette(kCameraRouletteQ, sampleU(stream, kDimCameraRoulette));
    p.throughput.rgb = vec3(rr.survives ? 1.0 / rr.survival : 0.0);
  }
  return p;
}
