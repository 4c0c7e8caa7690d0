// One row of docs/tables/stability.md, recorded as a GoogleTest property; tools/stability_table.sh collects them
// from `ctest -L stiff` runs (gtest JSON output).
#pragma once
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace vkmc::test {

inline void stabilityRow(const std::string& testCase, const std::string& what, const std::string& expected, double measured,
                         double sigma, bool pass) {
  static int row = 0;
  char text[512];
  std::snprintf(text, sizeof(text), "%s|%s|%s|%.6g|%.3g|%s", testCase.c_str(), what.c_str(), expected.c_str(), measured, sigma,
                pass ? "pass" : "FAIL");
  ::testing::Test::RecordProperty("stability_row_" + std::to_string(row++), text);
}

}  // namespace vkmc::test
