// Untrusted-input checks that run before tinygltf (see the header for why each exists).
#include "scene/gltf_input_guard.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <nlohmann/json.hpp>

#include "error.h"

namespace vkmc {

std::vector<unsigned char> readRegularFile(const std::string& path, uint64_t maxBytes, const std::string& what) {
  // O_NONBLOCK: opening a FIFO without a writer would otherwise wait forever.
  int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) throw Error("cannot open " + what + " '" + path + "': " + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw Error(what + " '" + path + "' is not a regular file");
  }
  if (uint64_t(st.st_size) > maxBytes) {
    ::close(fd);
    throw Error(what + " '" + path + "' is " + std::to_string(st.st_size) + " bytes, over the limit of " +
                std::to_string(maxBytes));
  }
  std::vector<unsigned char> bytes(size_t(st.st_size));
  size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      ::close(fd);
      throw Error("cannot read " + what + " '" + path + "'" +
                  (n < 0 ? std::string(": ") + std::strerror(errno) : ": file shrank"));
    }
    done += size_t(n);
  }
  ::close(fd);
  return bytes;
}

std::string_view glbJsonChunk(const std::vector<unsigned char>& glb) {
  auto word = [&](size_t offset) {
    uint32_t w;
    std::memcpy(&w, glb.data() + offset, 4);
    return w;
  };
  if (glb.size() < 20 || word(0) != 0x46546C67u) throw Error("not a GLB file (no 'glTF' magic)");
  if (word(4) != 2) throw Error("GLB version " + std::to_string(word(4)) + " (only 2 is supported)");
  uint64_t length = word(8), jsonLength = word(12);
  if (length > glb.size())
    throw Error("GLB header length " + std::to_string(length) + " exceeds the file's " + std::to_string(glb.size()) + " bytes");
  if (word(16) != 0x4E4F534Au) throw Error("GLB's first chunk is not JSON");
  uint64_t jsonEnd = 20 + jsonLength;
  if (jsonLength == 0 || jsonEnd > length)
    throw Error("GLB JSON chunk of " + std::to_string(jsonLength) + " bytes runs past the file");
  if (jsonEnd % 4 != 0) throw Error("GLB JSON chunk is not padded to 4 bytes");
  if (jsonEnd < length) {  // a BIN chunk: its 8-byte header and its data must both lie inside the file
    if (jsonEnd + 8 > length) throw Error("GLB BIN chunk header runs past the file");
    uint64_t binLength = word(size_t(jsonEnd));
    if (jsonEnd + 8 + binLength > length)
      throw Error("GLB BIN chunk of " + std::to_string(binLength) + " bytes runs past the file's end");
  }
  return std::string_view(reinterpret_cast<const char*>(glb.data()) + 20, size_t(jsonLength));
}

std::vector<unsigned char> replaceGlbJson(const std::vector<unsigned char>& glb, std::string json) {
  std::string_view old = glbJsonChunk(glb);
  size_t rest = 20 + old.size();  // the BIN chunk, if any, starts here (glbJsonChunk checked the padding)
  while (json.size() % 4 != 0) json.push_back(' ');
  uint64_t total = 20 + uint64_t(json.size()) + (glb.size() - rest);
  if (total > 0xFFFFFFFFu) throw Error("GLB too large after its JSON was rewritten");
  std::vector<unsigned char> out(20);
  auto put = [&](size_t offset, uint32_t w) { std::memcpy(out.data() + offset, &w, 4); };
  put(0, 0x46546C67u), put(4, 2), put(8, uint32_t(total)), put(12, uint32_t(json.size())), put(16, 0x4E4F534Au);
  out.insert(out.end(), json.begin(), json.end());
  out.insert(out.end(), glb.begin() + rest, glb.end());
  return out;
}

namespace {

// Counts values and tracks depth without building anything; stops at the first limit crossed.
class BoundedScan : public nlohmann::json_sax<nlohmann::json> {
 public:
  explicit BoundedScan(const InputLimits& limits) : limits_(limits) {}
  std::string problem;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(); }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(); }
  bool end_array() override { return close(); }
  bool key(string_t&) override { return true; }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) override {
    std::string what = e.what();  // "[json.exception.parse_error.101] parse error at ...: reason"
    size_t bracket = what.find("] ");
    problem = "invalid JSON at byte " + std::to_string(position) + ": " +
              (bracket == std::string::npos ? what : what.substr(bracket + 2));
    return false;
  }

 private:
  bool value() {
    if (++values_ <= limits_.maxJsonValues) return true;
    problem = "JSON holds more than " + std::to_string(limits_.maxJsonValues) + " values";
    return false;
  }
  bool open() {
    if (++depth_ <= limits_.maxJsonDepth) return value();
    problem = "JSON nested deeper than " + std::to_string(limits_.maxJsonDepth) + " levels";
    return false;
  }
  bool close() {
    --depth_;
    return true;
  }
  const InputLimits& limits_;
  uint64_t values_ = 0;
  uint32_t depth_ = 0;
};

}  // namespace

