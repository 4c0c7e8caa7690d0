// The world a test's glTF declares (scene.h's World): lights-only where it has lights of its own (a material with an
// emissive factor and no emissive map, or a KHR_lights_punctual light), else white, the uniform environment its
// expected values assume: the rule by which the renderer lit undeclared files before the studio, read from the
// JSON (so an unlit material, whose base colour is its emission, or an emissiveStrength of 0 reads as no light).
// Without a declaration the studio would light every test scene as it lights a user's file.
#pragma once
#include <nlohmann/json.hpp>

#include <fstream>
#include <string>

namespace vkmc::test {

inline bool hasOwnLights(const nlohmann::json& gltf) {
  if (gltf.contains("extensions") && gltf["extensions"].contains("KHR_lights_punctual")) return true;
  for (const nlohmann::json& m : gltf.value("materials", nlohmann::json::array())) {
    if (!m.is_object() || m.contains("emissiveTexture") || !m.contains("emissiveFactor")) continue;
    for (const nlohmann::json& c : m["emissiveFactor"])
      if (c.is_number() && c.get<double>() > 0.0) return true;
  }
  return false;
}

// The same JSON with scenes[0].extras.vkmc_world set; text that is not a JSON object (a malformed fixture) stays as is.
inline std::string withLabWorld(const std::string& text) {
  nlohmann::json gltf = nlohmann::json::parse(text, nullptr, false);
  if (!gltf.is_object() || !gltf.contains("scenes") || !gltf["scenes"].is_array() || gltf["scenes"].empty() ||
      (gltf.contains("scene") && !gltf["scene"].is_number_unsigned()))
    return text;
  const size_t scene = gltf.value("scene", 0u) < gltf["scenes"].size() ? gltf.value("scene", 0u) : 0u;
  if (!gltf["scenes"][scene].is_object()) return text;
  gltf["scenes"][scene]["extras"]["vkmc_world"] = hasOwnLights(gltf) ? "lights-only" : "white";
  return gltf.dump();
}

// Takes the declaration out of a written .gltf again: the file then renders as a user's file does, in the studio.
inline std::string withoutWorld(const std::string& gltfPath) {
  nlohmann::json gltf;
  std::ifstream(gltfPath) >> gltf;
  gltf["scenes"][0].erase("extras");
  std::ofstream(gltfPath) << gltf.dump();
  return gltfPath;
}

}  // namespace vkmc::test
