// Error-against-time studies (`vkmc bench STUDY.json -o DIR`): a scene, an image size, a reference, named
// estimator configurations and an spp or time ladder; every configuration at every rung, repeated, in one
// process with the configurations interleaved so that machine noise hits them alike.
//
// Study file keys:
// | key            | meaning                                                                    | default |
// |----------------|----------------------------------------------------------------------------|---------|
// | name           | study name                                                                 | file    |
// | scene          | glTF path, relative to the study file                                      | —       |
// | width, height  | image size                                                                 | 64, 64  |
// | reference      | {"exr": path} or {"spp": N}: rendered with the first configuration, cached | spp 1024|
// | configurations | [{"name": ..., "estimator": {keys} or "estimator_file": path}, ...]        | —       |
// | spp / seconds  | the ladder: samples per pixel, or time budgets in seconds                  | —       |
// | repeats        | renders per configuration and rung (medians reported)                      | 3       |
// | seed           | first seed; repeat r uses seed + r                                         | 1       |
#pragma once
#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

#include "estimators/estimator_config.h"
#include "render/pixel_filter.h"

namespace vkmc {

struct StudyConfiguration {
  std::string name;
  EstimatorConfig estimator;
};

struct Study {
  std::string name;
  std::string scenePath;
  uint32_t width = 64, height = 64;
  std::string referenceExr;  // given reference, or empty
  // An analytic reference, the same in every pixel (a furnace's Le / (1 - albedo)): "reference": {"constant": [r, g, b]}
  std::optional<glm::vec3> referenceConstant;
  uint32_t referenceSpp = 1024;
  std::vector<StudyConfiguration> configurations;
  std::vector<double> ladder;  // spp or seconds
  bool timeLadder = false;
  uint32_t repeats = 3;
  uint32_t seed = 1;
  PixelFilter filter;                   // "filter": {"name": NAME, "radius": R}, for the reference and every configuration
  std::vector<std::string> inputFiles;  // the study file, its estimator files and reference: no output may name one
};

// The files a study writes into its output folder.
inline const char* const kStudyOutputFiles[] = {"results.csv", "results.json", "error_vs_time.svg", "summary.md",
                                                "equal_time.png"};

Study loadStudy(const std::string& path);

struct StudyRow {
  std::string configuration;
  double rung = 0.0;  // spp or seconds asked for
  uint32_t repeat = 0;
  uint32_t spp = 0;
  double seconds = 0.0, gpuSeconds = 0.0;
  uint64_t rays = 0;
  double mse = 0.0, relmse = 0.0, efficiency = 0.0;
  uint64_t nonfinite = 0;
};

// The order in which one repeat renders the configurations: as listed on even repeats, reversed on odd ones, so
// that no configuration always runs first or last (on this machine a render's speed drifts with its neighbours and
// the minutes; the seeds do not depend on the order). Rows are reported in the listed order whatever the run order.
std::vector<size_t> studyRunOrder(size_t configurations, uint32_t repeat);

// Runs the study and writes results.csv, results.json, error_vs_time.svg, summary.md and equal_time.png
// into outDir. Returns the rows.
std::vector<StudyRow> runStudy(const Study& study, const std::string& outDir);

}  // namespace vkmc
