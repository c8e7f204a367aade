// Reading point files: CSV and .npy into a checked row-major array (point_file.hpp).
#include "quadmc/sampling/point_file.hpp"

#include "quadmc/core/errors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <system_error>

namespace quadmc {
namespace {

namespace fs = std::filesystem;

// One line of error about the file as a whole.
[[noreturn]] void fail_file(const fs::path& file, std::string_view what,
                            std::string_view expected) {
  throw invalid_argument(fmt::format("point file {}", file.string()), std::string(what), expected);
}

// One line of error about the value at 1-based (row, column).
[[noreturn]] void fail_value(const fs::path& file, std::uint64_t row, std::size_t column,
                             std::string_view text, std::string_view expected) {
  throw invalid_argument(fmt::format("point file {} row {} column {}", file.string(), row, column),
                         text, expected);
}

// The file's bytes, after the checks that need no reading: it exists, is a regular file, and is
// not above max_point_file_bytes.
std::string read_bytes(const fs::path& file) {
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (status.type() == fs::file_type::not_found) {
    fail_file(file, "missing", "an existing file (is the path template right?)");
  }
  if (ec) fail_file(file, "unreadable", fmt::format("a readable file ({})", ec.message()));
  if (!fs::is_regular_file(status)) fail_file(file, "not a regular file", "a regular file");
  const std::uintmax_t bytes = fs::file_size(file, ec);
  if (ec) fail_file(file, "unreadable", fmt::format("a readable file ({})", ec.message()));
  if (bytes > max_point_file_bytes) {
    fail_file(file, fmt::format("{} bytes", bytes),
              fmt::format("at most {} bytes (max_point_file_bytes)", max_point_file_bytes));
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    fail_file(file, "unreadable", fmt::format("a readable file ({})", std::strerror(errno)));
  }
  std::string out(static_cast<std::size_t>(bytes), '\0');
  in.read(out.data(), static_cast<std::streamsize>(bytes));
  if (static_cast<std::uintmax_t>(in.gcount()) != bytes) {
    fail_file(file, "unreadable", "a file that reads to its end");
  }
  return out;
}

// The columns a row must have: s, plus the weight.
std::size_t columns_of(std::size_t s, point_file_columns columns) {
  return s + (columns == point_file_columns::points_and_weights ? 1 : 0);
}

// Checks the shape against what the caller expects, once the columns c and rows n are known.
void check_shape(const fs::path& file, std::uint64_t n, std::size_t c, point_file_columns columns,
                 std::uint64_t expected_n, std::size_t expected_s) {
  const bool weighted = columns == point_file_columns::points_and_weights;
  if (c < (weighted ? 2u : 1u)) {
    fail_file(file, fmt::format("{} columns", c),
              weighted ? "s coordinates and a weight per row (at least 2 columns)"
                       : "at least 1 coordinate per row");
  }
  if (expected_s != 0 && c != columns_of(expected_s, columns)) {
    fail_file(
        file, fmt::format("{} columns", c),
        fmt::format("{} (the integrand's dimension s = {}{})", columns_of(expected_s, columns),
                    expected_s, weighted ? ", plus the weight" : ""));
  }
  if (n == 0) fail_file(file, "0 rows", "at least 1 point");
  if (expected_n != 0 && n != expected_n) {
    fail_file(file, fmt::format("{} rows", n),
              fmt::format("N = {} rows, as the path's {{N}} says", expected_n));
  }
  if (n > max_point_file_values / c) {
    fail_file(file, fmt::format("{} × {} values", n, c),
              fmt::format("at most {} values (max_point_file_values)", max_point_file_values));
  }
}

// The data of a checked shape, its rows still to be stored (store): s from the columns c.
point_file_data empty_data(std::uint64_t n, std::size_t c, point_file_columns columns) {
  point_file_data out;
  out.s = c - (columns == point_file_columns::points_and_weights ? 1 : 0);
  out.n = n;
  out.x.reserve(n * out.s);
  if (columns == point_file_columns::points_and_weights) out.w.reserve(n);
  return out;
}

bool in_range(double v, point_file_columns columns) noexcept {
  return columns == point_file_columns::points ? v >= 0.0 && v < 1.0 : v >= 0.0 && v <= 1.0;
}

// Checks one value at 0-based (i, j) of c columns.
void check_value(const fs::path& file, double v, std::uint64_t i, std::size_t j, std::size_t c,
                 point_file_columns columns, std::string_view text) {
  const bool weight = columns == point_file_columns::points_and_weights && j + 1 == c;
  if (!std::isfinite(v)) {
    fail_value(file, i + 1, j + 1, text, weight ? "a finite weight" : "a finite coordinate");
  }
  // A rule's nodes may lie on the boundary (rules/weighted_point_set.hpp: the closed cube, as
  // Simpson's do); a point set's may not (sampling/point_set.hpp: [0, 1)).
  if (!weight && !in_range(v, columns)) {
    fail_value(file, i + 1, j + 1, text,
               columns == point_file_columns::points ? "a coordinate in [0, 1)"
                                                     : "a node coordinate in [0, 1]");
  }
}

void store(point_file_data& out, double v, std::size_t j, std::size_t s) {
  if (j < s) {
    out.x.push_back(v);
  } else {
    out.w.push_back(v);
  }
}

// A number that is the whole field, or nullopt.
std::optional<double> parse_number(std::string_view field) {
  double v = 0.0;
  const char* end = field.data() + field.size();
  const auto [ptr, ec] = std::from_chars(field.data(), end, v);
  if (ec != std::errc() || ptr != end || field.empty()) return std::nullopt;
  return v;
}

point_file_data read_csv(const fs::path& file, const std::string& text, point_file_columns columns,
                         std::uint64_t expected_n, std::size_t expected_s) {
  // The lines, without their "\n" or "\r\n"; a last line without "\n" counts, a final "\n" ends
  // the last line.
  std::vector<std::string_view> lines;
  std::string_view rest(text);
  while (!rest.empty()) {
    const std::size_t end = rest.find('\n');
    std::string_view line = rest.substr(0, end);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
  }
  auto fields_of = [](std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = line.find(',', start);
      out.push_back(line.substr(start, comma == std::string_view::npos ? comma : comma - start));
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    return out;
  };
  std::size_t first = 0;
  // A header: its first field is not a number (x1,x2,…,w as `quadmc points` writes it).
  if (!lines.empty() && !parse_number(fields_of(lines[0])[0])) first = 1;
  const std::uint64_t n = lines.size() - first;
  const std::size_t c = n == 0 ? 0 : fields_of(lines[first]).size();
  if (n == 0) fail_file(file, "no data rows", "at least 1 point");
  check_shape(file, n, c, columns, expected_n, expected_s);
  point_file_data out = empty_data(n, c, columns);
  for (std::uint64_t i = 0; i < n; ++i) {
    const std::vector<std::string_view> fields = fields_of(lines[first + i]);
    if (fields.size() != c) {
      fail_value(file, i + 1, std::min(fields.size(), c) + 1,
                 fmt::format("{} fields", fields.size()),
                 fmt::format("{} comma-separated values on every row (line {})", c, first + i + 1));
    }
    for (std::size_t j = 0; j < c; ++j) {
      const std::optional<double> v = parse_number(fields[j]);
      if (!v) fail_value(file, i + 1, j + 1, fmt::format("'{}'", fields[j]), "a decimal number");
      check_value(file, *v, i, j, c, columns, fields[j]);
      store(out, *v, j, out.s);
    }
  }
  return out;
}

// The .npy header dict, parsed strictly: exactly the keys 'descr', 'fortran_order' and 'shape'.
struct npy_header {
  std::string descr;
  bool fortran_order = true;
  std::vector<std::uint64_t> shape;
};

class npy_header_parser {
 public:
  npy_header_parser(const fs::path& file, std::string_view text) : file_(&file), text_(text) {}

