// "Who leads at equal N": per integrand family and dimension, the method of smallest error at each
// N of the ladder. One computation for the three places that show it: the page's "Who leads at
// equal N" section (markdown_report.cpp), the answer at the top of the page (answer_first.hpp)
// and who_leads.csv, which bench/plot.py draws as a picture.
//
// The rule: a family is an integrand's name without the "_s<s>" that a `dimensions` list appends
// (scene/parse.hpp), so dim_gaussian_s2 … _s16 form one family. At a ladder N, the competitors
// are the methods that spend at most N evaluations there: each enters with its cell of the
// largest ladder N' ≤ N, so a rule whose grid for N is the one it already ran for N' (a plan
// "same grid" skip) still competes, and the cell says "at N = N'". The error is the RMSE over
// the repetitions, |error| for a rule; the smallest wins, a tie goes to the series listed first.
// Only ladder cells (N > 0), only N where some method ran exactly N and two or more compete; a
// family run by one method has no table. The same rule for every scene, no integrand named.
//
// Use it on the tables of one run. Not for tolerance cells (N = 0: time_to_error_table.hpp) nor
// for comparing runs (compare.hpp).
#pragma once

#include "quadmc/analysis/convergence_table.hpp"
#include "quadmc/core/smoothness.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

// The winner of one (family, s, N) cell of the table.
struct leader {
  std::string method;
  double error = 0.0;      // its RMSE (|error| for a rule) at at_n
  std::uint64_t at_n = 0;  // the ladder N of the cell it competes with (≤ the column's N)
  bool at_floor = false;   // that cell is a rounding-floor point (rounding_floor.hpp): below
                           // it the methods differ by rounding, not by convergence
};

struct leaders_row {
  std::size_t s = 0;
  std::vector<std::optional<leader>> cells;  // one per ladder N; nullopt: "—"
};

struct family_leaders {
  std::string family;
  smoothness regularity = smoothness::analytic;  // of its first series
  std::vector<std::uint64_t> ladder;             // increasing
  std::vector<leaders_row> rows;                 // increasing s
};

// The name of an integrand's family across dimensions (the rule above).
std::string family_stem(std::string_view integrand, std::size_t s);

// The families with a table, in order of first appearance.
std::vector<family_leaders> who_leads(std::span<const convergence_table> tables);

// who_leads.csv: one row per (family, s, N) cell of the tables, "—" cells included with empty
// method, error, at_N and at_floor, so that the file has the shape of the tables:
//   scene, family, s, N, method, error, at_N, at_floor
// error in the shortest text that reads back to the same double, as in slopes.csv; at_floor 1
// where the winner's cell is a rounding-floor point, else 0.
inline constexpr std::string_view who_leads_csv_file = "who_leads.csv";
std::string who_leads_csv_text(std::string_view scene, std::span<const family_leaders> families);

}  // namespace quadmc
