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

// Channels R, G, B (mean), variance.R/G/B (variance of the mean), variance.dof (its degrees of freedom: samples - 1,
// or replicates - 1 under the QMC samplers; Film::varianceDof), samples, cost (a sample's mean camera-path
// vertices: Film::cost) and efficiency (1 / (relative variance of the mean x vertices spent): Film::efficiency, an
// efficiency map); no variance or efficiency channels where the film estimates none (Film::estimatesVariance: one scrambling a
// pixel). Written all or nothing (io/output_files.h): a failed run never leaves a partial or clobbered file.
ExrImage filmToImage(const Film& film);
void writeFilmExr(const std::string& path, const Film& film);
void writeExr(const std::string& path, const ExrImage& image);
std::string encodeFilmExr(const Film& film);
std::string encodeExr(const ExrImage& image);
// The most float values (pixels x channels) readExr allocates: 2 GiB, an 8192 x 8192 render with all its channels.
constexpr uint64_t kExrMaxValues = uint64_t(1) << 29;
// Throws vkmc::Error naming the file when it is not a regular file, not an EXR, or declares more than maxValues
// values (checked from its header, before anything is allocated).
ExrImage readExr(const std::string& path, uint64_t maxValues = kExrMaxValues);
// The same from the file's bytes; `name` names it in errors.
ExrImage decodeExr(const std::string& bytes, const std::string& name, uint64_t maxValues = kExrMaxValues);

}  // namespace vkmc
