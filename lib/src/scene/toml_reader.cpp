// The scene layer's TOML reader (toml_reader.hpp): typed getters and refusals, each failure a
// one-line scene_error at the key.
#include "toml_reader.hpp"

#include "quadmc/scene/parse.hpp"
#include "quadmc/scene/toml_text.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

namespace quadmc::scene_toml {

std::string describe(const toml::node& n) {
  if (const auto* v = n.as_integer()) return fmt::format("{}", v->get());
  if (const auto* v = n.as_floating_point()) return fmt::format("{}", v->get());
  if (const auto* v = n.as_string()) {
    // Control characters escaped as TOML writes them: a message is one line, and "a\nb" shown
    // as "a b" was another name than the one refused.
    std::string text;
    for (const char c : v->get()) {
      switch (c) {
        case '\n':
          text += "\\n";
          break;
        case '\t':
          text += "\\t";
          break;
        case '\r':
          text += "\\r";
          break;
        case '"':
          text += "\\\"";
          break;
        case '\\':
          text += "\\\\";
          break;
        default:
          if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
            text += fmt::format("\\u{:04X}", static_cast<unsigned char>(c));
          } else {
            text += c;
          }
      }
    }
    return fmt::format("\"{}\"", text);
  }
  if (const auto* v = n.as_boolean()) return v->get() ? "true" : "false";
  if (n.is_array()) return "an array";
  if (n.is_table()) return "a table";
  return "a date/time";
}

toml::table reader::parse(std::string_view text) const {
  const std::string safe_text = toml_safe_text(text, file_);
  try {
    return toml::parse(safe_text, file_);
  } catch (const toml::parse_error& e) {
    throw scene_error(at(e.source()), "", toml_original_text(e.description()));
  }
}

key_locations reader::locations(const toml::table& t) const {
  key_locations keys;
  for (auto&& [key, value] : t) keys.emplace(toml_original_text(key.str()), at(key.source()));
  return keys;
}

void reader::fail(const source_location& where, std::string_view path,
                  std::string_view message) const {
  throw scene_error(where, toml_original_text(path), toml_original_text(message));
}

void reader::expected(const entry& e, std::string_view what) const {
  fail(e, fmt::format("expected {}, got {}", what, describe(*e.value)));
}

std::optional<entry> reader::find(const toml::table& table, std::string_view key,
                                  std::string_view prefix) const {
  const auto it = table.find(key);
  if (it == table.end()) return std::nullopt;
  return entry{&it->first, &it->second, path(prefix, key)};
}

std::string reader::path(std::string_view prefix, std::string_view key) {
  return prefix.empty() ? std::string(key) : fmt::format("{}.{}", prefix, key);
}

void reader::check_keys(const toml::table& table, std::span<const std::string_view> allowed,
                        std::string_view prefix, std::string_view what) const {
  for (auto&& [key, value] : table) {
    if (std::find(allowed.begin(), allowed.end(), key.str()) != allowed.end()) continue;
    fail(at(key.source()), path(prefix, key.str()),
         fmt::format("unknown key in {}; expected one of: {}", what, fmt::join(allowed, ", ")));
  }
}

std::uint64_t reader::count(const entry& e, std::uint64_t lo, std::uint64_t hi,
                            std::string_view what) const {
  if (e.value->is_integer()) return integer(e, lo, hi, what);
  if (const auto* f = e.value->as_floating_point()) {
    const double v = f->get();
    if (std::isfinite(v) && v == std::floor(v) && v >= static_cast<double>(lo) &&
        v <= static_cast<double>(hi)) {
      return static_cast<std::uint64_t>(v);
    }
  }
  expected(e, what);
}

std::uint64_t reader::integer(const entry& e, std::uint64_t lo, std::uint64_t hi,
                              std::string_view what) const {
  if (const auto* i = e.value->as_integer()) {
    const std::int64_t v = i->get();
    if (v >= 0 && static_cast<std::uint64_t>(v) >= lo && static_cast<std::uint64_t>(v) <= hi) {
      return static_cast<std::uint64_t>(v);
    }
  }
  expected(e, what);
}

double reader::number(const entry& e, std::string_view what) const {
  if (const auto* i = e.value->as_integer()) return static_cast<double>(i->get());
  if (const auto* f = e.value->as_floating_point()) {
    if (std::isfinite(f->get())) return f->get();
  }
  expected(e, what);
}

std::string reader::string(const entry& e, std::string_view what) const {
  if (const auto* s = e.value->as_string()) return toml_original_text(s->get());
  expected(e, what);
}

bool reader::boolean(const entry& e) const {
  if (const auto* b = e.value->as_boolean()) return b->get();
  expected(e, "true or false");
}

// Names become file and directory names in results/, so they stay portable. Integrand names
// and method labels are also copied into every cell's listing and file names with a prefix
// and a suffix, so they are at most max_name_length long; a scene's own `name` is one folder
// name, whose length the command checks against the file system.
std::string reader::display_name(const entry& e, bool bounded) const {
  // "." and ".." are made of those characters but name the folder itself and its parent.
  const std::string what =
      bounded ? fmt::format(
                    "a name of letters, digits, '_', '-', '.', other than '.' and '..' "
                    "(at most {} characters)",
                    scene_limits::max_name_length)
              : std::string("a name of letters, digits, '_', '-', '.', other than '.' and '..'");
  std::string s = string(e, what);
  if (!is_portable_name(s) || (bounded && s.size() > scene_limits::max_name_length)) {
    expected(e, what);
  }
  return s;
}

const toml::table& reader::table(const entry& e, std::string_view what) const {
  if (const auto* t = e.value->as_table()) return *t;
  expected(e, what);
}

const toml::array& reader::tables(const entry& e, std::string_view header) const {
  const auto* a = e.value->as_array();
  if (a == nullptr || a->empty() || !a->is_array_of_tables()) {
    expected(e, fmt::format("one or more [[{}]] tables", header));
  }
  return *a;
}

const toml::array& reader::array(const entry& e, std::string_view what) const {
  const auto* a = e.value->as_array();
  if (a == nullptr || a->empty()) expected(e, what);
  return *a;
}

entry reader::element(const entry& e, std::size_t i) {
  return {e.key, e.value->as_array()->get(i), fmt::format("{}[{}]", e.path, i + 1)};
}

}  // namespace quadmc::scene_toml
