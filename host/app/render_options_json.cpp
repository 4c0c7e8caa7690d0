// RenderOptions <-> JSON (see the header).
#include "app/render_options_json.h"

#include <cmath>
#include <filesystem>
#include <limits>
#include <type_traits>

#include "error.h"
#include "scene/studio_environment.h"

namespace vkmc {
namespace {

std::string absolutePath(const std::string& path) {
  if (path.empty()) return path;
  std::error_code ec;
  std::filesystem::path p = std::filesystem::absolute(path, ec);
  return ec ? path : p.lexically_normal().string();
}

nlohmann::json vec3Json(const std::optional<glm::vec3>& v) {
  return v ? nlohmann::json::array({v->x, v->y, v->z}) : nlohmann::json(nullptr);
}

// A number of type T taken only from JSON of its kind and range: the options come from a checkpoint, which a forger
// can seal, and nlohmann's conversion of 1e300 to an integer or a float is undefined behaviour.
template <class T>
T numberFrom(const nlohmann::json& j) {
  if constexpr (std::is_unsigned_v<T>) {
    if (!j.is_number_unsigned() || j.get<uint64_t>() > std::numeric_limits<T>::max())
      throw Error("malformed render options: " + j.dump() + " is not a count");
    return T(j.get<uint64_t>());
  } else {
    if (!j.is_number() || !(std::abs(j.get<double>()) <= double(std::numeric_limits<T>::max())))
      throw Error("malformed render options: " + j.dump() + " is not a number in range");
    return T(j.get<double>());
  }
}

std::optional<glm::vec3> vec3From(const nlohmann::json& j) {
  if (j.is_null()) return std::nullopt;
  return glm::vec3(numberFrom<float>(j.at(0)), numberFrom<float>(j.at(1)), numberFrom<float>(j.at(2)));
}

template <class T>
nlohmann::json optionalJson(const std::optional<T>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

template <class T>
std::optional<T> optionalFrom(const nlohmann::json& j) {
  return j.is_null() ? std::nullopt : std::optional<T>(numberFrom<T>(j));
}

}  // namespace

nlohmann::json renderOptionsJson(const RenderOptions& o) {
  nlohmann::json j = {
      {"scene", absolutePath(o.scenePath)},
      {"width", optionalJson(o.width)},
      {"height", optionalJson(o.height)},
      {"spp", o.spp},
      {"estimator", o.estimator.toJson()},
      {"seed", o.seed},
      {"camera", optionalJson(o.cameraIndex)},
      {"look_from", vec3Json(o.lookFrom)},
      {"look_at", vec3Json(o.lookAt)},
      {"fov", o.fovDegrees},
      {"background", vec3Json(o.background)},
      {"environment", o.environmentPath == kStudioEnvironment ? o.environmentPath : absolutePath(o.environmentPath)},
      {"environment_rotation", o.environmentRotation},
      {"environment_strength", o.environmentStrength},
      {"filter", {{"name", pixelFilterName(o.filter.kind)}, {"radius", o.filter.radius}}},
      {"time_budget", o.timeBudget},
      {"reference", absolutePath(o.referencePath)},
      {"specialize", o.specialize},
      {"without_textures", o.withoutTextures},
      {"workgroup", o.workgroupSize},
      {"wavefront_paths", o.wavefrontPaths},
      {"integrator", toString(o.integrator)}};
  // Only where it is on: the options of a render without it read as they did before it existed.
  if (o.estimatorAuto) j["estimator_auto"] = {{"pinned", o.pinnedKeys}};
  return j;
}

RenderOptions renderOptionsFromJson(const nlohmann::json& j) {
  RenderOptions o;
  try {
    o.scenePath = j.at("scene");
    o.width = optionalFrom<uint32_t>(j.at("width"));
    o.height = optionalFrom<uint32_t>(j.at("height"));
    o.spp = numberFrom<uint32_t>(j.at("spp"));
    o.estimator.applyJson(j.at("estimator"));
    o.seed = numberFrom<uint32_t>(j.at("seed"));
    o.cameraIndex = optionalFrom<uint32_t>(j.at("camera"));
    o.lookFrom = vec3From(j.at("look_from"));
    o.lookAt = vec3From(j.at("look_at"));
    o.fovDegrees = numberFrom<float>(j.at("fov"));
    o.background = vec3From(j.at("background"));
    o.environmentPath = j.at("environment");
    o.environmentRotation = numberFrom<float>(j.at("environment_rotation"));
    o.environmentStrength = numberFrom<float>(j.at("environment_strength"));
    o.filter = pixelFilterFromJson(j.at("filter"));
    o.timeBudget = numberFrom<double>(j.at("time_budget"));
    o.referencePath = j.at("reference");
    o.specialize = j.at("specialize");
    o.withoutTextures = j.at("without_textures");
    o.workgroupSize = numberFrom<uint32_t>(j.at("workgroup"));
    // absent in checkpoints before it existed: the device's
    o.wavefrontPaths = j.contains("wavefront_paths") ? numberFrom<uint32_t>(j.at("wavefront_paths")) : 0u;
    o.integrator = integratorFromString(j.at("integrator"));
    if (j.contains("estimator_auto")) {
      o.estimatorAuto = true;
      for (const auto& key : j.at("estimator_auto").at("pinned")) o.pinnedKeys.insert(key.get<std::string>());
    }
  } catch (const nlohmann::json::exception& e) {
    throw Error(std::string("malformed render options: ") + e.what());
  }
  return o;
}

std::string differingRenderOptions(const nlohmann::json& a, const nlohmann::json& b) {
  std::string keys;
  for (const auto& [key, value] : a.items()) {
    if (key == "reference") continue;
    if (b.contains(key) && b.at(key) == value) continue;
    if (key == "estimator" && value.is_object() && b.contains(key) && b.at(key).is_object()) {
      for (const auto& [inner, v] : value.items())  // name the estimator's keys: "estimator.rr"
        if (!b.at(key).contains(inner) || b.at(key).at(inner) != v) keys += (keys.empty() ? "" : ", ") + key + "." + inner;
      continue;
    }
    keys += (keys.empty() ? "" : ", ") + key;
  }
  // wavefront_paths came later than some checkpoints: one without it ran the device's choice, as `b` does.
  for (const auto& [key, value] : b.items())
    if (!a.contains(key) && key != "wavefront_paths") keys += (keys.empty() ? "" : ", ") + key;
  return keys;
}

}  // namespace vkmc
