// One exception type for every user-facing failure: its message is the one line vkmc prints.
#pragma once
#include <stdexcept>
#include <string>

namespace vkmc {
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};
}  // namespace vkmc
