// sRGB PNG preview of the mean image, with an exposure in stops.
#pragma once
#include <string>

#include "render/film.h"

#include <vector>

#include "io/exr.h"

namespace vkmc {
void writeFilmPng(const std::string& path, const Film& film, float exposureStops);
std::string encodeFilmPng(const Film& film, float exposureStops);
// Images side by side (same size), each under its label, tone-mapped to sRGB with one shared exposure.
void writeContactSheet(const std::string& path, const std::vector<ExrImage>& images, const std::vector<std::string>& labels,
                       float exposureStops);
std::string encodeContactSheet(const std::vector<ExrImage>& images, const std::vector<std::string>& labels, float exposureStops);
}  // namespace vkmc
