// Test support for the checks of the source tree as text: where the tree is, and a list of
// offending lines laid out one per line under a failure's message.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace quadmc::test_support {

inline std::filesystem::path source_dir() {
  return std::filesystem::path(QUADMC_SOURCE_DIR);
}

inline std::string listed(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& l : lines) out += "\n  " + l;
  return out;
}

}  // namespace quadmc::test_support
