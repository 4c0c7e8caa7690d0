// sRGB PNG preview of the mean image, with an exposure in stops.
#pragma once
#include <string>

#include "render/film.h"

namespace vkmc {
void writeFilmPng(const std::string& path, const Film& film, float exposureStops);
}