  npy_header parse() {
    npy_header h;
    bool has_descr = false;
    bool has_order = false;
    bool has_shape = false;
    expect('{');
    while (true) {
      skip_space();
      if (peek() == '}') break;
      const std::string key = quoted();
      skip_space();
      expect(':');
      skip_space();
      if (key == "descr" && !has_descr) {
        h.descr = quoted();
        has_descr = true;
      } else if (key == "fortran_order" && !has_order) {
        h.fortran_order = boolean();
        has_order = true;
      } else if (key == "shape" && !has_shape) {
        h.shape = shape();
        has_shape = true;
      } else {
        bad(fmt::format("key '{}'", key),
            "each of 'descr', 'fortran_order', 'shape' exactly once and no other key");
      }
      skip_space();
      if (peek() == ',') {
        ++at_;
        continue;
      }
      if (peek() != '}') bad(context(), "',' or '}' in the header dict");
    }
    ++at_;
    skip_space();
    if (at_ != text_.size()) bad(context(), "the header to end after its dict");
    if (!has_descr || !has_order || !has_shape) {
      bad("a header without 'descr', 'fortran_order' or 'shape'", "all three keys");
    }
    return h;
  }

 private:
  [[noreturn]] void bad(std::string_view what, std::string_view expected) const {
    fail_file(*file_, fmt::format(".npy header {}", what), expected);
  }
  std::string context() const {
    return fmt::format("at byte {} ('{}')", at_, text_.substr(at_, 12));
  }
  char peek() const { return at_ < text_.size() ? text_[at_] : '\0'; }
  void skip_space() {
    while (at_ < text_.size() && (text_[at_] == ' ' || text_[at_] == '\n')) ++at_;
  }
  void expect(char c) {
    if (peek() != c) bad(context(), fmt::format("'{}'", c));
    ++at_;
  }
  std::string quoted() {
    const char q = peek();
    if (q != '\'' && q != '"') bad(context(), "a quoted string");
    const std::size_t end = text_.find(q, at_ + 1);
    if (end == std::string_view::npos) bad(context(), "a closed string");
    std::string out(text_.substr(at_ + 1, end - at_ - 1));
    at_ = end + 1;
    return out;
  }
  bool boolean() {
    if (text_.substr(at_, 4) == "True") {
      at_ += 4;
      return true;
    }
    if (text_.substr(at_, 5) == "False") {
      at_ += 5;
      return false;
    }
    bad(context(), "True or False");
  }
  std::vector<std::uint64_t> shape() {
    expect('(');
    std::vector<std::uint64_t> out;
    while (true) {
      skip_space();
      if (peek() == ')') break;
      std::uint64_t v = 0;
      const char* begin = text_.data() + at_;
      const auto [ptr, ec] = std::from_chars(begin, text_.data() + text_.size(), v);
      if (ec != std::errc() || ptr == begin) bad(context(), "a non-negative integer in 'shape'");
      at_ += static_cast<std::size_t>(ptr - begin);
      out.push_back(v);
      skip_space();
      if (peek() == ',') {
        ++at_;
      } else if (peek() != ')') {
        bad(context(), "',' or ')' in 'shape'");
      }
    }
    ++at_;
    return out;
  }

