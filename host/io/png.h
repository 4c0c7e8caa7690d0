// PNG previews: the mean image through a look (io/tone_map.h), the efficiency map, contact sheets.
#pragma once
#include <string>

#include "render/film.h"

#include <vector>

#include "io/exr.h"
#include "io/tone_map.h"

namespace vkmc {
struct FilmPreview {
  std::string png;
  double stops = 0.0;          // the exposure applied (the look's, or the automatic one)
  double clippedShare = 0.0;   // the share of pixels white (255) in some channel
  double backdropShare = 0.0;  // the share of pixels showing only the backdrop (not in the highlights kept)
};
// backdrop: the grey escaped camera rays see (RenderOutcome::backdrop), or 0 where there is none.
FilmPreview encodeFilmPng(const Film& film, const PreviewLook& look, float backdrop = 0.0f);
// The efficiency channel (Film::efficiency) in false colour: log10 of it from the image's 1st to 99th percentile
// mapped onto viridis (dark blue: noise that costs much; yellow: cheap and clean); grey where the pixel shows no
// variance; black where no efficiency can be told (no variance estimated).
std::string encodeEfficiencyPng(const Film& film);
// The same from efficiencies per pixel (an EXR's `efficiency` channel: `vkmc compare --efficiency-png`).
std::string encodeEfficiencyPng(const std::vector<double>& efficiency, uint32_t width, uint32_t height);
// Images side by side (same size), each under its label, with one shared exposure and the neutral tone map.
void writeContactSheet(const std::string& path, const std::vector<ExrImage>& images, const std::vector<std::string>& labels,
                       float exposureStops);
std::string encodeContactSheet(const std::vector<ExrImage>& images, const std::vector<std::string>& labels, float exposureStops);
}  // namespace vkmc
