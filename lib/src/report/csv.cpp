// CSV quoting and parsing (RFC 4180); the contract is in csv.hpp.
#include "quadmc/report/csv.hpp"

#include "quadmc/core/errors.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace quadmc {

std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
  return out;
}

std::string csv_line(std::span<const std::string> fields) {
  std::string out;
  for (std::size_t k = 0; k < fields.size(); ++k) {
    if (k > 0) out += ',';
    out += csv_field(fields[k]);
  }
  out += '\n';
  return out;
}

std::size_t csv_table::column(std::string_view name) const {
  const auto it = std::find(header.begin(), header.end(), name);
  if (it == header.end()) {
    throw invalid_argument(
        fmt::format("{}: missing column '{}' (header: {})", source, name, fmt::join(header, ",")));
  }
  return static_cast<std::size_t>(it - header.begin());
}

bool csv_table::has_column(std::string_view name) const noexcept {
  return std::find(header.begin(), header.end(), name) != header.end();
}

csv_table parse_csv(std::string_view text, std::string source) {
  csv_table table;
  table.source = std::move(source);
  std::vector<std::vector<std::string>> records;
  std::vector<std::string> record;
  std::string field;
  bool quoted = false;         // inside a quoted field
  bool field_started = false;  // the record has content (blank lines are skipped)
  std::size_t line = 1;
  std::size_t record_line = 1;
  auto end_record = [&] {
    if (field_started || !record.empty()) {
      record.push_back(std::move(field));
      records.push_back(std::move(record));
    }
    record.clear();
    field.clear();
    field_started = false;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"') {
        if (i + 1 < text.size() && text[i + 1] == '"') {
          field += '"';
          ++i;
        } else {
          quoted = false;
          // After a closing quote only a separator or a line end may follow.
          if (i + 1 < text.size() && text[i + 1] != ',' && text[i + 1] != '\n' &&
              text[i + 1] != '\r') {
            throw invalid_argument(
                fmt::format("{}:{}: text after a closing quote", table.source, line));
          }
        }
      } else {
        if (c == '\n') ++line;
        field += c;
      }
      continue;
    }
    switch (c) {
      case '"':
        if (!field.empty()) {
          throw invalid_argument(
              fmt::format("{}:{}: quote inside an unquoted field", table.source, line));
        }
        quoted = true;
        field_started = true;
        break;
      case ',':
        record.push_back(std::move(field));
        field.clear();
        field_started = true;
        break;
      case '\r':
        break;  // CRLF line ends: the LF ends the record
      case '\n':
        end_record();
        ++line;
        record_line = line;
        break;
      default:
        field += c;
        field_started = true;
    }
  }
  if (quoted) {
    throw invalid_argument(
        fmt::format("{}:{}: unterminated quoted field", table.source, record_line));
  }
  end_record();
  if (records.empty())
    throw invalid_argument(fmt::format("{}: empty CSV, no header", table.source));
  table.header = std::move(records.front());
  for (std::size_t r = 1; r < records.size(); ++r) {
    if (records[r].size() != table.header.size()) {
      throw invalid_argument(fmt::format("{}: record {} has {} fields, the header has {}",
                                         table.source, r + 1, records[r].size(),
                                         table.header.size()));
    }
    table.rows.push_back(std::move(records[r]));
  }
  return table;
}

csv_table read_csv_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw invalid_argument("file", file.string(), "a readable CSV file");
  std::ostringstream text;
  text << in.rdbuf();
  std::string content = text.str();
  // A spreadsheet that saves "CSV UTF-8" puts a byte-order mark first, which made the first
  // column "\xEF\xBB\xBFscene" and the error "missing column 'scene'". It carries no data.
  constexpr std::string_view bom = "\xEF\xBB\xBF";
  if (content.starts_with(bom)) content.erase(0, bom.size());
  return parse_csv(content, file.string());
}

}  // namespace quadmc
