// Prints shaders/shared/layer_albedo_table.h: vkmc-layer-albedo > shaders/shared/layer_albedo_table.h
#include <cstdio>

#include "render/layer_albedo.h"

int main() {
  std::fputs(vkmc::layerAlbedoHeader().c_str(), stdout);
  return 0;
}
