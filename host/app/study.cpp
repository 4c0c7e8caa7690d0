// Study runner: reference (given or cached), interleaved ladder of renders, results, plot and summary.
#include "app/study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "analysis/error_metrics.h"
#include "analysis/summary_statistics.h"
#include "analysis/plots.h"
#include "app/render_job.h"
#include "error.h"
#include "io/exr.h"
#include "io/output_files.h"
#include "io/png.h"
#include "scene/gltf_loader.h"

namespace vkmc {
namespace fs = std::filesystem;

namespace {

std::string readFile(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw Error("'" + path + "' is not a regular file");  // a FIFO would block the read
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open '" + path + "'");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

uint64_t fnv1a(const std::string& bytes, uint64_t h = 1469598103934665603ull) {
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return h;
}

std::string cacheDir() {
  if (const char* d = std::getenv("VKMC_CACHE_DIR")) return d;
  if (const char* x = std::getenv("XDG_CACHE_HOME")) return std::string(x) + "/vkmc";
  if (const char* h = std::getenv("HOME")) return std::string(h) + "/.cache/vkmc";
  return ".vkmc-cache";
}

// "constant": one number or [r, g, b], each finite and at least 0 (a radiance).
glm::vec3 constantReference(const nlohmann::json& v) {
  auto channel = [](const nlohmann::json& x) {
    if (!x.is_number() || !std::isfinite(x.get<double>()) || x.get<double>() < 0.0 || x.get<double>() > 3.0e38)
      throw Error("study: 'reference' constant values must be finite numbers of at least 0");
    return x.get<float>();
  };
  if (v.is_number()) return glm::vec3(channel(v));
  if (!v.is_array() || v.size() != 3) throw Error("study: 'reference' constant must be a number or [r, g, b]");
  return glm::vec3(channel(v[0]), channel(v[1]), channel(v[2]));
}

}  // namespace

Study loadStudy(const std::string& path) {
  nlohmann::json j = nlohmann::json::parse(readFile(path), nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw Error("study '" + path + "' is not a JSON object");
  fs::path dir = fs::path(path).parent_path();
  auto resolve = [&](const std::string& p) { return fs::path(p).is_absolute() ? p : (dir / p).lexically_normal().string(); };
  Study s;
  s.name = j.value("name", fs::path(path).stem().string());
  if (!j.contains("scene") || !j["scene"].is_string()) throw Error("study: 'scene' (a glTF path) is required");
  s.scenePath = resolve(j["scene"].get<std::string>());
  s.inputFiles.push_back(path);
  auto count = [&](const char* key, uint32_t fallback, uint32_t lo, uint32_t hi) {
    if (!j.contains(key)) return fallback;
    if (!j[key].is_number_integer() || j[key].get<int64_t>() < lo || j[key].get<int64_t>() > hi)
      throw Error(std::string("study: '") + key + "' must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                  "]");
    return j[key].get<uint32_t>();
  };
  s.width = count("width", 64, 1, 4096);
  s.height = count("height", 64, 1, 4096);
  s.repeats = count("repeats", 3, 1, 100);
  s.seed = count("seed", 1, 0, 1u << 30);
  if (j.contains("filter")) {
    try {
      s.filter = pixelFilterFromJson(j["filter"]);
    } catch (const Error& e) {
      throw Error(std::string("study: ") + e.what());
    }
  }
  if (j.contains("reference")) {
    const auto& r = j["reference"];
    if (r.contains("exr") && r["exr"].is_string())
      s.referenceExr = resolve(r["exr"].get<std::string>()), s.inputFiles.push_back(s.referenceExr);
    else if (r.contains("spp") && r["spp"].is_number_integer() && r["spp"].get<int64_t>() >= 1 &&
             r["spp"].get<int64_t>() <= (1 << 20))
      s.referenceSpp = r["spp"].get<uint32_t>();
    else if (r.contains("constant"))
      s.referenceConstant = constantReference(r["constant"]);
    else
      throw Error("study: 'reference' must be {\"exr\": path}, {\"spp\": N} or {\"constant\": [r, g, b]}");
  }
  if (!j.contains("configurations") || !j["configurations"].is_array() || j["configurations"].empty())
    throw Error("study: 'configurations' must be a non-empty array");
  for (const auto& c : j["configurations"]) {
    if (!c.is_object() || !c.contains("name") || !c["name"].is_string()) throw Error("study: every configuration needs a 'name'");
    StudyConfiguration sc;
    sc.name = c["name"].get<std::string>();
    if (c.contains("estimator_file")) {
      s.inputFiles.push_back(resolve(c["estimator_file"].get<std::string>()));
      sc.estimator = loadEstimatorFile(s.inputFiles.back());
    }
    if (c.contains("estimator")) sc.estimator.applyJson(c["estimator"]);
    sc.estimator.validate();
    s.configurations.push_back(sc);
  }
  bool hasSpp = j.contains("spp"), hasSeconds = j.contains("seconds");
  if (hasSpp == hasSeconds) throw Error("study: give exactly one ladder, 'spp' or 'seconds'");
  s.timeLadder = hasSeconds;
  const auto& ladder = j[hasSeconds ? "seconds" : "spp"];
  if (!ladder.is_array() || ladder.empty()) throw Error("study: the ladder must be a non-empty array");
  for (const auto& v : ladder) {
    if (!v.is_number() || !(v.get<double>() > 0.0) || v.get<double>() > 1e5)
      throw Error("study: ladder values must be positive numbers");
    if (!hasSeconds && v.get<double>() != std::floor(v.get<double>())) throw Error("study: spp ladder values must be integers");
    s.ladder.push_back(v.get<double>());
  }
  return s;
}

std::vector<size_t> studyRunOrder(size_t configurations, uint32_t repeat) {
  std::vector<size_t> order(configurations);
  for (size_t k = 0; k < configurations; ++k) order[k] = repeat % 2 == 0 ? k : configurations - 1 - k;
  return order;
}

namespace {

// A study's render of one configuration, seed and rung (a time budget or a sample count).
RenderOptions studyOptions(const Study& study, const EstimatorConfig& e, uint32_t seed) {
  RenderOptions o;
  o.scenePath = study.scenePath;
  o.width = study.width;
  o.height = study.height;
  o.estimator = e;
  o.seed = seed;
  o.filter = study.filter;
  o.integrator = Integrator::Wavefront;  // one integrator for every row (auto could mix them on a GPU)
  o.progress = false;
  return o;
}

void setRung(const Study& study, double rung, RenderOptions& o) {
  if (study.timeLadder)
    o.timeBudget = rung, o.spp = kMaxSpp;
  else
    o.spp = static_cast<uint32_t>(rung);
}

struct StudyReference {
  ExrImage image;
  std::string note;  // where it came from
};

// Rendered with the first configuration and cached by a hash of what determines it.
StudyReference renderedReference(vk::Context& ctx, const Study& study, const Scene& scene) {
  std::string key = readFile(study.scenePath) + "|" + std::to_string(study.width) + "x" + std::to_string(study.height) + "|" +
                    std::to_string(study.referenceSpp) + "|" + study.configurations[0].estimator.toJson().dump() +
                    (study.filter.isPixelBox() ? "" : "|" + pixelFilterJson(study.filter).dump()) + "|vkmc-ref-3";
  char hex[17];
  std::snprintf(hex, sizeof(hex), "%016llx", static_cast<unsigned long long>(fnv1a(key)));
  fs::path cached = fs::path(cacheDir()) / "references" / (std::string(hex) + ".exr");
  if (fs::exists(cached)) return {readExr(cached.string()), cached.string() + " (cached)"};
  std::fprintf(stderr, "vkmc bench: rendering the reference (%u spp, %s)\n", study.referenceSpp,
               study.configurations[0].name.c_str());
  RenderOptions o = studyOptions(study, study.configurations[0].estimator, 0x5eed0000u + study.seed);
  o.spp = study.referenceSpp;
  StudyReference ref{filmToImage(runRender(ctx, o, scene).film), cached.string() + " (rendered)"};
  std::error_code ec;
  fs::create_directories(cached.parent_path(), ec);
  if (fs::is_directory(cached.parent_path())) writeExr(cached.string(), ref.image);
  return ref;
}

// The reference: a constant, a given EXR, or rendered (and cached).
StudyReference studyReference(vk::Context& ctx, const Study& study, const Scene& scene) {
  StudyReference ref;
  if (study.referenceConstant) {
    const glm::vec3 c = *study.referenceConstant;
    ref.image.width = int(study.width), ref.image.height = int(study.height);
    for (int k = 0; k < 3; ++k) ref.image.channels[std::string(1, "RGB"[k])].assign(size_t(study.width) * study.height, c[k]);
    char note[96];
    std::snprintf(note, sizeof(note), "constant (%g, %g, %g)", double(c.r), double(c.g), double(c.b));
    ref.note = note;
  } else if (!study.referenceExr.empty()) {
    ref = {readExr(study.referenceExr), study.referenceExr};
  } else {
    ref = renderedReference(ctx, study, scene);
  }
  if (uint32_t(ref.image.width) != study.width || uint32_t(ref.image.height) != study.height)
    throw Error("reference is " + std::to_string(ref.image.width) + "x" + std::to_string(ref.image.height) +
                ", the study renders " + std::to_string(study.width) + "x" + std::to_string(study.height));
  return ref;
}

StudyRow studyRow(const std::string& configuration, double rung, uint32_t repeat, const RenderOutcome& r, const ErrorMetrics& e) {
  StudyRow row;
  row.configuration = configuration;
  row.rung = rung;
  row.repeat = repeat;
  row.spp = r.stats.samplesPerPixel;
  row.seconds = r.stats.seconds;
  row.gpuSeconds = r.stats.gpuSeconds;
  row.rays = r.stats.rays();
  row.mse = e.mse;
  row.relmse = e.relmse;
  row.efficiency = e.relmse > 0 && row.seconds > 0 ? 1.0 / (e.relmse * row.seconds) : 0.0;
  row.nonfinite = r.film.totalNonfinite();
  return row;
}

using RungImages = std::map<std::pair<size_t, size_t>, ExrImage>;  // (configuration, rung) -> repeat 0's image

// Every configuration at every rung, repeats alternating the configurations' order; rows in the listed order.
std::vector<StudyRow> renderStudyRows(vk::Context& ctx, const Study& study, const Scene& scene, const ExrImage& reference,
                                      RungImages& images) {
  const size_t configurations = study.configurations.size();
  std::vector<StudyRow> rows(study.ladder.size() * study.repeats * configurations);
  for (size_t rung = 0; rung < study.ladder.size(); ++rung)
    for (uint32_t rep = 0; rep < study.repeats; ++rep)
      for (size_t c : studyRunOrder(configurations, rep)) {
        RenderOptions o =
            studyOptions(study, study.configurations[c].estimator, study.seed + rep * 7919u + uint32_t(rung) * 104729u);
        setRung(study, study.ladder[rung], o);
        RenderOutcome r = runRender(ctx, o, scene);
        ExrImage img = filmToImage(r.film);
        const StudyRow row = studyRow(study.configurations[c].name, study.ladder[rung], rep, r, compareImages(img, reference));
        rows[(rung * study.repeats + rep) * configurations + c] = row;
        if (rep == 0) images[{c, rung}] = std::move(img);
        std::fprintf(stderr, "vkmc bench: %-24s rung %-6g repeat %u: %u spp, %.3f s, relMSE %.4g\n", row.configuration.c_str(),
                     row.rung, rep, row.spp, row.seconds, row.relmse);
      }
  return rows;
}

// results.csv and results.json.
void addResultFiles(OutputSet& outputs, const fs::path& outDir, const nlohmann::json& header, const std::vector<StudyRow>& rows) {
  std::ostringstream csv;
  csv << "configuration,rung,repeat,spp,seconds,gpu_seconds,rays,mse,relmse,efficiency,nonfinite_samples\n";
  nlohmann::json jrows = nlohmann::json::array();
  for (const StudyRow& r : rows) {
    csv << '"' << r.configuration << "\"," << r.rung << ',' << r.repeat << ',' << r.spp << ',' << r.seconds << ',' << r.gpuSeconds
        << ',' << r.rays << ',' << r.mse << ',' << r.relmse << ',' << r.efficiency << ',' << r.nonfinite << '\n';
    jrows.push_back({{"config", r.configuration},
                     {"rung", r.rung},
                     {"repeat", r.repeat},
                     {"spp", r.spp},
                     {"seconds", r.seconds},
                     {"gpu_seconds", r.gpuSeconds},
                     {"rays", r.rays},
                     {"mse", r.mse},
                     {"relmse", r.relmse},
                     {"efficiency", r.efficiency},
                     {"nonfinite_samples", r.nonfinite}});
  }
  nlohmann::json results = header;
  results["rows"] = jrows;
  outputs.add((outDir / "results.csv").string(), csv.str());
  outputs.add((outDir / "results.json").string(), results.dump(2) + "\n");
}

// A configuration's medians over repeats at each rung, and its log-log fits.
struct Curve {
  std::vector<double> seconds, relmse, spp;
  LogFit fit, fitSpp;
  uint64_t nonfinite = 0;
};

std::vector<Curve> studyCurves(const Study& study, const std::vector<StudyRow>& rows) {
  std::vector<Curve> curves(study.configurations.size());
  for (size_t c = 0; c < study.configurations.size(); ++c) {
    for (size_t rung = 0; rung < study.ladder.size(); ++rung) {
      std::vector<double> s, e, n;
      for (const StudyRow& r : rows)
        if (r.configuration == study.configurations[c].name && r.rung == study.ladder[rung]) {
          s.push_back(r.seconds), e.push_back(r.relmse), n.push_back(r.spp);
          curves[c].nonfinite += r.nonfinite;
        }
      curves[c].seconds.push_back(median(s));
      curves[c].relmse.push_back(median(e));
      curves[c].spp.push_back(median(n));
    }
    curves[c].fit = fitLogLog(curves[c].seconds, curves[c].relmse);
    curves[c].fitSpp = fitLogLog(curves[c].spp, curves[c].relmse);
  }
  return curves;
}

// Equal time: the longest time every configuration reached; equal error: the smallest error all reached.
struct EqualPoints {
  double time = 1e300, error = 0.0;
};
EqualPoints equalPoints(const std::vector<Curve>& curves) {
  EqualPoints p;
  for (const Curve& c : curves) {
    p.time = std::min(p.time, *std::max_element(c.seconds.begin(), c.seconds.end()));
    p.error = std::max(p.error, *std::min_element(c.relmse.begin(), c.relmse.end()));
  }
  return p;
}

// summary.md's table: each configuration at equal time and equal error, relative to the first.
void writeSummaryTable(std::ostringstream& md, const Study& study, const std::vector<StudyRow>& rows,
                       const std::vector<Curve>& curves, EqualPoints equal) {
  md << "| configuration | relMSE at " << equal.time << " s | efficiency (equal time) | seconds to relMSE " << equal.error
     << " | efficiency (equal error) | slope vs log s | slope vs log spp | last rung relMSE (min-max) | non-finite |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  double baseEt = 0.0, baseEe = 0.0;
  for (size_t c = 0; c < curves.size(); ++c) {
    double errAt = curves[c].fit.at(equal.time);
    double timeTo = curves[c].fit.inverse(equal.error);
    double effT = errAt > 0 ? 1.0 / (errAt * equal.time) : 0.0;
    double effE = timeTo > 0 ? 1.0 / (equal.error * timeTo) : 0.0;
    if (c == 0) baseEt = effT, baseEe = effE;
    double lo = 1e300, hi = 0.0;
    for (const StudyRow& r : rows)
      if (r.configuration == study.configurations[c].name && r.rung == study.ladder.back())
        lo = std::min(lo, r.relmse), hi = std::max(hi, r.relmse);
    char line[640];
    std::snprintf(line, sizeof(line), "| %s | %.4g | %.3g | %.4g | %.3g | %.2f | %.2f | %.4g-%.4g | %llu |\n",
                  study.configurations[c].name.c_str(), errAt, baseEt > 0 ? effT / baseEt : 0.0, timeTo,
                  baseEe > 0 ? effE / baseEe : 0.0, curves[c].fit.slope, curves[c].fitSpp.slope, lo, hi,
                  static_cast<unsigned long long>(curves[c].nonfinite));
    md << line;
  }
}

std::string summaryMarkdown(const Study& study, const std::string& device, const StudyReference& reference, double referenceNoise,
                            const std::vector<StudyRow>& rows, const std::vector<Curve>& curves) {
  std::ostringstream md;
  char timeText[64];
  std::time_t now = std::time(nullptr);
  std::strftime(timeText, sizeof(timeText), "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  md << "# " << study.name << "\n\n";
  md << "Scene `" << study.scenePath << "`, " << study.width << "x" << study.height << ", " << (study.timeLadder ? "time" : "spp")
     << " ladder, " << study.repeats << " repeats (medians), device " << device << ", " << timeText << ".\n";
  md << "Reference: " << reference.note
     << ". Efficiency = 1/(relMSE x seconds), from each configuration's log-log fit of relMSE\n"
     << "against seconds; relative to the first configuration (" << study.configurations[0].name << ").\n";
  if (std::isfinite(referenceNoise))
    md << "The reference's own relative variance is " << referenceNoise << ": every relMSE below includes about that much,\n"
       << "so where a row's relMSE is within a few times of it, its ratios to the other rows are pulled toward 1.\n";
  md << "\n";
  writeSummaryTable(md, study, rows, curves, equalPoints(curves));
  md << "\nAn unbiased estimator's error falls as 1/samples: slope -1 against spp, and against time when time grows\n"
        "in proportion to samples (per-render overheads make small renders steeper against time). A flatter slope\n"
        "exposes bias, or a reference too noisy for the error reached. Raw rows: results.csv; plot:\n"
        "error_vs_time.svg; images at equal time: equal_time.png.\n";
  return md.str();
}

// Equal-time images: per configuration the rung whose median time is closest to the equal time.
std::string equalTimeSheet(const Study& study, const std::vector<Curve>& curves, RungImages& images) {
  const double equalTime = equalPoints(curves).time;
  std::vector<ExrImage> sheet;
  std::vector<std::string> labels;
  for (size_t c = 0; c < curves.size(); ++c) {
    size_t best = 0;
    for (size_t rung = 1; rung < study.ladder.size(); ++rung)
      if (std::abs(std::log(curves[c].seconds[rung] / equalTime)) < std::abs(std::log(curves[c].seconds[best] / equalTime)))
        best = rung;
    sheet.push_back(images[{c, best}]);
    char label[160];
    std::snprintf(label, sizeof(label), "%s %.2fs", study.configurations[c].name.c_str(), curves[c].seconds[best]);
    labels.push_back(label);
  }
  return encodeContactSheet(sheet, labels, 0.0f);
}

}  // namespace

std::vector<StudyRow> runStudy(const Study& study, const std::string& outDir) {
  std::error_code ec;
  fs::create_directories(outDir, ec);
  if (!fs::is_directory(outDir)) throw Error("cannot create output folder '" + outDir + "'");
  std::vector<std::string> inputs = gltfInputFiles(study.scenePath);
  inputs.insert(inputs.end(), study.inputFiles.begin(), study.inputFiles.end());
  std::vector<std::pair<std::string, std::string>> named;
  for (const char* name : kStudyOutputFiles) named.push_back({"bench -o", (fs::path(outDir) / name).string()});
  checkOutputPaths(named, inputs);  // before any render: a study's outputs never overwrite what it reads
  vk::Context ctx;
  Scene scene = loadGltf(study.scenePath, deviceLoadLimits(ctx));
  const StudyReference reference = studyReference(ctx, study, scene);
  // What of every relMSE below is the reference's own noise: where a row's relMSE nears it, the row's ratio to the
  // others is pulled toward 1 (a ratio read from such rows understates the difference).
  const double referenceNoise = referenceRelativeVariance(reference.image);
  // Warm-up (not recorded): every configuration once at the smallest rung.
  for (const auto& c : study.configurations) {
    RenderOptions o = studyOptions(study, c.estimator, study.seed);
    setRung(study, study.ladder.front(), o);
    runRender(ctx, o, scene);
  }
  RungImages images;
  const std::vector<StudyRow> rows = renderStudyRows(ctx, study, scene, reference.image, images);
  OutputSet outputs;  // the study's files are written together, all or none
  const nlohmann::json header = {
      {"study", study.name},
      {"device", ctx.deviceName()},
      {"reference", reference.note},
      {"reference_relvariance", std::isfinite(referenceNoise) ? nlohmann::json(referenceNoise) : nlohmann::json(nullptr)}};
  addResultFiles(outputs, outDir, header, rows);
  const std::vector<Curve> curves = studyCurves(study, rows);
  std::vector<PlotSeries> plot;
  for (size_t c = 0; c < curves.size(); ++c) plot.push_back({study.configurations[c].name, curves[c].seconds, curves[c].relmse});
  outputs.add((fs::path(outDir) / "error_vs_time.svg").string(),
              logLogSvg(plot, study.name + ": relMSE against render time", "seconds (median of repeats)", "relMSE"));
  outputs.add((fs::path(outDir) / "summary.md").string(),
              summaryMarkdown(study, ctx.deviceName(), reference, referenceNoise, rows, curves));
  outputs.add((fs::path(outDir) / "equal_time.png").string(), equalTimeSheet(study, curves, images));
  outputs.commit();
  return rows;
}

}  // namespace vkmc
