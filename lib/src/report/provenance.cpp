// meta.csv of a results folder: what produced it (provenance.hpp).
#include "quadmc/report/provenance.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/report/csv.hpp"

#include <fmt/format.h>

#include <sstream>

namespace quadmc {

std::string meta_csv_text(const provenance& p) {
  std::string levels;
  for (const std::string& level : p.simd_levels_available) {
    levels += (levels.empty() ? "" : " ") + level;
  }
  const std::vector<std::string> header(meta_csv_columns.begin(), meta_csv_columns.end());
  const std::vector<std::string> row = {p.version, p.commit,     p.compiler,
                                        levels,    p.simd_level, p.rng};
  return csv_line(header) + csv_line(row);
}

provenance read_meta_csv(const std::filesystem::path& file) {
  const csv_table table = read_csv_file(file);
  for (const std::string_view column : meta_csv_columns) {
    if (column != "rng") (void)table.column(column);
  }
  if (table.rows.size() != 1) {
    throw invalid_argument(fmt::format("{}: expected one row after the header, found {}",
                                       file.string(), table.rows.size()));
  }
  const std::vector<std::string>& row = table.rows.front();
  provenance p;
  p.version = row[table.column("quadmc_version")];
  p.commit = row[table.column("commit")];
  p.compiler = row[table.column("compiler")];
  std::istringstream levels(row[table.column("simd_levels_available")]);
  for (std::string level; levels >> level;) p.simd_levels_available.push_back(level);
  p.simd_level = row[table.column("simd_level")];
  if (table.has_column("rng")) p.rng = row[table.column("rng")];
  return p;
}

}  // namespace quadmc
