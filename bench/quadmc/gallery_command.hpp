// `quadmc gallery [--out DIR] [--realizations R] [--seed K] [--threads T]
//                 [--points NAME=PATH_TEMPLATE]…`: the pictures of every point set of the catalogue
// (estimators/point_set_catalogue.hpp) in s = 2, side by side the way [Pharr et al. 2016,
// §7.2–7.3] compares sampling patterns, written to results/gallery/ (or DIR), and beside them a
// row for each of the user's own point sets read from files (--points).
//
// Use it to see what a point set does before reading its error slopes: where its points fall,
// whether its projections are stratified, how its energy spreads over frequencies, and how
// uniform it is by number. Not a convergence study (that is `quadmc run`), and only s = 2.
//
// What it computes (this command computes and writes CSV; bench/gallery.py draws the PNGs):
//  - scatter.csv: the points of stream 0 of seed K at N = 16, 64, 256;
//  - strata.csv: the stratum grid each pictured set fills with exactly one point per stratum,
//    where it has one: `cells` (a k × k grid: jittered, unjittered, padded, and the Sobol' points,
//    a (0, m, 2)-net, at N = 4^j) or `rows_and_columns` (N columns and N rows of width 1/N:
//    Latin hypercube, and the rank-1 lattice, whose coordinates are i/N and i·z₂/N shifted with
//    z₂ odd);
//  - spectrum.csv: the radially averaged periodogram (sampling/periodogram.hpp) at N = 1024 over
//    R independent realizations (streams 0 … R − 1, default R = 256), bins |f| = 1 … 64;
//  - discrepancy.csv: the L2-star, centered and wrap-around discrepancies (sampling/
//    discrepancy.hpp) of the pictured points and their root mean square over min(R, 32)
//    realizations, at N = 16, 64, 256, 1024;
//  - README.md (the page), meta.csv (what built the command), gallery.png and spectra.png.
// --points NAME=PATH_TEMPLATE (repeatable) adds the user's set NAME after the catalogue's, in
// every file above with `set` = NAME, and user_points.csv (set, template, n, realizations; only
// then). The files are sampling/point_file.hpp's (CSV as `quadmc points` writes it, or .npy),
// s = 2, named by the template with "{N}" and "{r}" replaced as for the external_points method
// (README "Methods"); a relative template is read from the current folder. N = 16, 64, 256 and
// 1024 are all required (r = 0 at least), so that every row is complete and comparable; the
// realizations are r = 0, 1, … up to the first missing file, at most min(R, 32) at the scatter
// sizes (the discrepancies' RMS) and R at N = 1024 (the spectrum), 1 without "{r}". A user's set
// has no strata. NAME: 1 to 40 letters, digits, '_' or '-', not a set of the catalogue, not given
// twice (usage errors, exit 2). Every file is read and checked before anything is computed or
// written; a bad one is a one-line error naming it (and its row and column), exit 1.
// Same (K, R) and files → the same numbers, bit for bit, for any T (each set, a user's too, is
// computed by one thread, its realizations in the order r = 0, 1, …). The folder is replaced by the
// rules of report/results_staging.hpp (a folder holding anything else is refused). Errors are one
// line.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc_cli {

struct gallery_request {
  std::string out;  // empty: results/gallery
  std::uint64_t realizations = 256;
  std::uint64_t seed = 2026;
  unsigned threads = 0;             // 0: all cores; never more than the point sets
  std::vector<std::string> points;  // --points NAME=PATH_TEMPLATE, as given (checked when parsed)
};

// Adds the `gallery` subcommand to `app`, filling `request` when it is parsed.
CLI::App* add_gallery_subcommand(CLI::App& app, gallery_request& request);

// Whether `name` is a file the gallery writes (report/results_staging.hpp's predicate).
bool is_gallery_file_name(std::string_view name);

// Prints the plan, computes with a progress bar on a terminal, writes the folder and prints where.
// `print` writes to stdout. Throws with a one-line message on any failure.
void run_gallery(const gallery_request& request,
                 const std::function<void(std::string_view)>& print);

}  // namespace quadmc_cli
