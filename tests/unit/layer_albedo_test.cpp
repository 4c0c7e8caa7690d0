// The clearcoat and sheen albedo table the kernels read (shaders/shared/layer_albedo_table.h) is what
// host/render/layer_albedo.cpp integrates from the shared lobe functions, and bounds the albedo from above.
#include <gtest/gtest.h>

#include "../shaders/shared/layer_albedo.h"
#include "../shaders/shared/rng.h"
#include "render/layer_albedo.h"

using namespace vkmc;

TEST(LayerAlbedo, TheCommittedTableIsTheGeneratorsOutput) {
  // A spread of nodes (the whole table takes ~10 s to integrate): regenerate with
  // build/vkmc-layer-albedo > shaders/shared/layer_albedo_table.h when a lobe changes.
  const uint32_t n = gpu::kLayerAlbedoSize;
  for (uint32_t layer = 0; layer < gpu::kLayerAlbedoLayers; ++layer)
    for (uint32_t a : {0u, 1u, 7u, 16u, n - 1})
      for (uint32_t c : {0u, 2u, 11u, 24u, n - 1}) {
        float committed = gpu::kLayerAlbedo[(layer * n + a) * n + c];
        EXPECT_NEAR(committed, layerAlbedoNode(layer, a, c), 2e-6f)
            << "layer " << layer << " alpha node " << a << " cos node " << c;
      }
}

TEST(LayerAlbedo, InterpolatedValuesBoundTheAlbedoFromAbove) {
  // Up to the quadrature's own error (~1e-3): the layers below are never scaled by too little.
  for (uint32_t i = 0; i < 60; ++i) {
    uint key = gpu::pathKey(77u, i, 0u);
    double c = 0.02 + 0.98 * gpu::randomUnit(key, 0u), alpha = 0.02 + 0.98 * gpu::randomUnit(key, 1u);
    EXPECT_GE(gpu::layerAlbedo(gpu::kLayerAlbedoCoat, float(c), float(alpha)), coatAlbedo(c, alpha) - 2e-3) << c << " " << alpha;
    EXPECT_GE(gpu::layerAlbedo(gpu::kLayerAlbedoSheen, float(c), float(alpha)), sheenAlbedo(c, alpha) - 2e-3)
        << c << " " << alpha;
    EXPECT_LE(gpu::layerAlbedo(gpu::kLayerAlbedoCoat, float(c), float(alpha)), 1.0f);
  }
  // A smooth coat reflects exactly its Fresnel: 0.04 at normal incidence, all of it at grazing.
  EXPECT_NEAR(coatAlbedo(1.0, 0.0), 0.04, 1e-4);
  EXPECT_GT(coatAlbedo(0.01, 0.0), 0.9);
}
