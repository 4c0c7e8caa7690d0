// Readable names for value-parameterized tests: letters and digits kept, every other run of characters one
// underscore ("rr fixed q=0.5" -> "rr_fixed_q_0_5"), as gtest allows only [A-Za-z0-9_] in a parameter's name.
#pragma once
#include <cctype>
#include <cstdio>
#include <string>
#include <string_view>

namespace vkmc::test {

inline std::string paramName(std::string_view readable) {
  std::string name;
  for (char c : readable) {
    if (std::isalnum(static_cast<unsigned char>(c)))
      name += c;
    else if (!name.empty() && name.back() != '_')
      name += '_';
  }
  while (!name.empty() && name.back() == '_') name.pop_back();
  return name;
}

// A number as %g prints it: 0.001 -> "0.001", 1e-06 -> "1e-06".
inline std::string shortNumber(double x) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%g", x);
  return buf;
}

}  // namespace vkmc::test
