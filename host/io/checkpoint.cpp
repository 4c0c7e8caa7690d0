// Checkpoint files (see the header).
#include "io/checkpoint.h"

#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "error.h"
#include "render/render_stats.h"
#include "scene/content_hash.h"
#include "scene/gltf_input_guard.h"

namespace vkmc {
namespace {

constexpr char kMagic[] = "VKMC-CHECKPOINT\n";  // 16 bytes without the terminator
constexpr size_t kMagicBytes = sizeof(kMagic) - 1;
constexpr int kFormatVersion = 3;  // 2: the estimator's `replicates` (earlier films had 4); 3: each pixel's cost
static_assert(std::endian::native == std::endian::little, "checkpoints are little-endian");

// The payload's arrays, in order, for a film of `pixels` pixels: one list serves encoding and decoding.
template <class FilmT, class Visit>
void forEachArray(FilmT& film, Visit&& visit) {
  visit(film.sum), visit(film.sumSq), visit(film.count), visit(film.nonfinite), visit(film.highRange), visit(film.replicateSum),
      visit(film.replicateCount), visit(film.vertices);
}

void appendU64(std::string& out, uint64_t v) { out.append(reinterpret_cast<const char*>(&v), 8); }

}  // namespace

std::string encodeCheckpoint(const Checkpoint& c) {
  const RenderState& st = c.state;
  nlohmann::json header = {{"format", "vkmc checkpoint"},
                           {"version", kFormatVersion},
                           {"config", c.config},
                           {"width", st.film.width},
                           {"height", st.film.height},
                           {"replicate_variance", st.film.replicateVariance},
                           {"replicates", st.film.replicates},
                           {"next_sample", st.nextSample},
                           {"batch_samples", st.batchSamples},
                           {"stats", renderStatsJson(st.stats)}};
  std::string payload;
  forEachArray(st.film, [&](const auto& v) { payload.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(v[0])); });
  if (st.batchSamples > 0)
    payload.append(reinterpret_cast<const char*>(st.batch.data()), st.batch.size() * sizeof(gpu::FilmPixel));
  // Paths in the configuration are bytes, not always UTF-8: replaced where invalid, never a failed checkpoint.
  const std::string text = header.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string out(kMagic, kMagicBytes);
  appendU64(out, text.size());
  out += text;
  appendU64(out, payload.size());
  out += payload;
  ContentHash h;
  h.add(out);
  appendU64(out, h.value());
  return out;
}

namespace {

using Fail = std::function<Error(const std::string&)>;

// Where a checkpoint's header and payload lie, once its magic, lengths and checksum are checked.
struct Sections {
  size_t headerAt = 0, headerBytes = 0, payloadAt = 0, payloadBytes = 0;
};

Sections checkedSections(const std::string& bytes, const Fail& fail) {
  if (bytes.size() < kMagicBytes || bytes.compare(0, kMagicBytes, kMagic) != 0) throw fail("is not a vkmc checkpoint");
  size_t at = kMagicBytes;
  auto readU64 = [&](const char* what) {
    if (bytes.size() - at < 8) throw fail(std::string("is truncated (") + what + ")");
    uint64_t v;
    std::memcpy(&v, bytes.data() + at, 8);
    at += 8;
    return v;
  };
  Sections s;
  s.headerBytes = readU64("header length");
  if (s.headerBytes > bytes.size() - at) throw fail("is truncated (header)");
  s.headerAt = at;
  at += s.headerBytes;
  s.payloadBytes = readU64("payload length");
  if (s.payloadBytes > bytes.size() - at) throw fail("is truncated (payload)");
  s.payloadAt = at;
  at += s.payloadBytes;
  const size_t checked = at;
  const uint64_t checksum = readU64("checksum");
  if (at != bytes.size()) throw fail("has " + std::to_string(bytes.size() - at) + " bytes after its end");
  ContentHash h;
  h.add(bytes.data(), checked);
  if (h.value() != checksum) throw fail("is corrupt (its checksum does not match its contents)");
  return s;
}

// The render state a header describes, its film allocated only once the payload's length matches the image's.
Checkpoint stateFromHeader(const nlohmann::json& header, uint64_t payloadBytes, const Fail& fail) {
  // A count of the header: an unsigned integer up to `most` (a float or a negative number never converts).
  auto count = [&](const char* key, uint64_t most) {
    const nlohmann::json& v = header.at(key);
    if (!v.is_number_unsigned() || v.get<uint64_t>() > most) throw fail(std::string("has an impossible ") + key);
    return uint32_t(v.get<uint64_t>());
  };
  Checkpoint c;
  c.config = header.at("config");
  const uint32_t width = count("width", kMaxImageSide), height = count("height", kMaxImageSide);
  if (width == 0 || height == 0) throw fail("has an impossible image size");
  // The payload the image needs, from one pixel's arrays, before the film is allocated: a forged size must not
  // allocate gigabytes.
  uint64_t perPixel = 0;
  const Film onePixel(1, 1);
  forEachArray(onePixel, [&](const auto& v) { perPixel += v.size() * sizeof(v[0]); });
  const uint32_t batchSamples = count("batch_samples", kMaxSpp);
  const uint64_t needed = uint64_t(width) * height * (perPixel + (batchSamples > 0 ? sizeof(gpu::FilmPixel) : 0));
  if (payloadBytes != needed)
    throw fail("holds " + std::to_string(payloadBytes) + " bytes of film where its image needs " + std::to_string(needed));
  c.state.film = Film(width, height);
  if (!header.at("replicate_variance").is_boolean()) throw fail("has a malformed header: replicate_variance");
  c.state.film.replicateVariance = header.at("replicate_variance").get<bool>();
  c.state.film.replicates = count("replicates", gpu::kMaxSampleReplicates);
  if (c.state.film.replicates < 1) throw fail("has an impossible replicates");
  c.state.nextSample = count("next_sample", kMaxSpp);
  c.state.batchSamples = batchSamples;
  try {
    c.state.stats = renderStatsFromJson(header.at("stats"));
  } catch (const Error& e) {
    throw fail(std::string("has a malformed header: ") + e.what());
  }
  if (c.state.batchSamples > c.state.nextSample || c.state.stats.samplesPerPixel > c.state.nextSample)
    throw fail("has sample counts no render reaches (next sample " + std::to_string(c.state.nextSample) + ")");
  return c;
}

}  // namespace

