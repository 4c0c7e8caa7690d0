// glTF extensions as the spec's policy asks (glTF 2.0, section 3.12): a file that requires an extension vkmc does
// not implement is refused with an error naming it; each extension a file uses that vkmc ignores, wholly or in
// part, gets one warning naming it and what is ignored.
#pragma once
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vkmc {

// Throws vkmc::Error naming the first required extension vkmc does not implement in full; returns one warning per
// used (or required) extension that is not implemented in full.
std::vector<std::string> checkExtensions(const std::vector<std::string>& used, const std::vector<std::string>& required);

// Every extension vkmc knows, in the table's order, with what it ignores of it ("" where it implements it in full).
struct GltfExtensionSupport {
  std::string_view name;
  std::string_view ignored;
};
std::span<const GltfExtensionSupport> knownExtensions();

}  // namespace vkmc
