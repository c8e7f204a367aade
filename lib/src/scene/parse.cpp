// Scene parsing: toml++ document → quadmc::scene (parse.hpp documents every key).
//
// Every check reports through scene_reader::fail, so every message has the one shape
// "file:line:column: key 'path': expected …, got …" and points at the key (not the value), which
// is where an editor's cursor should land.
#include "quadmc/scene/parse.hpp"

#include "quadmc/rules/gauss_legendre_rule.hpp"
#include "quadmc/sampling/inversion_warps.hpp"
#include "quadmc/scene/methods.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>

namespace quadmc {

namespace {

// Counts above 2^53 are not exactly representable as doubles, which the analysis layer uses for
// N; point sets also need N·s < 2^62 (sampling/point_set.hpp), which make_plan checks per cell.
constexpr std::uint64_t max_count = std::uint64_t{1} << 53;
constexpr std::size_t max_dimension = scene_limits::max_dimension;
constexpr std::size_t max_ladder = scene_limits::max_ladder;

std::string describe(const toml::node& n) {
  if (const auto* v = n.as_integer()) return fmt::format("{}", v->get());
  if (const auto* v = n.as_floating_point()) return fmt::format("{}", v->get());
  if (const auto* v = n.as_string()) return fmt::format("\"{}\"", v->get());
  if (const auto* v = n.as_boolean()) return v->get() ? "true" : "false";
  if (n.is_array()) return "an array";
  if (n.is_table()) return "a table";
  return "a date/time";
}

// toml++ 3.3.0 has undefined behaviour on 3019 code points: its generated
// is_non_ascii_horizontal_whitespace() reaches __builtin_unreachable() for U+00A1…U+0499,
// U+2C5E…U+2FFF, U+3001…U+3057 and U+FB26…U+FEFE (found by the scene fuzzer, tests/fuzz/, on
// `name = "x"§`; the ranges come from calling it on every code point). They include π, σ, ε, é, §
// and ·, which scene descriptions and comments use. So toml++ never sees them: each is replaced by
// a stand-in from the private-use area U+E000…U+EBCA, on which that function is defined, and every
// string taken from the parsed document (values, keys, toml++'s messages) is mapped back. The
// mapping is one-to-one, and line/column positions do not move (one code point for one).
// Private-use characters of that block in the file itself would be ambiguous: they are an error.
struct code_point_range {
  char32_t first, last;
};
constexpr std::array<code_point_range, 4> toml_unsafe{
    {{0x00A1, 0x0499}, {0x2C5E, 0x2FFF}, {0x3001, 0x3057}, {0xFB26, 0xFEFE}}};
constexpr char32_t stand_in_base = 0xE000;
constexpr char32_t stand_in_count = 3019;  // Σ (last − first + 1) over toml_unsafe

constexpr char32_t stand_in_for(char32_t c) noexcept {  // 0 when c is safe
  char32_t offset = 0;
  for (const code_point_range& r : toml_unsafe) {
    if (c >= r.first && c <= r.last) return stand_in_base + offset + (c - r.first);
    offset += r.last - r.first + 1;
  }
  return 0;
}

constexpr char32_t original_of(char32_t c) noexcept {  // c itself when it is not a stand-in
  if (c < stand_in_base || c >= stand_in_base + stand_in_count) return c;
  char32_t offset = c - stand_in_base;
  for (const code_point_range& r : toml_unsafe) {
    const char32_t size = r.last - r.first + 1;
    if (offset < size) return r.first + offset;
    offset -= size;
  }
  return c;
}
static_assert(stand_in_for(0x00A7) == 0xE006 && original_of(0xE006) == 0x00A7);
static_assert(stand_in_for(0xFEFE) == stand_in_base + stand_in_count - 1);
static_assert(stand_in_for(0x00A0) == 0 && stand_in_for(0x3000) == 0);

// One well-formed UTF-8 sequence at text[i]: its code point and length, or length 0 when the
// bytes are not valid UTF-8 (those are left as they are, for toml++ to report).
struct decoded {
  char32_t c = 0;
  std::size_t length = 0;
};
decoded decode_utf8(std::string_view text, std::size_t i) noexcept {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(text[i + k]); };
  const unsigned char lead = b(0);
  const std::size_t n = lead < 0x80           ? 1
                        : (lead >> 5) == 0x6  ? 2
                        : (lead >> 4) == 0xE  ? 3
                        : (lead >> 3) == 0x1E ? 4
                                              : 0;
  if (n == 0 || i + n > text.size()) return {};
  char32_t c = n == 1 ? lead : lead & (0x7F >> n);
  for (std::size_t k = 1; k < n; ++k) {
    if ((b(k) & 0xC0) != 0x80) return {};
    c = (c << 6) | (b(k) & 0x3F);
  }
  return {c, n};
}

void encode_utf8(char32_t c, std::string& out) {
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

std::string with_stand_ins(std::string_view text, std::string_view file_name) {
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  std::uint32_t line = 1, column = 1;
  for (std::size_t i = 0; i < text.size();) {
    const decoded d = decode_utf8(text, i);
    const std::size_t length = d.length == 0 ? 1 : d.length;
    if (d.length > 1) {
      if (d.c >= stand_in_base && d.c < stand_in_base + stand_in_count) {
        throw scene_error({std::string(file_name), line, column}, "",
                          fmt::format("private-use character U+{:04X} is not supported in scene "
                                      "files",
                                      static_cast<std::uint32_t>(d.c)));
      }
      if (const char32_t stand_in = stand_in_for(d.c); stand_in != 0) {
        encode_utf8(stand_in, out);
      } else {
        out.append(text.substr(i, length));
      }
    } else {
      out.append(text.substr(i, length));
    }
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
    i += length;
  }
  return out;
}

std::string without_stand_ins(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const decoded d = decode_utf8(text, i);
    if (d.length == 0) {
      out += text[i++];
      continue;
    }
    encode_utf8(original_of(d.c), out);
    i += d.length;
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Nesting bound, checked before toml++ sees the text.
//
// toml++ 3.3 bounds arrays and inline tables (TOML_MAX_NESTED_VALUES = 256) but not dotted keys or
// table headers: every part of `a.a.a… = 1` or `[a.a.a…]` is one more nested table, and its
// recursion overflows the stack somewhere between 20,000 and 40,000 parts (an 80 KB file). So a
// lexical scan measures the depth first: each part of a dotted key or table header and each array
// or inline table is one level, summed from the root to the innermost value, and a file deeper
// than scene_limits::max_nesting is refused at the first level too many. A scene needs 4
// ([budget] N = { from = … }). The scan knows TOML's four string forms and its comments, so dots,
// brackets and braces inside them do not count; anything else it steps over without judging, since
// toml++ reports the syntax errors. Its own recursion is bounded by the same limit.
class nesting_scan {
 public:
  nesting_scan(std::string_view text, std::string_view file) : text_(text), file_(file) {}

  void run() {
    std::size_t header_depth = 0;
    while (skip_blank(true)) {
      if (peek() == '[') {  // [table] or [[array of tables]]
        const bool array = peek(1) == '[';
        advance();
        if (array) advance();
        header_depth = key(0);
      } else {
        const std::size_t depth = header_depth + key(header_depth);
        skip_blank(false);
        if (peek() == '=') {
          advance();
          value(depth);
        }
      }
      skip_line();
    }
  }

 private:
  bool at_end() const noexcept { return i_ >= text_.size(); }
  char peek(std::size_t ahead = 0) const noexcept {
    return i_ + ahead < text_.size() ? text_[i_ + ahead] : '\0';
  }
  bool starts_with(std::string_view s) const noexcept { return text_.substr(i_, s.size()) == s; }
  // Columns count code points, as toml++ and with_stand_ins do: UTF-8 continuation bytes do not
  // advance the column.
  void advance() noexcept {
    const char c = text_[i_++];
    if (c == '\n') {
      ++line_;
      column_ = 1;
    } else if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) {
      ++column_;
    }
  }

  // Called with the depth of the level that starts at the current position.
  void check_depth(std::size_t depth) const {
    if (depth <= scene_limits::max_nesting) return;
    throw scene_error({std::string(file_), line_, column_}, "",
                      fmt::format("nesting deeper than {} levels (each part of a dotted key or "
                                  "table header and each array or inline table counts one; a "
                                  "scene needs at most 4)",
                                  scene_limits::max_nesting));
  }

  // Spaces, tabs and comments, and newlines when `newlines`; false at the end of the text.
  bool skip_blank(bool newlines) noexcept {
    while (!at_end()) {
      const char c = peek();
      if (c == ' ' || c == '\t' || c == '\r' || (newlines && c == '\n')) {
        advance();
      } else if (c == '#') {
        while (!at_end() && peek() != '\n') advance();
      } else {
        break;
      }
    }
    return !at_end();
  }
  // The rest of a top-level line (a comment, or text toml++ will reject) and its newline.
  void skip_line() noexcept {
    while (!at_end() && peek() != '\n') {
      if (peek() == '"' || peek() == '\'') {
        string();
      } else if (peek() == '#') {
        skip_blank(false);
      } else {
        advance();
      }
    }
    if (!at_end()) advance();
  }

  // One string of any of TOML's four forms, from its opening quote. An unterminated one ends at
  // the end of its line (single-line forms) or of the text (multi-line forms).
  void string() noexcept {
    const char quote = peek();
    const bool basic = quote == '"';
    const std::string_view triple = basic ? std::string_view("\"\"\"") : "'''";
    if (starts_with(triple)) {
      for (int k = 0; k < 3; ++k) advance();
      while (!at_end() && !starts_with(triple)) {
        if (basic && peek() == '\\') advance();  // an escape: the next character is taken as is
        if (!at_end()) advance();
      }
      // The closing run may be up to five quotes long; the first two belong to the string.
      for (int k = 0; k < 5 && !at_end() && peek() == quote; ++k) advance();
      return;
    }
    advance();
    while (!at_end() && peek() != '\n') {
      const char c = peek();
      advance();
      if (c == quote) return;
      if (basic && c == '\\' && !at_end() && peek() != '\n') advance();
    }
  }

  // A possibly dotted key whose first part is at depth `base` + 1; returns its number of parts.
  std::size_t key(std::size_t base) {
    std::size_t parts = 0;
    for (;;) {
      skip_blank(false);
      check_depth(base + parts + 1);
      const std::size_t start = i_;
      if (peek() == '"' || peek() == '\'') {
        string();
      } else {
        while (!at_end() && (std::isalnum(static_cast<unsigned char>(peek())) != 0 ||
                             peek() == '_' || peek() == '-')) {
          advance();
        }
      }
      if (i_ == start) return parts;  // not a key: toml++ will say what it is
      ++parts;
      skip_blank(false);
      if (peek() != '.') return parts;
      advance();
    }
  }

  // One value whose key ends at `depth`: an array or inline table is one level deeper.
  void value(std::size_t depth) {
    skip_blank(false);
    const char c = peek();
    if (c == '[' || c == '{') {
      check_depth(depth + 1);
      advance();
      if (c == '[') {
        array(depth + 1);
      } else {
        inline_table(depth + 1);
      }
    } else if (c == '"' || c == '\'') {
      string();
    } else {
      // A number, boolean or date; it ends where a separator, comment or another value begins.
      constexpr std::string_view ends = ",]}#[{\"' \t\r\n";
      while (!at_end() && ends.find(peek()) == std::string_view::npos) advance();
    }
  }

  void array(std::size_t depth) {
    while (skip_blank(true)) {
      if (peek() == ']') {
        advance();
        return;
      }
      const std::size_t start = i_;
      value(depth);
      skip_blank(true);
      if (peek() == ',') {
        advance();
      } else if (i_ == start && !at_end()) {
        advance();  // neither a value nor a separator: step over it
      }
    }
  }

  void inline_table(std::size_t depth) {
    while (skip_blank(true)) {
      if (peek() == '}') {
        advance();
        return;
      }
      const std::size_t start = i_;
      const std::size_t parts = key(depth);
      skip_blank(false);
      if (peek() == '=') {
        advance();
        value(depth + parts);
      }
      skip_blank(true);
      if (peek() == ',') {
        advance();
      } else if (i_ == start && !at_end()) {
        advance();
      }
    }
  }

  std::string_view text_;
  std::string_view file_;
  std::size_t i_ = 0;
  std::uint32_t line_ = 1, column_ = 1;
};

// A key and its value inside a table, with the dotted path used in messages.
struct entry {
  const toml::key* key = nullptr;
  const toml::node* value = nullptr;
  std::string path;
};

class scene_reader {
 public:
  explicit scene_reader(std::string file) : file_(std::move(file)) {}

  const std::string& file() const noexcept { return file_; }

  source_location at(const toml::source_region& region) const {
    return {file_, region.begin.line, region.begin.column};
  }
  source_location at(const entry& e) const { return at(e.key->source()); }

  [[noreturn]] void fail(const source_location& where, std::string_view path,
                         std::string_view message) const {
    throw scene_error(where, without_stand_ins(path), without_stand_ins(message));
  }
  [[noreturn]] void fail(const entry& e, std::string_view message) const {
    fail(at(e), e.path, message);
  }
  [[noreturn]] void expected(const entry& e, std::string_view what) const {
    fail(e, fmt::format("expected {}, got {}", what, describe(*e.value)));
  }

  std::optional<entry> find(const toml::table& table, std::string_view key,
                            std::string_view prefix) const {
    const auto it = table.find(key);
    if (it == table.end()) return std::nullopt;
    return entry{&it->first, &it->second, path(prefix, key)};
  }

  static std::string path(std::string_view prefix, std::string_view key) {
    return prefix.empty() ? std::string(key) : fmt::format("{}.{}", prefix, key);
  }

  // Unknown keys are errors: a typo ("repetition") must not silently fall back to a default.
  void check_keys(const toml::table& table, std::span<const std::string_view> allowed,
                  std::string_view prefix, std::string_view what) const {
    for (auto&& [key, value] : table) {
      if (std::find(allowed.begin(), allowed.end(), key.str()) != allowed.end()) continue;
      std::string list;
      for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      fail(at(key.source()), path(prefix, key.str()),
           fmt::format("unknown key in {}; expected one of: {}", what, list));
    }
  }

  std::uint64_t count(const entry& e, std::uint64_t lo, std::uint64_t hi,
                      std::string_view what) const {
    // Integral floats are accepted so that "max_evaluations = 1e8" reads as written.
    if (const auto* i = e.value->as_integer()) {
      const std::int64_t v = i->get();
      if (v >= 0 && static_cast<std::uint64_t>(v) >= lo && static_cast<std::uint64_t>(v) <= hi) {
        return static_cast<std::uint64_t>(v);
      }
    } else if (const auto* f = e.value->as_floating_point()) {
      const double v = f->get();
      if (std::isfinite(v) && v == std::floor(v) && v >= static_cast<double>(lo) &&
          v <= static_cast<double>(hi)) {
        return static_cast<std::uint64_t>(v);
      }
    }
    expected(e, what);
  }

  double number(const entry& e, std::string_view what) const {
    if (const auto* i = e.value->as_integer()) return static_cast<double>(i->get());
    if (const auto* f = e.value->as_floating_point()) {
      if (std::isfinite(f->get())) return f->get();
    }
    expected(e, what);
  }

  std::string string(const entry& e, std::string_view what) const {
    if (const auto* s = e.value->as_string()) return without_stand_ins(s->get());
    expected(e, what);
  }

  bool boolean(const entry& e) const {
    if (const auto* b = e.value->as_boolean()) return b->get();
    expected(e, "true or false");
  }

  // Names become file and directory names in results/, so they stay portable. Integrand names
  // and method labels are also copied into every cell's listing and file names with a prefix
  // and a suffix, so they are at most max_name_length long; the scene's own `name` is one folder
  // name, whose length the command checks against the file system.
  std::string display_name(const entry& e, bool bounded = true) const {
    const std::string what =
        bounded ? fmt::format("a name of letters, digits, '_', '-', '.' (at most {} characters)",
                              max_name_length)
                : std::string("a name of letters, digits, '_', '-', '.'");
    std::string s = string(e, what);
    if (!is_portable_name(s) || (bounded && s.size() > max_name_length)) expected(e, what);
    return s;
  }
  static constexpr std::size_t max_name_length = scene_limits::max_name_length;

  static bool is_portable_name(std::string_view s) {
    if (s.empty() || s == "." || s == "..") return false;
    return std::all_of(s.begin(), s.end(), [](char c) {
      return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
             c == '_' || c == '-' || c == '.';
    });
  }

  const toml::table& table(const entry& e, std::string_view what) const {
    if (const auto* t = e.value->as_table()) return *t;
    expected(e, what);
  }

  // The tables of an array of tables ([[integrand]]), at least one.
  const toml::array& tables(const entry& e, std::string_view header) const {
    const auto* a = e.value->as_array();
    if (a == nullptr || a->empty() || !a->is_array_of_tables()) {
      expected(e, fmt::format("one or more [[{}]] tables", header));
    }
    return *a;
  }

 private:
  std::string file_;
};

key_locations locations_of(const scene_reader& r, const toml::table& t) {
  key_locations keys;
  for (auto&& [key, value] : t) keys.emplace(without_stand_ins(key.str()), r.at(key.source()));
  return keys;
}

// ---------------------------------------------------------------------------------------------
// [[integrand]]

// `taken` maps each display name in `out` to its index there.
void parse_integrand(const scene_reader& r, const toml::table& t, std::size_t index,
                     std::vector<integrand_spec>& out, std::map<std::string, std::size_t>& taken) {
  const std::string prefix = fmt::format("integrand[{}]", index);
  integrand_spec base;
  base.table_index = index;
  base.table = r.at(t.source());
  base.keys = locations_of(r, t);

  // Every key is copied into each integrand a `dimensions` list expands to: the count is
  // bounded so that a long table cannot multiply into gigabytes.
  if (t.size() > scene_limits::max_integrand_keys) {
    r.fail(base.table, prefix,
           fmt::format("{} keys in one [[integrand]] table; at most {} (family, name, dimension, "
                       "ensemble and the family's parameters)",
                       t.size(), scene_limits::max_integrand_keys));
  }
  const auto family = r.find(t, "family", prefix);
  if (!family) r.fail(base.table, prefix + ".family", "missing required key (a catalogue name)");
  base.family = r.string(*family, "a family name (`quadmc list` prints them)");
  if (base.family.empty() || base.family.size() > scene_limits::max_name_length) {
    r.expected(*family, "a family name (`quadmc list` prints them)");
  }

  std::optional<std::string> given_name;
  if (const auto e = r.find(t, "name", prefix)) given_name = r.display_name(*e);

  std::vector<std::size_t> dimensions;
  const auto dim = r.find(t, "dimension", prefix);
  const auto dims = r.find(t, "dimensions", prefix);
  if (dim && dims) r.fail(*dims, "give either `dimension` or `dimensions`, not both");
  // Neither: s = 0 asks the catalogue for the family's default (1, or 2 for irradiance);
  // make_plan fills in the real s.
  if (!dim && !dims) dimensions.push_back(0);
  const std::string_view dim_expected = "a dimension between 1 and 1024";
  if (dim) dimensions.push_back(r.count(*dim, 1, max_dimension, dim_expected));
  if (dims) {
    const auto* a = dims->value->as_array();
    if (a == nullptr || a->empty()) r.expected(*dims, "a non-empty array of dimensions");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const entry element{dims->key, a->get(i), fmt::format("{}[{}]", dims->path, i + 1)};
      const std::size_t s = r.count(element, 1, max_dimension, dim_expected);
      if (std::find(dimensions.begin(), dimensions.end(), s) != dimensions.end()) {
        r.fail(element, fmt::format("dimension {} is listed twice", s));
      }
      dimensions.push_back(s);
    }
  }
  if (const auto e = r.find(t, "ensemble", prefix)) {
    base.ensemble = r.count(*e, 1, 1'000'000, "an ensemble size between 1 and 1000000");
    base.ensemble_given = true;
  }

  // Every other key is a family parameter; the catalogue decides which ones the family takes.
  for (auto&& [key, value] : t) {
    const std::string_view k = key.str();
    if (k == "family" || k == "name" || k == "dimension" || k == "dimensions" || k == "ensemble") {
      continue;
    }
    const entry e{&key, &value, scene_reader::path(prefix, k)};
    const std::string what =
        fmt::format("a number or an array of numbers (a parameter of {})", base.family);
    if (value.is_number()) {
      base.scalars.emplace(without_stand_ins(k), r.number(e, what));
    } else if (const auto* a = value.as_array()) {
      if (a->empty()) r.expected(e, what);
      // A vector parameter has one entry per coordinate (the catalogue checks the exact length).
      if (a->size() > max_dimension) {
        r.fail(e, fmt::format("an array of {} numbers; a parameter has at most {} (one per "
                              "dimension)",
                              a->size(), max_dimension));
      }
      std::vector<double> v;
      for (std::size_t i = 0; i < a->size(); ++i) {
        const entry element{&key, a->get(i), fmt::format("{}[{}]", e.path, i + 1)};
        v.push_back(r.number(element, "a finite number"));
      }
      base.vectors.emplace(without_stand_ins(k), std::move(v));
    } else {
      r.expected(e, what);
    }
  }

  base.base_name = given_name.value_or(base.family);
  if (out.size() + dimensions.size() > scene_limits::max_integrands) {
    r.fail(dims ? r.at(*dims) : base.table, dims ? dims->path : prefix,
           fmt::format("the scene would have {} integrands (after `dimensions` lists expand); at "
                       "most {}",
                       out.size() + dimensions.size(), scene_limits::max_integrands));
  }
  for (std::size_t s : dimensions) {
    integrand_spec spec = base;
    spec.dimension = s;
    if (given_name && !dims) {
      spec.name = *given_name;
    } else {
      spec.name = s == 0 ? base.base_name : fmt::format("{}_s{}", base.base_name, s);
    }
    if (const auto it = taken.find(spec.name); it != taken.end()) {
      const integrand_spec& other = out[it->second];
      r.fail(spec.table, prefix + ".name",
             fmt::format("integrand name '{}' is already used by integrand[{}] (line {}); set "
                         "a distinct `name`",
                         spec.name, other.table_index, other.table.line));
    }
    taken.emplace(spec.name, out.size());
    out.push_back(std::move(spec));
  }
}

// ---------------------------------------------------------------------------------------------
// [[method]]

void parse_warp(const scene_reader& r, const entry& e, method_spec& m) {
  const warp_info* info = nullptr;
  std::optional<entry> parameter;
  if (e.value->is_string()) {
    m.warp = r.string(e, "a warp name");
    info = find_warp(m.warp);
    if (info == nullptr) r.expected(e, fmt::format("one of: {}", warp_names()));
  } else if (const auto* t = e.value->as_table()) {
    const auto name = r.find(*t, "name", e.path);
    if (!name) r.fail(e, fmt::format("missing `name` (one of: {})", warp_names()));
    m.warp = r.string(*name, "a warp name");
    info = find_warp(m.warp);
    if (info == nullptr) r.expected(*name, fmt::format("one of: {}", warp_names()));
    const std::array<std::string_view, 2> allowed{"name", info->parameter};
    r.check_keys(*t, allowed, e.path, fmt::format("warp '{}'", m.warp));
    parameter = r.find(*t, info->parameter, e.path);
  } else {
    r.expected(e, "a warp name or a table { name = …, <parameter> = … }");
  }
  m.warp_parameter = info->default_value;
  if (parameter) {
    // The warps' own bounds (sampling/inversion_warps.hpp explains them), checked here so that a
    // run never reaches a warp that refuses its parameter.
    if (m.warp == "power") {
      const std::string what =
          fmt::format("an exponent -1 < k <= {:g} (larger k round every sample to 1)",
                      power_warp::max_exponent);
      m.warp_parameter = r.number(*parameter, what);
      if (!(m.warp_parameter > -1.0 && m.warp_parameter <= power_warp::max_exponent)) {
        r.expected(*parameter, what);
      }
    } else {
      const std::string what =
          fmt::format("a rate 0 < |l| <= {:g} (e^l must stay a finite, normal double)",
                      truncated_exponential_warp::max_abs_rate);
      m.warp_parameter = r.number(*parameter, what);
      if (!(m.warp_parameter != 0.0 &&
            std::abs(m.warp_parameter) <= truncated_exponential_warp::max_abs_rate)) {
        r.expected(*parameter, what);
      }
    }
  }
}

void parse_panels(const scene_reader& r, const entry& e, method_spec& m) {
  const bool simpson = m.name == "simpson";
  const std::string_view what =
      simpson ? "an even panel count between 2 and 2^53" : "a panel count between 1 and 2^53";
  auto one = [&](const entry& element) {
    const std::uint64_t n = r.count(element, simpson ? 2 : 1, max_count, what);
    // Composite Simpson pairs the panels: an odd n leaves one panel without a partner.
    if (simpson && n % 2 != 0) r.expected(element, what);
    if (!m.panels.empty() && n <= m.panels.back()) {
      r.fail(element,
             fmt::format("panel counts must increase, got {} after {}", n, m.panels.back()));
    }
    m.panels.push_back(n);
  };
  if (const auto* a = e.value->as_array()) {
    if (a->empty()) r.expected(e, "a panel count or a non-empty array of panel counts");
    if (a->size() > max_ladder) r.fail(e, fmt::format("more than {} values", max_ladder));
    for (std::size_t i = 0; i < a->size(); ++i) {
      one(entry{e.key, a->get(i), fmt::format("{}[{}]", e.path, i + 1)});
    }
  } else {
    one(e);
  }
}

// The names a method's `integrands` list may use: display names and the `name` of a
// `dimensions` table. A set, so that long lists cost n·log n, not n × integrands.
using integrand_names = std::set<std::string, std::less<>>;

integrand_names names_of(const std::vector<integrand_spec>& integrands) {
  integrand_names names;
  for (const auto& f : integrands) {
    names.insert(f.name);
    names.insert(f.base_name);
  }
  return names;
}

method_spec parse_method(const scene_reader& r, const toml::table& t, std::size_t index,
                         const std::vector<integrand_spec>& integrands,
                         const integrand_names& names) {
  const std::string prefix = fmt::format("method[{}]", index);
  method_spec m;
  m.table_index = index;
  m.table = r.at(t.source());
  m.keys = locations_of(r, t);

  const auto name = r.find(t, "name", prefix);
  if (!name) {
    r.fail(m.table, prefix + ".name",
           fmt::format("missing required key (one of: {})", method_names()));
  }
  m.name = r.string(*name, "a method name");
  const method_info* info = find_method(m.name);
  if (info == nullptr) r.expected(*name, fmt::format("one of: {}", method_names()));
  r.check_keys(t, info->options, prefix, fmt::format("a '{}' method", m.name));

  if (const auto e = r.find(t, "repetitions", prefix)) {
    m.repetitions = r.count(*e, 1, 1'000'000'000, "a positive integer");
    m.repetitions_given = true;
  }
  if (const auto e = r.find(t, "m", prefix)) {
    const auto& supported = gauss_legendre_rule::supported_points;
    std::string list;
    for (unsigned p : supported) list += fmt::format("{}{}", list.empty() ? "" : " ", p);
    const std::string what = fmt::format("one of {}", list);
    m.m = r.count(*e, 1, gauss_legendre_rule::max_points, what);
    if (std::find(supported.begin(), supported.end(), m.m) == supported.end()) {
      r.expected(*e, what);
    }
  }
  if (const auto e = r.find(t, "panels", prefix)) parse_panels(r, *e, m);
  if (const auto e = r.find(t, "accumulator", prefix)) {
    constexpr std::string_view names = "one of: pairwise, neumaier, naive, long_double";
    const std::optional<summation> a = parse_summation(r.string(*e, names));
    if (!a) r.expected(*e, names);
    m.accumulator = *a;
    m.accumulator_given = true;
  }
  if (const auto e = r.find(t, "point_set", prefix)) {
    m.point_set = r.string(*e, "a point set name");
    if (find_point_set(m.point_set) == nullptr) {
      r.expected(*e, fmt::format("one of: {}", point_set_names()));
    }
  }
  const bool takes_point_set =
      std::find(info->options.begin(), info->options.end(), "point_set") != info->options.end();
  const bool point_set_given = !m.point_set.empty();
  if (takes_point_set && !point_set_given) m.point_set = "independent";

  if (const auto e = r.find(t, "warp", prefix)) {
    parse_warp(r, *e, m);
  } else if (m.name == "importance") {
    r.fail(m.table, prefix + ".warp",
           fmt::format("missing required key for importance (one "
                       "of: {})",
                       warp_names()));
  }

  if (const auto e = r.find(t, "integrands", prefix)) {
    const auto* a = e->value->as_array();
    if (a == nullptr || a->empty()) r.expected(*e, "a non-empty array of integrand names");
    if (a->size() > scene_limits::max_integrands) {
      r.fail(*e, fmt::format("more than {} names", scene_limits::max_integrands));
    }
    for (std::size_t i = 0; i < a->size(); ++i) {
      const entry element{e->key, a->get(i), fmt::format("{}[{}]", e->path, i + 1)};
      std::string n = r.string(element, "an integrand name");
      if (!names.contains(n)) {
        std::string known;
        constexpr std::size_t shown = 16;  // the message stays one readable line
        for (std::size_t k = 0; k < integrands.size() && k < shown; ++k) {
          known += (known.empty() ? "" : ", ") + integrands[k].name;
        }
        if (integrands.size() > shown) known += fmt::format(", … ({} in all)", integrands.size());
        r.fail(element, fmt::format("no integrand is named '{}' (integrands: {})", n, known));
      }
      m.integrands.push_back(std::move(n));
    }
  }

  if (const auto e = r.find(t, "label", prefix)) {
    m.label = r.display_name(*e);
  } else {
    m.label = m.name;
    if (!m.warp.empty()) m.label += "_" + m.warp;
    if (point_set_given) m.label += "_" + m.point_set;
    // One series per accumulator: midpoint_naive beside midpoint_neumaier.
    if (m.accumulator_given) m.label += "_" + std::string(to_string(m.accumulator));
  }
  return m;
}

// ---------------------------------------------------------------------------------------------
// [budget], [output]

std::vector<std::uint64_t> parse_ladder(const scene_reader& r, const entry& e) {
  const std::string_view what = "a count between 1 and 2^53";
  std::vector<std::uint64_t> ladder;
  if (const auto* a = e.value->as_array()) {
    if (a->empty()) r.expected(e, "a non-empty array of counts");
    if (a->size() > max_ladder) r.fail(e, fmt::format("more than {} values", max_ladder));
    for (std::size_t i = 0; i < a->size(); ++i) {
      const entry element{e.key, a->get(i), fmt::format("{}[{}]", e.path, i + 1)};
      const std::uint64_t n = r.count(element, 1, max_count, what);
      if (!ladder.empty() && n <= ladder.back()) {
        r.fail(element, fmt::format("values must increase, got {} after {}", n, ladder.back()));
      }
      ladder.push_back(n);
    }
    return ladder;
  }
  const auto* t = e.value->as_table();
  if (t == nullptr) r.expected(e, "an array of counts or { from = …, to = …, factor = … }");
  constexpr std::array<std::string_view, 3> keys{"from", "to", "factor"};
  r.check_keys(*t, keys, e.path, "a geometric range");
  const auto from = r.find(*t, "from", e.path);
  const auto to = r.find(*t, "to", e.path);
  const auto factor = r.find(*t, "factor", e.path);
  for (const auto& [k, found] : {std::pair{"from", from}, {"to", to}, {"factor", factor}}) {
    if (!found) r.fail(e, fmt::format("missing `{}` in the range", k));
  }
  const std::uint64_t lo = r.count(*from, 1, max_count, what);
  const std::uint64_t hi = r.count(*to, 1, max_count, what);
  if (hi < lo) r.expected(*to, fmt::format("a count ≥ from = {}", lo));
  const double f = r.number(*factor, "a factor > 1");
  if (!(f > 1.0)) r.expected(*factor, "a factor > 1");
  if (f == std::floor(f) && f < static_cast<double>(max_count)) {
    // Integral factor: exact integer products, so N = 4^k hits perfect powers exactly.
    const auto q = static_cast<std::uint64_t>(f);
    for (std::uint64_t n = lo;; n *= q) {
      ladder.push_back(n);
      if (ladder.size() > max_ladder) break;
      if (n > hi / q) break;
    }
  } else {
    // The loop below would run k = 0 … ⌈ln(to/from)/ln(factor)⌉ before leaving the range, and
    // rounding can repeat values for many steps (factor = 1.0000000001 from 1 to 10^6: 1.4·10^11
    // steps for 256 distinct values, minutes of work), so the count of steps is bounded first.
    // log1p(f − 1): f − 1 is exact for f ≤ 2 (Sterbenz), and log1p keeps its relative accuracy.
    const double ratio = static_cast<double>(hi) / static_cast<double>(lo);
    const double steps = std::ceil(std::log(ratio) / std::log1p(f - 1.0));
    if (!(steps <= static_cast<double>(scene_limits::max_ladder_steps))) {
      r.fail(
          *factor,
          fmt::format("factor = {} needs {:.3g} steps from {} to {}; at most {} "
                      "(a factor ≥ {:.6g} covers this range)",
                      f, steps, lo, hi, scene_limits::max_ladder_steps,
                      std::pow(ratio, 1.0 / static_cast<double>(scene_limits::max_ladder_steps))));
    }
    // One step more than the estimate, in case ⌈·⌉ rounded down a value that still fits.
    const auto last = static_cast<int>(steps) + 1;
    for (int k = 0; k <= last; ++k) {
      const double x = std::round(static_cast<double>(lo) * std::pow(f, k));
      if (x > static_cast<double>(hi)) break;
      const auto n = static_cast<std::uint64_t>(x);
      if (ladder.empty() || n > ladder.back()) ladder.push_back(n);
      if (ladder.size() > max_ladder) break;
    }
  }
  if (ladder.size() > max_ladder) {
    r.fail(e, fmt::format("the range gives more than {} values; use a larger factor", max_ladder));
  }
  return ladder;
}

budget_spec parse_budget(const scene_reader& r, const entry& e) {
  const toml::table& t = r.table(e, "a [budget] table");
  constexpr std::array<std::string_view, 3> keys{"N", "max_evaluations", "max_seconds"};
  r.check_keys(t, keys, "budget", "[budget]");
  budget_spec b;
  const auto N = r.find(t, "N", "budget");
  if (!N) r.fail(r.at(t.source()), "budget.N", "missing required key (the N ladder)");
  b.N = parse_ladder(r, *N);
  b.N_location = r.at(*N);
  if (const auto m = r.find(t, "max_evaluations", "budget")) {
    b.max_evaluations = r.count(*m, 1, std::numeric_limits<std::int64_t>::max(),
                                "a positive number of evaluations");
  }
  if (const auto s = r.find(t, "max_seconds", "budget")) {
    const double v = r.number(*s, "a positive number of seconds");
    if (!(v > 0.0)) r.expected(*s, "a positive number of seconds");
    b.max_seconds = v;
  }
  return b;
}

output_spec parse_output(const scene_reader& r, const entry& e) {
  const toml::table& t = r.table(e, "an [output] table");
  constexpr std::array<std::string_view, 3> keys{"csv", "markdown", "plots"};
  r.check_keys(t, keys, "output", "[output]");
  output_spec o;
  if (const auto v = r.find(t, "csv", "output")) o.csv = r.boolean(*v);
  if (const auto v = r.find(t, "markdown", "output")) o.markdown = r.boolean(*v);
  if (const auto v = r.find(t, "plots", "output")) o.plots = r.boolean(*v);
  // The plots are drawn from convergence.csv (bench/plot.py reads it from the results folder).
  if (o.plots && !o.csv) {
    const auto plots = r.find(t, "plots", "output");
    const auto csv = r.find(t, "csv", "output");
    r.fail(plots ? r.at(*plots) : r.at(t.source()), "output.plots",
           fmt::format("plots need the CSV they are drawn from, but output.csv = false (line {}); "
                       "set plots = false or csv = true",
                       r.at(*csv).line));
  }
  return o;
}

// ---------------------------------------------------------------------------------------------

scene parse_root(const scene_reader& r, const toml::table& root) {
  const source_location file_start{r.file(), 1, 1};
  if (root.empty()) {
    r.fail(file_start, "",
           "empty scene: expected at least [[integrand]], [[method]] and [budget] tables");
  }
  constexpr std::array<std::string_view, 8> keys{"name",      "description", "seed",   "threads",
                                                 "integrand", "method",      "budget", "output"};
  r.check_keys(root, keys, "", "the scene");

  scene sc;
  sc.file = r.file();
  if (const auto e = r.find(root, "name", "")) {
    sc.name = r.display_name(*e, false);
  } else {
    sc.name = std::filesystem::path(r.file()).stem().string();
    if (!scene_reader::is_portable_name(sc.name)) sc.name = "scene";
  }
  if (const auto e = r.find(root, "description", "")) sc.description = r.string(*e, "a string");
  if (const auto e = r.find(root, "seed", "")) {
    sc.seed = r.count(*e, 0, std::numeric_limits<std::int64_t>::max(), "an integer ≥ 0");
  }
  if (const auto e = r.find(root, "threads", "")) {
    sc.threads = static_cast<unsigned>(
        r.count(*e, 0, 4096, "a thread count between 0 (all cores) and 4096"));
  }

  const auto integrands = r.find(root, "integrand", "");
  if (!integrands) {
    r.fail(file_start, "integrand", "missing: a scene needs at least one [[integrand]] table");
  }
  const toml::array& integrand_tables = r.tables(*integrands, "integrand");
  std::map<std::string, std::size_t> taken;
  for (std::size_t i = 0; i < integrand_tables.size(); ++i) {
    parse_integrand(r, *integrand_tables.get(i)->as_table(), i + 1, sc.integrands, taken);
  }

  const auto methods = r.find(root, "method", "");
  if (!methods)
    r.fail(file_start, "method", "missing: a scene needs at least one [[method]] table");
  const toml::array& method_tables = r.tables(*methods, "method");
  const integrand_names names = names_of(sc.integrands);
  if (method_tables.size() > scene_limits::max_methods) {
    const auto& extra = *method_tables.get(scene_limits::max_methods)->as_table();
    r.fail(r.at(extra.source()), fmt::format("method[{}]", scene_limits::max_methods + 1),
           fmt::format("{} [[method]] tables; at most {}", method_tables.size(),
                       scene_limits::max_methods));
  }
  for (std::size_t i = 0; i < method_tables.size(); ++i) {
    method_spec m = parse_method(r, *method_tables.get(i)->as_table(), i + 1, sc.integrands, names);
    for (const auto& other : sc.methods) {
      if (other.label == m.label) {
        r.fail(m.table, fmt::format("method[{}].label", i + 1),
               fmt::format("method label '{}' is already used by method[{}] (line {}); set a "
                           "distinct `label`",
                           m.label, other.table_index, other.table.line));
      }
    }
    sc.methods.push_back(std::move(m));
  }

  const auto budget = r.find(root, "budget", "");
  if (!budget) r.fail(file_start, "budget", "missing required table [budget] (with N)");
  sc.budget = parse_budget(r, *budget);
  if (const auto e = r.find(root, "output", "")) sc.output = parse_output(r, *e);
  return sc;
}

}  // namespace

scene parse_scene(std::string_view toml_text, std::string_view file_name) {
  const scene_reader reader{std::string(file_name)};
  if (toml_text.size() > scene_limits::max_file_bytes) {
    throw scene_error({std::string(file_name), 0, 0}, "",
                      fmt::format("the scene is {} bytes; a scene file has at most {} (1 MiB)",
                                  toml_text.size(), scene_limits::max_file_bytes));
  }
  nesting_scan(toml_text, file_name).run();
  const std::string safe_text = with_stand_ins(toml_text, file_name);
  toml::table root;
  try {
    root = toml::parse(safe_text, file_name);
  } catch (const toml::parse_error& e) {
    // toml++'s own position: where the syntax broke (for a truncated file, its end).
    throw scene_error(reader.at(e.source()), "", without_stand_ins(e.description()));
  }
  return parse_root(reader, root);
}

scene parse_scene_file(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  const std::string name = path.string();
  auto fail = [&](std::string_view message) -> scene_error {
    return scene_error({name, 0, 0}, "", message);
  };
  // Only regular files and pipes (`quadmc run <(generate-scene)`) are read, and never more than
  // the limit plus one byte: /dev/zero, /dev/urandom or a terminal would otherwise be read until
  // memory runs out or forever.
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) throw fail("cannot open the scene file");
  if (fs::is_directory(status)) throw fail("is a directory, not a scene file");
  if (!fs::is_regular_file(status) && !fs::is_fifo(status)) {
    throw fail(fmt::format("not a regular file (a {}); a scene is a TOML file of at most {} bytes",
                           fs::is_character_file(status) ? "character device"
                           : fs::is_block_file(status)   ? "block device"
                           : fs::is_socket(status)       ? "socket"
                                                         : "special file",
                           scene_limits::max_file_bytes));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw fail("cannot open the scene file");
  std::string text;
  std::array<char, 65536> buffer{};
  while (text.size() <= scene_limits::max_file_bytes) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    text.append(buffer.data(), static_cast<std::size_t>(in.gcount()));
    if (!in) break;
  }
  if (in.bad()) throw fail("cannot read the scene file");
  if (text.size() > scene_limits::max_file_bytes) {
    throw fail(fmt::format("the scene file is larger than {} bytes (1 MiB), the limit",
                           scene_limits::max_file_bytes));
  }
  return parse_scene(text, name);
}

}  // namespace quadmc
