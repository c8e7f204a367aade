// Who leads a table whose rows compete column by column, smaller being better: the point sets of
// the gallery at each N (their discrepancies), the estimators × point sets of a render at each
// spp (their image RMSE). The answer lines at the top of those pages (quadmc gallery, quadmc
// render) are read from such tables with the rule of the run pages' "Who leads" (answer_first.hpp):
// the leader is the winner of the last column, named "from" the first column of its unbroken run
// of wins up to the last ("at every" column when that is the first); when the last two columns have
// different winners there is no steady leader, and the sentence says who won each of them.
//
// Use it for tables computed in one run; a run page's "Who leads at equal N" has its own
// computation (who_leads.hpp), which also knows rounding floors and skipped cells.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

struct scored_table {
  std::string column_label;            // what a column is, printed before its value: "N", "spp"
  std::vector<std::uint64_t> columns;  // increasing
  std::vector<std::string> rows;       // the competitors, in the page's order
  // values[row][column]; nullopt where the row has no figure at that column.
  std::vector<std::vector<std::optional<double>>> values;
};

// Per column, the row with the smallest value (a tie goes to the row listed first); nullopt where
// no row has a value. Throws quadmc::invalid_argument when a row's values do not match the columns.
std::vector<std::optional<std::size_t>> column_winners(const scored_table& t);

// The table's answer as a phrase, e.g. "`sobol` leads from N = 64 (0.0133 at N = 256, 3.29× below
// `independent`'s 0.0437)" or "no steady leader (`lattice` at N = 64, `sobol` at N = 256)".
// `baseline` names a row to compare the leader with at the last column (empty, absent, or the
// leader itself: no comparison). "no figures" when no column has a winner.
std::string leaders_phrase(const scored_table& t, std::string_view baseline = {});

}  // namespace quadmc
