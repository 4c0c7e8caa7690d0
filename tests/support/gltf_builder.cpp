// GltfBuilder: a JSON glTF with one external .bin buffer.
#include "gltf_builder.h"

#include "lab_world.h"

#include <fstream>
#include <sstream>

namespace vkmc::test {

size_t GltfBuilder::append(const void* data, size_t bytes) {
  while (bin_.size() % 4 != 0) bin_.push_back('\0');
  size_t offset = bin_.size();
  bin_.append(static_cast<const char*>(data), bytes);
  return offset;
}

int GltfBuilder::view(const void* data, size_t bytes, size_t stride) {
  size_t offset = append(data, bytes);
  std::string json = R"({"buffer":0,"byteOffset":)" + std::to_string(offset) + R"(,"byteLength":)" + std::to_string(bytes);
  if (stride) json += R"(,"byteStride":)" + std::to_string(stride);
  return rawView(json + "}");
}

int GltfBuilder::rawView(const std::string& json) {
  views_.push_back(json);
  return static_cast<int>(views_.size() - 1);
}

int GltfBuilder::accessor(int view, int componentType, const std::string& type, size_t count, const std::string& extra) {
  std::string json = view >= 0 ? R"({"bufferView":)" + std::to_string(view) + "," : "{";
  json += R"("componentType":)" + std::to_string(componentType) + R"(,"type":")" + type + R"(","count":)" + std::to_string(count);
  accessors_.push_back(json + (extra.empty() ? "" : "," + extra) + "}");
  return static_cast<int>(accessors_.size() - 1);
}

std::string GltfBuilder::write(const std::filesystem::path& dir, const std::string& name, const std::string& body,
                               const std::string& rootNodes, const std::string& extraBuffers) const {
  auto list = [](const std::vector<std::string>& items) {
    std::string out;
    for (const std::string& s : items) out += (out.empty() ? "" : ",") + s;
    return out;
  };
  std::string bin = bin_.empty() ? std::string(4, '\0') : bin_;
  std::ostringstream j;
  j << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[)" << rootNodes << "]}]," << body << ",";
  j << R"("accessors":[)" << list(accessors_) << R"(],"bufferViews":[)" << list(views_) << "],";
  j << R"("buffers":[{"byteLength":)" << bin.size() << R"(,"uri":")" << name << R"(.bin"})"
    << (extraBuffers.empty() ? "" : "," + extraBuffers) << "]}";
  std::ofstream(dir / (name + ".gltf")) << withLabWorld(j.str());
  std::ofstream(dir / (name + ".bin"), std::ios::binary) << bin;
  return (dir / (name + ".gltf")).string();
}

}  // namespace vkmc::test
