// What produced a results folder: the quadmc version, the git commit, the compiler and the SIMD
// levels, the fields `quadmc --version` prints. Every results folder with CSV files holds them in
// meta.csv and its README.md lists them at the top, so that a table can always be traced to the
// code and the build that made it.
//
// Use it through run_info::build (markdown_report.hpp) and write_results_folder, or meta_csv_text
// and read_meta_csv for another writer (bench/peers) or a reader. Not a record of the run itself:
// seed, threads and run time are in the README header, the scene in every CSV row. Nothing in it
// is a result, so bench/same_results.py, which checks that figures did not move, does not read it
// (two runs of one scene from different commits differ here and nowhere else).
//
//   meta.csv  a header line and one row:
//     quadmc_version, commit, compiler, simd_levels_available, simd_level, rng
//   Like the other CSV files (results_csv.hpp): columns may be added at the end, never renamed
//   or removed.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

struct provenance {
  std::string version;   // quadmc's version, CMake's project(VERSION), e.g. "0.1.0"
  std::string commit;    // git commit of the source ("<hash>-dirty" with local changes), or
                         // "unknown" when the build could not tell (no git, not a checkout)
  std::string compiler;  // compiler, its version and the build type: "GNU 12.2.0 (Release)"
  std::vector<std::string> simd_levels_available;  // what this CPU and build support, scalar
                                                   // first (core/simd_level.hpp)
  std::string simd_level;                          // the level the kernels ran at
  // The generator(s) the random streams used (core/rng.hpp's names, joined by spaces where a
  // writer ran both): the scene's `rng`. Folders written before the column read as Philox, the
  // only generator then.
  std::string rng = "philox4x32_10";
};

inline constexpr std::array<std::string_view, 6> meta_csv_columns = {
    "quadmc_version", "commit", "compiler", "simd_levels_available", "simd_level", "rng"};

// The file name in a results folder.
inline constexpr std::string_view meta_csv_file = "meta.csv";

// meta.csv's text: the header line, then one row; simd_levels_available joined by spaces.
std::string meta_csv_text(const provenance& p);

// meta.csv read back (added columns ignored). Throws invalid_argument naming the file when it
// cannot be read, lacks a column of meta_csv_columns but the last (rng, added later), or has not
// exactly one row.
provenance read_meta_csv(const std::filesystem::path& file);

}  // namespace quadmc
