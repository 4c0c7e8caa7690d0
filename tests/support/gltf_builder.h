// glTF files assembled piece by piece for tests of attributes, accessors and extensions: binary data appended to
// one buffer, everything else given as JSON.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace vkmc::test {

class GltfBuilder {
 public:
  // Appends `bytes` to the binary buffer (4-byte aligned) as a new buffer view; returns its index.
  int view(const void* data, size_t bytes, size_t stride = 0);
  template <class T>
  int view(const std::vector<T>& v, size_t stride = 0) {
    return view(v.data(), v.size() * sizeof(T), stride);
  }
  // Appends bytes to the buffer without a view; returns their offset.
  size_t append(const void* data, size_t bytes);
  int rawView(const std::string& json);  // a buffer view object given as JSON
  // An accessor over view `view` ("type" is "SCALAR", "VEC3", ...); `extra` adds JSON members.
  int accessor(int view, int componentType, const std::string& type, size_t count, const std::string& extra = "");
  // A view and an accessor over `data` in one step.
  template <class T>
  int accessor(const std::vector<T>& data, int componentType, const std::string& type, size_t count,
               const std::string& extra = "") {
    return accessor(view(data), componentType, type, count, extra);
  }

  // Writes dir/name.gltf (+ name.bin). `body` holds the other top-level members without braces (nodes, meshes,
  // materials, extensionsUsed, ...); scene 0 is all nodes listed in `rootNodes`. `extraBuffers` are buffer objects
  // (JSON) after buffer 0.
  std::string write(const std::filesystem::path& dir, const std::string& name, const std::string& body,
                    const std::string& rootNodes = "0", const std::string& extraBuffers = "") const;

 private:
  std::string bin_;
  std::vector<std::string> views_, accessors_;
};

}  // namespace vkmc::test
