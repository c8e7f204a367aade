// Tests of toml_text.hpp: what toml++ is given, checked and transformed, and mapped back.
#include "quadmc/scene/toml_text.hpp"

#include "quadmc/scene/parse.hpp"
#include "quadmc/scene/scene_error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace quadmc {
namespace {

TEST(TomlText, UnsafeCodePointsRoundTripAndKeepTheirPositions) {
  // π, σ, é, § and · are among the 3019 code points toml++ 3.3.0 mishandles; ASCII, U+00A0 and
  // CJK text outside the ranges pass unchanged.
  const std::string text = "description = \"π σ é § · 中文\"  # ε\nname = \"x\"\n";
  const std::string safe = toml_safe_text(text, "f.toml");
  EXPECT_NE(safe, text);
  EXPECT_EQ(safe.find("π"), std::string::npos);
  EXPECT_NE(safe.find("中文"), std::string::npos) << "outside the unsafe ranges: kept";
  EXPECT_EQ(toml_original_text(safe), text);
  // One code point for one: the byte length may change, the line/column layout does not.
  EXPECT_EQ(std::count(safe.begin(), safe.end(), '\n'), 2);
  const std::string ascii = "a = 1\n";
  EXPECT_EQ(toml_safe_text(ascii, "f.toml"), ascii);
}

TEST(TomlText, PrivateUseStandInsInTheFileAreRefused) {
  try {
    toml_safe_text("a = \"\xEE\x80\x86\"\n", "f.toml");  // U+E006, the stand-in of §
    FAIL() << "a private-use character of the stand-in block must be refused";
  } catch (const scene_error& e) {
    EXPECT_EQ(e.where().line, 1u);
    EXPECT_NE(std::string(e.what()).find("U+E006"), std::string::npos) << e.what();
  }
}

TEST(TomlText, NestingIsBoundedBeforeTomlxxRecurses) {
  const std::size_t limit = scene_limits::max_nesting;
  std::string ok = "a";
  for (std::size_t k = 1; k < limit; ++k) ok += ".a";
  EXPECT_NO_THROW(toml_safe_text(ok + " = 1\n", "f.toml"));
  try {
    toml_safe_text(ok + ".a = 1\n", "f.toml");
    FAIL() << limit + 1 << " dotted parts must be refused";
  } catch (const scene_error& e) {
    EXPECT_EQ(e.where().line, 1u);
    EXPECT_NE(std::string(e.what()).find("nesting deeper than"), std::string::npos) << e.what();
  }
  // Dots, brackets and braces inside strings and comments are not levels.
  const std::string quoted =
      "a = \"" + std::string(1000, '[') + "\"  # " + std::string(1000, '{') + "\n";
  EXPECT_NO_THROW(toml_safe_text(quoted, "f.toml"));
  EXPECT_THROW(toml_safe_text("a = " + std::string(limit + 1, '[') + "\n", "f.toml"), scene_error);
}

}  // namespace
}  // namespace quadmc
