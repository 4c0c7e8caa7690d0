// Directional albedos of the layers that sit on top of a glTF material (clearcoat, sheen), integrated from the
// shared lobe functions: the tables in shaders/shared/layer_albedo_table.h are generated from these
// (`vkmc-layer-albedo > shaders/shared/layer_albedo_table.h`) and tests/unit/layer_albedo_test.cpp keeps them equal.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace vkmc {

// E(cos) = integral of f(wo, wi) cos(wi) over the hemisphere, for wo at cosine cosO from the normal.
double coatAlbedo(double cosO, double alpha);   // GGX with Schlick F0 = 0.04 (microfacet.h coatReflectionEval)
double sheenAlbedo(double cosO, double alpha);  // Charlie sheen (sheen.h sheenEval)

// The table the kernels interpolate: per layer, kLayerAlbedoSize x kLayerAlbedoSize nodes over (alpha, cos) in
// [0, 1]^2, each node the largest albedo within half a cell of it, so interpolated values bound E from above and
// the layers below are never scaled too little (energy stays <= 1).
std::vector<float> layerAlbedoTable();
float layerAlbedoNode(uint32_t layer, uint32_t alphaIndex, uint32_t cosIndex);  // one entry of it
std::string layerAlbedoHeader();

}  // namespace vkmc
