// The README.md page of a results folder, readable on GitHub: run header, slope summary, then per
// (integrand, s) the plots, one convergence table per method and the work-precision table.
//
// Use it through write_results_folder (results_folder.hpp), or render_results_markdown for the
// text alone. Not a plot generator: the SVGs are drawn by bench/plot.py from the CSV files; this
// page links them under the names below, which plot.py reproduces (keep the two in step).
#pragma once

#include "quadmc/analysis/convergence_table.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

// What the header of a results page says about the run. Empty strings / NaN are omitted.
struct run_info {
  std::string scene;
  std::uint64_t seed = 0;
  unsigned threads = 0;
  std::string machine;               // e.g. "x86_64, 2 cores"
  std::string compiler;              // e.g. "GCC 12.2.0 -O2"
  double run_seconds = 0.0;          // wall time of the whole run
  std::vector<std::string> skipped;  // the plan's skipped cells, with their reason
};

// File-name-safe form of an integrand name: every character outside [A-Za-z0-9_.-] becomes '_'.
std::string plot_stem(std::string_view integrand);
// "<integrand>_s<s>.svg": error against N, one line per method (bench/plot.py draws it).
std::string convergence_plot_file(std::string_view integrand, std::size_t s);
// "work_precision_<integrand>_s<s>.svg": error against seconds per estimate.
std::string work_precision_plot_file(std::string_view integrand, std::size_t s);

// The whole page. Tables are grouped by (integrand, s) in order of first appearance.
std::string render_results_markdown(const run_info& info,
                                    std::span<const convergence_table> tables);

}  // namespace quadmc
