// RenderOptions as JSON and back: what a checkpoint records about the render it belongs to, so that
// `vkmc render --resume FILE` needs nothing else and a resume with options refuses ones that differ.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "app/render_job.h"

namespace vkmc {

// Every option that decides the image, with input paths made absolute (a resume may run in another folder).
nlohmann::json renderOptionsJson(const RenderOptions& options);
// Throws vkmc::Error on a malformed object; the result still goes through validateOptions in runRender.
RenderOptions renderOptionsFromJson(const nlohmann::json& j);
// The keys whose values differ between two renderOptionsJson objects, comma-separated ("" when none). `reference`
// is left out: it changes the report, not the image.
std::string differingRenderOptions(const nlohmann::json& a, const nlohmann::json& b);

}  // namespace vkmc