  const fs::path* file_;
  std::string_view text_;
  std::size_t at_ = 0;
};

std::uint64_t little_endian(const std::string& bytes, std::size_t at, std::size_t count) {
  std::uint64_t v = 0;
  for (std::size_t k = 0; k < count; ++k) {
    v |= std::uint64_t{static_cast<unsigned char>(bytes[at + k])} << (8 * k);
  }
  return v;
}

point_file_data read_npy(const fs::path& file, const std::string& bytes, point_file_columns columns,
                         std::uint64_t expected_n, std::size_t expected_s) {
  constexpr std::string_view magic("\x93NUMPY", 6);
  if (bytes.size() < 10 || std::string_view(bytes).substr(0, 6) != magic) {
    fail_file(file, "without the .npy magic \\x93NUMPY", "a NumPy .npy file");
  }
  const int major = static_cast<unsigned char>(bytes[6]);
  const int minor = static_cast<unsigned char>(bytes[7]);
  if ((major != 1 && major != 2 && major != 3) || minor != 0) {
    fail_file(file, fmt::format(".npy format version {}.{}", major, minor), "1.0, 2.0 or 3.0");
  }
  const std::size_t length_bytes = major == 1 ? 2 : 4;
  if (bytes.size() < 8 + length_bytes) fail_file(file, "a truncated .npy header", "a whole header");
  const std::uint64_t header_length = little_endian(bytes, 8, length_bytes);
  const std::size_t start = 8 + length_bytes;
  if (header_length > bytes.size() - start) {
    fail_file(file, fmt::format(".npy header length {}", header_length),
              fmt::format("at most the {} bytes after it", bytes.size() - start));
  }
  const std::string_view text(bytes.data() + start, header_length);
  if (text.empty() || text.back() != '\n') {
    fail_file(file, ".npy header without its final newline", "a header ending in '\\n'");
  }
  const npy_header h = npy_header_parser(file, text).parse();
  std::size_t item = 0;
  if (h.descr == "<f8") {
    item = 8;
  } else if (h.descr == "<f4") {
    item = 4;
  } else {
    fail_file(file, fmt::format(".npy dtype '{}'", h.descr),
              "'<f8' (float64) or '<f4' (float32), little-endian");
  }
  if (h.fortran_order) {
    fail_file(file, ".npy fortran_order True", "fortran_order False (C order)");
  }
  if (h.shape.size() != 2) {
    fail_file(file, fmt::format(".npy shape of {} dimensions", h.shape.size()), "shape (N, s)");
  }
  const std::uint64_t n = h.shape[0];
  if (h.shape[1] > max_point_file_values) {
    fail_file(file, fmt::format("{} columns", h.shape[1]),
              fmt::format("at most {} values (max_point_file_values)", max_point_file_values));
  }
  const auto c = static_cast<std::size_t>(h.shape[1]);
  check_shape(file, n, c, columns, expected_n, expected_s);
  const std::size_t data = start + header_length;
  if (bytes.size() - data != n * c * item) {
    fail_file(
        file, fmt::format("{} bytes of data", bytes.size() - data),
        fmt::format("{} × {} × {} = {} bytes for shape ({}, {})", n, c, item, n * c * item, n, c));
  }
  point_file_data out = empty_data(n, c, columns);
  for (std::uint64_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < c; ++j) {
      const std::size_t at = data + (i * c + j) * item;
      const std::uint64_t word = little_endian(bytes, at, item);
      const double v =
          item == 8 ? std::bit_cast<double>(word)
                    : static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(word)));
      if (!std::isfinite(v) || (j < out.s && !in_range(v, columns))) {
        check_value(file, v, i, j, c, columns, quote(v));
      }
      store(out, v, j, out.s);
    }
  }
  return out;
}

}  // namespace

point_file_data read_point_file(const fs::path& file, point_file_columns columns,
                                std::uint64_t expected_n, std::size_t expected_s) {
  const std::string bytes = read_bytes(file);
  if (file.extension() == ".npy") return read_npy(file, bytes, columns, expected_n, expected_s);
  return read_csv(file, bytes, columns, expected_n, expected_s);
}

fs::path point_file_path(std::string_view path_template, std::uint64_t N, std::uint64_t r,
                         const fs::path& folder) {
  std::string out;
  for (std::size_t k = 0; k < path_template.size();) {
    if (path_template.substr(k, 3) == "{N}") {
      out += std::to_string(N);
      k += 3;
    } else if (path_template.substr(k, 3) == "{r}") {
      out += std::to_string(r);
      k += 3;
    } else {
      out += path_template[k++];
    }
  }
  fs::path p(out);
  return p.is_relative() && !folder.empty() ? folder / p : p;
}

}  // namespace quadmc
