// The text toml++ is given (toml_text.hpp): a nesting bound and stand-ins for the code points
// toml++ 3.3.0 mishandles.
#include "quadmc/scene/toml_text.hpp"

#include "quadmc/scene/parse.hpp"
#include "quadmc/scene/scene_error.hpp"

#include <fmt/format.h>

#include <array>
#include <cctype>
#include <cstdint>

namespace quadmc {
namespace {

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

}  // namespace

std::string toml_safe_text(std::string_view text, std::string_view file_name) {
  nesting_scan(text, file_name).run();
  return with_stand_ins(text, file_name);
}

std::string toml_original_text(std::string_view text) {
  return without_stand_ins(text);
}

}  // namespace quadmc
