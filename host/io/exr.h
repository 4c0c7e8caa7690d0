// OpenEXR output and input of a render: mean RGB, per-pixel variance of the mean, sample count.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "render/film.h"

namespace vkmc {

struct ExrImage {
  int width = 0, height = 0;
  std::map<std::string, std::vector<float>> channels;  // name -> width*height floats
};

// Channels R, G, B (mean), variance.R/G/B (variance of the mean), samples. Written to a temporary file in
// the same folder and renamed, so a failed run never leaves a partial or clobbered file.
void writeFilmExr(const std::string& path, const Film& film);
void writeExr(const std::string& path, const ExrImage& image);
ExrImage readExr(const std::string& path);

// Writes `bytes` through a temporary name and a rename (for reports and PNGs too).
void writeFileAtomically(const std::string& path, const std::string& bytes);
std::string temporaryPathFor(const std::string& path);
// Renames a finished temporary file onto path; on failure removes it and throws vkmc::Error.
void commitTemporary(const std::string& tmp, const std::string& path);

}  // namespace vkmc
