// Test support for the scene tests: finding and editing one line of a scene's TOML text, so that
// an error test changes one key of a valid scene and names the line the error must point at.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>

namespace quadmc::test_support {

// 1-based line of the first occurrence of `needle`: the line an error about that key must name.
inline std::uint32_t line_of(std::string_view text, std::string_view needle) {
  const auto at = text.find(needle);
  EXPECT_NE(at, std::string_view::npos) << needle;
  if (at == std::string_view::npos) return 0;
  return 1 + static_cast<std::uint32_t>(std::count(text.begin(), text.begin() + at, '\n'));
}

// `text` with the first occurrence of `from` replaced by `to` (a failure if there is none).
inline std::string replace(std::string_view text, std::string_view from, std::string_view to) {
  std::string s(text);
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

}  // namespace quadmc::test_support
