// Texture lookups in the device forms vkmc could keep textures in, side by side on one scene's textures
// (`vkmc bench-textures`, shaders/probes/texture_forms.comp), both reading the same texture pages
// (render/texture_atlas.h):
//   sampled image   the renderer's form: the pages as an array image, filtered and sRGB-decoded by the sampler
//   texel buffer    the pages' texels in a storage texel buffer, bilinear filtering in the kernel, sRGB decoded
//                   by pow per tap (the renderer's form until 2026-11-28)
#pragma once
#include <string>
#include <vector>

#include "../shaders/shared/layout.h"
#include "scene/scene.h"
#include "vk/context.h"

namespace vkmc {

// Shading's lookups: one per invocation, at a point chosen on the surface by area (uv0 interpolated at uniform
// barycentrics) with the four slot textures of that triangle's material (kNoTexture where a slot is empty).
// coherent: ordered by material and by the uv's Morton code, as camera rays meet neighbouring points;
// otherwise in random order, as bounce rays do.
std::vector<gpu::TestRay> makeTextureLookups(const Scene& scene, uint32_t count, bool coherent, uint32_t seed);
uint64_t countTextureLookups(const std::vector<gpu::TestRay>& lookups);  // texture samples, empty slots excluded

struct TextureFormTiming {
  std::string form;
  std::vector<double> nsPerLookup;  // one per round
  double maxDifference = 0.0;       // largest |channel difference| of a lookup sum from the renderer's form
  std::string skipped;              // why the form did not run ("" when it did)
};

// Every form once (results compared), then `rounds` interleaved timed dispatches of each.
std::vector<TextureFormTiming> timeTextureForms(vk::Context& ctx, const Scene& scene, const std::vector<gpu::TestRay>& lookups,
                                                int rounds);

}  // namespace vkmc
