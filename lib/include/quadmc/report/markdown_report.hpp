// The README.md page of a results folder, readable on GitHub: run header, slope summary, then per
// (integrand, s) the plots, one convergence table per method and the work-precision table.
//
// Use it through write_results_folder (results_folder.hpp), or render_results_markdown for the
// text alone. Not a plot generator: the SVGs are drawn by bench/plot.py from the CSV files; this
// page links them under the names below, which plot.py reproduces (keep the two in step).
#pragma once

#include "quadmc/analysis/convergence_table.hpp"
#include "quadmc/analysis/time_to_error_cells.hpp"
#include "quadmc/functions/effective_dimension.hpp"
#include "quadmc/functions/effective_dimension_estimate.hpp"
#include "quadmc/report/provenance.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

// An integrand's effective dimensions as the page states them.
struct effective_dimension_row {
  std::string integrand;  // the scene's name for it
  std::size_t s = 0;
  std::size_t instances = 1;                          // an ensemble's K: the row is instance 0's
  std::optional<quadmc::effective_dimensions> exact;  // nullopt: not a product of factors
  // Where there is no exact form: the pick-freeze estimate (effective_dimension_estimate.hpp);
  // nullopt when f's sampled variance is 0 or a value is not finite.
  std::optional<quadmc::effective_dimension_estimate> estimated;
  std::string not_estimated;  // what f threw while it was estimated; empty otherwise
};

// What the header of a results page says about the run. Empty strings / NaN are omitted.
struct run_info {
  std::string scene;
  std::string description;  // the scene's `description`, free text
  std::uint64_t seed = 0;
  unsigned threads = 0;              // threads the run really used (run_output::threads)
  unsigned threads_allowed = 0;      // the limit it had; 0 or equal to threads: not repeated
  unsigned ranks = 1;                // processes of a distributed (MPI) run, each on `threads`
  std::string machine;               // e.g. "x86_64, 2 cores"
  provenance build;                  // version, commit, compiler, SIMD levels (also meta.csv)
  double run_seconds = 0.0;          // wall time of the whole run
  std::vector<std::string> skipped;  // the plan's skipped cells, with their reason
  // Integrands whose errors are measured from a given or computed reference instead of an exact
  // value, each "name: reference = v ± u (how)" (scene/plan.hpp, plan_reference); empty: none.
  std::vector<std::string> references;
  // One row per integrand of the scene (its first instance): its effective dimensions, exact
  // where f is a product of factors (functions/effective_dimension.hpp), else estimated.
  std::vector<effective_dimension_row> effective_dimensions;
  // The time-to-error winners timed again alternately after the run (scene/paired_timing.hpp):
  // the "Time to error" section's ratios and time_to_error_pairs.csv; empty: not run.
  paired_timing_outcome paired_timing;
  // What else the folder holds ([output] of the scene): the page links only files that exist.
  bool csv = true;    // convergence.csv and slopes.csv
  bool plots = true;  // the error and work-precision plots
};

// Plot file names, distinct for distinct (integrand, s) by construction, so that no two series
// overwrite each other's plots (before, `x` and `x_s1` in s = 1 shared "x_s1.svg", and `y` and
// `work_precision_y` shared "work_precision_y_s1.svg"):
//  - a prefix per kind, "error_" and "work_precision_", keeps the two kinds apart;
//  - the integrand part is plot_stem(integrand) when the name already ends in "_s<s>" (every
//    default name and every `dimensions` expansion, scene/parse.hpp: "gaussian_s3" in s = 3 gives
//    error_gaussian_s3.svg), else plot_stem(integrand) + "_s=<s>" (`x` in s = 1 gives
//    error_x_s=1.svg, apart from `x_s1`'s error_x_s1.svg);
//  - plot_stem is one-to-one and never writes '=': bytes in [A-Za-z0-9_.-] (all a scene's names
//    may hold) stay, any other byte becomes "~XX" (two upper-case hex digits).
// So a name with '=' is an appended one and splits at it; one without is the integrand's own.
// '=' and '~' need no escaping in a Markdown link or a URL path (RFC 3986), so README.md links
// the names as they are. bench/plot.py writes the same names (keep the two in step).
std::string plot_stem(std::string_view integrand);
// "error_<…>.svg": error against N, one line per method (bench/plot.py draws it).
std::string convergence_plot_file(std::string_view integrand, std::size_t s);
// "work_precision_<…>.svg": error against seconds per estimate.
std::string work_precision_plot_file(std::string_view integrand, std::size_t s);

// The whole page. Tables are grouped by (integrand, s) in order of first appearance.
std::string render_results_markdown(const run_info& info,
                                    std::span<const convergence_table> tables);

}  // namespace quadmc