Checkpoint decodeCheckpoint(const std::string& bytes, const std::string& name) {
  const Fail fail = [&](const std::string& why) { return Error("checkpoint '" + name + "' " + why); };
  const Sections s = checkedSections(bytes, fail);
  try {  // a forged header nested 100k deep would overflow the stack when copied or dumped
    checkJsonBounds(std::string_view(bytes).substr(s.headerAt, s.headerBytes), InputLimits{});
  } catch (const Error& e) {
    throw fail(std::string("has a header that is not JSON within bounds: ") + e.what());
  }
  nlohmann::json header =
      nlohmann::json::parse(bytes.begin() + s.headerAt, bytes.begin() + s.headerAt + s.headerBytes, nullptr, false);
  if (header.is_discarded() || !header.is_object()) throw fail("has a header that is not JSON");
  // Compared as JSON values, which never throw whatever their type (a forged "format" may be an object).
  if (header.value("format", nlohmann::json()) != nlohmann::json("vkmc checkpoint")) throw fail("is not a vkmc checkpoint");
  if (header.value("version", nlohmann::json()) != nlohmann::json(kFormatVersion))
    throw fail("has format version " + header.value("version", nlohmann::json(0)).dump() + "; this vkmc reads version " +
               std::to_string(kFormatVersion));
  Checkpoint c;
  try {
    c = stateFromHeader(header, s.payloadBytes, fail);
  } catch (const nlohmann::json::exception& e) {
    throw fail(std::string("has a malformed header: ") + e.what());
  }
  Film& film = c.state.film;
  const char* p = bytes.data() + s.payloadAt;
  forEachArray(film, [&](auto& v) {
    std::memcpy(v.data(), p, v.size() * sizeof(v[0]));
    p += v.size() * sizeof(v[0]);
  });
  if (c.state.batchSamples > 0) {
    c.state.batch.resize(film.pixels());
    std::memcpy(c.state.batch.data(), p, film.pixels() * sizeof(gpu::FilmPixel));
  }
  return c;
}

uint64_t largestCheckpointBytes() {
  constexpr uint64_t kLargestHeaderBytes = uint64_t(1) << 26;  // the configuration and counters: kilobytes in practice
  uint64_t perPixel = sizeof(gpu::FilmPixel);
  const Film onePixel(1, 1);
  forEachArray(onePixel, [&](const auto& v) { perPixel += v.size() * sizeof(v[0]); });
  return kMagicBytes + 3 * 8 + kLargestHeaderBytes + uint64_t(kMaxImageSide) * kMaxImageSide * perPixel;
}

Checkpoint readCheckpoint(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw Error("checkpoint '" + path + "' does not exist");
  if (!std::filesystem::is_regular_file(path, ec)) throw Error("checkpoint '" + path + "' is not a regular file");
  // Sized before it is read: a file larger than any image's checkpoint is not read into memory.
  const uint64_t bytes = std::filesystem::file_size(path, ec);
  if (ec) throw Error("cannot read checkpoint '" + path + "': " + ec.message());
  if (bytes > largestCheckpointBytes())
    throw Error("checkpoint '" + path + "' is " + std::to_string(bytes) + " bytes, more than any image's checkpoint (" +
                std::to_string(largestCheckpointBytes()) + ")");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open checkpoint '" + path + "'");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (!in && !in.eof()) throw Error("cannot read checkpoint '" + path + "'");
  return decodeCheckpoint(buffer.str(), path);
}

bool startsLikeCheckpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(kMagicBytes, '\0');
  return in.read(head.data(), std::streamsize(kMagicBytes)) && head == std::string_view(kMagic, kMagicBytes);
}

}  // namespace vkmc
