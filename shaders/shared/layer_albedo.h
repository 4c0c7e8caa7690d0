// Bilinear lookup of the layer albedos (layer_albedo_table.h): E(cos theta_o, alpha) of the clearcoat or sheen lobe,
// an upper bound of the integrated albedo, so that scaling the layers below by 1 - weight x E keeps energy <= 1.
#ifndef VKMC_LAYER_ALBEDO_H
#define VKMC_LAYER_ALBEDO_H
#ifdef __cplusplus
#include "layer_albedo_table.h"
#define VKMC_LAYER_ALBEDO_NODE(i) kLayerAlbedo[i]
#else
// The kernels read the table from BINDING_LAYER_ALBEDO (common.glsl's layerAlbedoTable): as a constant array
// it made llvmpipe's pipeline compile take minutes instead of seconds.
#include "layer_albedo_layout.h"
#define VKMC_LAYER_ALBEDO_NODE(i) uintBitsToFloat(imageLoad(layerAlbedoTable, int(i)).x)
#endif
VKMC_BEGIN_NAMESPACE

VKMC_FN float layerAlbedo(uint layer, float cosTheta, float alpha) {
  float scale = float(kLayerAlbedoSize - 1u);
  float x = clamp(cosTheta, 0.0f, 1.0f) * scale, y = clamp(alpha, 0.0f, 1.0f) * scale;
  uint x0 = min(uint(x), kLayerAlbedoSize - 2u), y0 = min(uint(y), kLayerAlbedoSize - 2u);
  float fx = x - float(x0), fy = y - float(y0);
  uint i = (layer * kLayerAlbedoSize + y0) * kLayerAlbedoSize + x0;
  float low = mix(VKMC_LAYER_ALBEDO_NODE(i), VKMC_LAYER_ALBEDO_NODE(i + 1u), fx);
  float high = mix(VKMC_LAYER_ALBEDO_NODE(i + kLayerAlbedoSize), VKMC_LAYER_ALBEDO_NODE(i + kLayerAlbedoSize + 1u), fx);
  return mix(low, high, fy);
}

VKMC_END_NAMESPACE
#endif
