// Reading values out of a parsed TOML document with the scene layer's error rules: every value
// located (file:line:column of its key), every failure one scene_error line "file:line:column:
// key 'path': expected …, got …", unknown keys refused, text through toml_text.hpp's stand-ins.
//
// Use it for every TOML file the scene layer reads (scene files in parse.cpp, render scenes in
// render_scene.cpp), so that both report mistakes the same way. Private to lib/src/scene/: what a
// key means, its default and its bounds stay with the parser of that file; this only reads and
// refuses. Not for the library's C++ API, whose errors are plain quadmc::invalid_argument.
#pragma once

#include "quadmc/scene/scene.hpp"
#include "quadmc/scene/scene_error.hpp"

#include <toml++/toml.h>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc::scene_toml {

// A value as a message shows it after "got": numbers and booleans as written, strings quoted
// with their control characters escaped (one line), "an array", "a table", "a date/time".
std::string describe(const toml::node& n);

// A key and its value inside a table, with the dotted path used in messages ("method[2].name",
// "spp[3]" for an array's third element, which is located at its array's key).
struct entry {
  const toml::key* key = nullptr;
  const toml::node* value = nullptr;
  std::string path;
};

class reader {
 public:
  explicit reader(std::string file) : file_(std::move(file)) {}

  const std::string& file() const noexcept { return file_; }

  // The text parsed as TOML: the nesting bound and stand-ins of toml_safe_text first, and a
  // syntax error as a scene_error at toml++'s position (for a truncated file, its end).
  toml::table parse(std::string_view text) const;

  source_location at(const toml::source_region& region) const {
    return {file_, region.begin.line, region.begin.column};
  }
  source_location at(const entry& e) const { return at(e.key->source()); }
  // Where each key of `t` is, by its original text.
  key_locations locations(const toml::table& t) const;

  [[noreturn]] void fail(const source_location& where, std::string_view path,
                         std::string_view message) const;
  [[noreturn]] void fail(const entry& e, std::string_view message) const {
    fail(at(e), e.path, message);
  }
  // "expected `what`, got <the value>".
  [[noreturn]] void expected(const entry& e, std::string_view what) const;

  std::optional<entry> find(const toml::table& table, std::string_view key,
                            std::string_view prefix) const;
  static entry of(const toml::key& key, const toml::node& value, std::string_view prefix) {
    return {&key, &value, path(prefix, key.str())};
  }
  static std::string path(std::string_view prefix, std::string_view key);

  // Unknown keys are errors: a typo ("repetition") must not silently fall back to a default.
  void check_keys(const toml::table& table, std::span<const std::string_view> allowed,
                  std::string_view prefix, std::string_view what) const;

  // A whole number in [lo, hi]; integral floats are accepted so that "max_evaluations = 1e8"
  // reads as written.
  std::uint64_t count(const entry& e, std::uint64_t lo, std::uint64_t hi,
                      std::string_view what) const;
  // A TOML integer in [lo, hi]; a float, even an integral one, is refused.
  std::uint64_t integer(const entry& e, std::uint64_t lo, std::uint64_t hi,
                        std::string_view what) const;
  // A finite number, integer or float.
  double number(const entry& e, std::string_view what) const;
  std::string string(const entry& e, std::string_view what) const;
  bool boolean(const entry& e) const;

  // A name that becomes a file or folder name: is_portable_name, and when `bounded` at most
  // scene_limits::max_name_length characters.
  std::string display_name(const entry& e, bool bounded = true) const;

  const toml::table& table(const entry& e, std::string_view what) const;
  // The tables of an array of tables ([[integrand]]), at least one.
  const toml::array& tables(const entry& e, std::string_view header) const;
  // A non-empty array, or "expected `what`".
  const toml::array& array(const entry& e, std::string_view what) const;
  // Element i (0-based) of the array `e` holds, with the path "<path>[i + 1]".
  static entry element(const entry& e, std::size_t i);

 private:
  std::string file_;
};

}  // namespace quadmc::scene_toml
