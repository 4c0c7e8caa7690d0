// sRGB PNG preview of the mean image, with an exposure in stops.
#pragma once
#include <string>

#include "render/film.h"

#include <vector>

#include "io/exr.h"

namespace vkmc {
void writeFilmPng(const std::string& path, const Film& film, float exposureStops);
std::string encodeFilmPng(const Film& film, float exposureStops);
// The efficiency channel (Film::efficiency) in false colour: log10 of it from the image's 1st to 99th percentile
// mapped onto viridis (dark blue: noise that costs much; yellow: cheap and clean); grey where the pixel shows no
// variance; black where no efficiency can be told (no variance estimated).
std::string encodeEfficiencyPng(const Film& film);
// The same from efficiencies per pixel (an EXR's `efficiency` channel: `vkmc compare --efficiency-png`).
std::string encodeEfficiencyPng(const std::vector<double>& efficiency, uint32_t width, uint32_t height);
// Images side by side (same size), each under its label, tone-mapped to sRGB with one shared exposure.
void writeContactSheet(const std::string& path, const std::vector<ExrImage>& images, const std::vector<std::string>& labels,
                       float exposureStops);
std::string encodeContactSheet(const std::vector<ExrImage>& images, const std::vector<std::string>& labels, float exposureStops);
}  // namespace vkmc
