// CSV text: quoting on write, parsing on read (RFC 4180: comma separator, fields holding a
// comma, quote, CR or LF are quoted, a quote inside is doubled, quoted fields may span lines).
//
// Use it for the results files (results_csv.hpp builds the two fixed tables on top). Not a general
// dialect sniffer: no other separators, no comment lines, no type inference; every field is text.
// The reader is tolerant of columns it does not know (columns may be added at the end of our
// files) and strict about the ones it needs: column() throws naming the file and the column.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

// The field as it must appear in a CSV line: quoted when it holds , " CR or LF.
std::string csv_field(std::string_view text);

// Fields joined by commas, each passed through csv_field, ended by "\n".
std::string csv_line(std::span<const std::string> fields);

struct csv_table {
  std::string source;  // file name (or a description) for error messages
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  // every row has header.size() fields

  // Index of a named column; throws invalid_argument "<source>: missing column '<name>'".
  std::size_t column(std::string_view name) const;
  bool has_column(std::string_view name) const noexcept;
};

// Parses CSV text whose first record is the header. Throws invalid_argument (naming `source` and
// the line) for an unterminated quote, a quote inside an unquoted field, an empty text, or a row
// whose field count differs from the header's. A final line break is optional; blank lines are
// skipped.
csv_table parse_csv(std::string_view text, std::string source);

// Reads and parses a file; throws invalid_argument naming the file when it cannot be read.
csv_table read_csv_file(const std::filesystem::path& file);

}  // namespace quadmc
