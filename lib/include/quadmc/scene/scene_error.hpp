// A mistake in a scene file, reported as ONE line that names the file, the line, the column and
// the key, in the format compilers use so editors can jump to it:
//
//   scene.toml:12:1: key 'method[2].repetitions': expected a positive integer, got -3
//
// Use it for every error a scene file can cause (TOML syntax, unknown keys, wrong types, values
// out of range, impossible combinations, integrands the catalogue rejects). Do not use it for
// errors of the library's C++ API: those are plain quadmc::invalid_argument.
// Array-of-table indices are 1-based ("method[2]" is the second [[method]] table), because
// that is how a person counts the tables in the file.
#pragma once

#include "quadmc/core/errors.hpp"

#include <cstdint>
#include <string>
#include <string_view>

namespace quadmc {

// Where something sits in a scene file; line and column are 1-based, 0 = unknown.
struct source_location {
  std::string file;
  std::uint32_t line = 0;
  std::uint32_t column = 0;
};

class scene_error : public invalid_argument {
 public:
  // `key` is the dotted path of the offending key, e.g. "method[2].repetitions"; empty when the
  // error concerns the file as a whole (syntax error, empty file).
  scene_error(const source_location& where, std::string_view key, std::string_view message)
      : invalid_argument(format_message(where, key, message)), where_(where), key_(key) {}

  const source_location& where() const noexcept { return where_; }
  const std::string& key() const noexcept { return key_; }

 private:
  static std::string format_message(const source_location& where, std::string_view key,
                                    std::string_view message) {
    std::string out = fmt::format("{}:{}:{}: ", where.file, where.line, where.column);
    if (!key.empty()) out += fmt::format("key '{}': ", key);
    out += message;
    // One line, always: a multi-line TOML diagnostic is folded so that grep and editors see it
    // as a single error.
    for (char& c : out) {
      if (c == '\n' || c == '\r') c = ' ';
    }
    return out;
  }

  source_location where_;
  std::string key_;
};

}  // namespace quadmc