namespace {

uint64_t unsignedOr(const nlohmann::json& object, const char* key, uint64_t fallback) {
  auto it = object.find(key);
  return it != object.end() && it->is_number_unsigned() ? it->get<uint64_t>() : fallback;
}

// Every bufferView inside its buffer's declared length, checked before tinygltf reads any: it decodes an image from
// a bufferView without checking that the view lies in its buffer (tinygltf 2.8: a crafted offset read far past it).
void checkBufferViews(const nlohmann::json& doc) {
  if (!doc.contains("bufferViews") || !doc["bufferViews"].is_array()) return;
  const nlohmann::json empty = nlohmann::json::array();
  const nlohmann::json& buffers = doc.contains("buffers") && doc["buffers"].is_array() ? doc["buffers"] : empty;
  const nlohmann::json& views = doc["bufferViews"];
  for (size_t v = 0; v < views.size(); ++v) {
    if (!views[v].is_object()) continue;  // tinygltf names malformed views
    const uint64_t buffer = unsignedOr(views[v], "buffer", UINT64_MAX);
    char why[192];
    if (buffer >= buffers.size() || !buffers[buffer].is_object()) {
      std::snprintf(why, sizeof(why), "bufferView %zu names a buffer the file does not have", v);
      throw Error(why);
    }
    const uint64_t offset = unsignedOr(views[v], "byteOffset", 0), length = unsignedOr(views[v], "byteLength", 0);
    const uint64_t size = unsignedOr(buffers[buffer], "byteLength", 0);
    if (offset > size || length > size - offset) {
      std::snprintf(why, sizeof(why), "bufferView %zu runs past the end of buffer %llu (offset %llu + length %llu > %llu bytes)",
                    v, (unsigned long long)buffer, (unsigned long long)offset, (unsigned long long)length,
                    (unsigned long long)size);
      throw Error(why);
    }
  }
  if (!doc.contains("images") || !doc["images"].is_array()) return;
  // An EXT_meshopt_compression fallback buffer holds no data (vkmc reads such files with it replaced by one byte):
  // an image decoded from a view into one would read past that byte.
  auto isFallback = [&](uint64_t buffer) {
    if (buffer >= buffers.size() || !buffers[buffer].is_object()) return false;
    const nlohmann::json& b = buffers[buffer];
    const auto ext = b.find("extensions");
    if (ext == b.end() || !ext->is_object() || !ext->contains("EXT_meshopt_compression")) return false;
    const nlohmann::json& meshopt = (*ext)["EXT_meshopt_compression"];
    return meshopt.is_object() && meshopt.value("fallback", nlohmann::json(false)) == nlohmann::json(true);
  };
  for (size_t i = 0; i < doc["images"].size(); ++i) {
    const nlohmann::json& image = doc["images"][i];
    if (!image.is_object() || !image.contains("bufferView")) continue;
    char why[128];
    const uint64_t view = unsignedOr(image, "bufferView", UINT64_MAX);
    if (view >= views.size()) {
      std::snprintf(why, sizeof(why), "image %zu names a bufferView the file does not have", i);
      throw Error(why);
    }
    if (views[view].is_object() && isFallback(unsignedOr(views[view], "buffer", UINT64_MAX))) {
      std::snprintf(why, sizeof(why), "image %zu reads bufferView %llu, in a meshopt fallback buffer that holds no data", i,
                    (unsigned long long)view);
      throw Error(why);
    }
  }
}

}  // namespace

void checkJsonBounds(std::string_view json, const InputLimits& limits) {
  BoundedScan scan(limits);
  if (!nlohmann::json::sax_parse(json.begin(), json.end(), &scan) || !scan.problem.empty())
    throw Error(scan.problem.empty() ? std::string("invalid JSON") : scan.problem);
}

GltfJsonFacts scanGltfJson(std::string_view json, const InputLimits& limits) {
  checkJsonBounds(json, limits);
  // Bounded now: read what the file declares about its buffers and extensions.
  nlohmann::json doc = nlohmann::json::parse(json.begin(), json.end());
  GltfJsonFacts facts;
  if (!doc.is_object()) return facts;
  if (doc.contains("buffers") && doc["buffers"].is_array())
    for (const auto& b : doc["buffers"])
      if (b.is_object() && b.contains("byteLength") && b["byteLength"].is_number_unsigned())
        facts.largestBuffer = std::max<uint64_t>(facts.largestBuffer, b["byteLength"].get<uint64_t>());
  checkBufferViews(doc);
  for (const char* list : {"buffers", "images"})
    if (doc.contains(list) && doc[list].is_array())
      for (const auto& item : doc[list])
        if (item.is_object() && item.contains("uri") && item["uri"].is_string() &&
            item["uri"].get<std::string>().rfind("data:", 0) != 0)
          facts.externalUris.push_back(item["uri"].get<std::string>());
  for (auto [key, list] :
       {std::pair{"extensionsUsed", &facts.extensionsUsed}, std::pair{"extensionsRequired", &facts.extensionsRequired}})
    if (doc.contains(key) && doc[key].is_array())
      for (const auto& e : doc[key])
        if (e.is_string()) list->push_back(e.get<std::string>());
  return facts;
}

}  // namespace vkmc
