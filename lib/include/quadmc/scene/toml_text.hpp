// The text toml++ 3.3 is given: scene files are checked and transformed first, because two of
// its defects would otherwise crash or misbehave on inputs a user can write.
//
// Use toml_safe_text on a scene's text before toml::parse, and toml_original_text on every
// string taken back from the parsed document (values, keys, toml++'s messages). Not a TOML
// parser: only the lexical structure needed for the two checks below is recognised, and every
// syntax error is left for toml++ to report.
//
//  - Nesting: toml++ bounds arrays and inline tables (TOML_MAX_NESTED_VALUES = 256) but not
//    dotted keys or table headers, and its recursion overflows the stack somewhere between
//    20,000 and 40,000 parts of `a.a.a… = 1`. The text is refused beyond scene_limits::max_nesting
//    levels, with file:line:column.
//  - Code points: toml++ 3.3.0 reaches __builtin_unreachable() (undefined behaviour) on 3019 code
//    points that scene descriptions and comments use (π, σ, ε, é, §, ·); each is replaced by a
//    stand-in of the private-use area, one code point for one so positions do not move, and
//    mapped back afterwards. Private-use characters of that block in the file are refused.
#pragma once

#include <string>
#include <string_view>

namespace quadmc {

// The text toml++ may parse, or a scene_error (file:line:column) for nesting deeper than
// scene_limits::max_nesting or a private-use character of the stand-in block.
std::string toml_safe_text(std::string_view text, std::string_view file_name);

// A string of the parsed document with every stand-in mapped back to its code point.
std::string toml_original_text(std::string_view text);

}  // namespace quadmc
