// Tests for time_to_error_cells.hpp: what each method needs to reach a tolerance (true error, not
// its own claim; the smallest ladder N by RMSE), which cell wins for it (the one the paired
// timing re-times), quadmc's best against the best peer, and the paired record's median, min and
// max.
#include "quadmc/analysis/time_to_error_cells.hpp"

#include "quadmc/core/errors.hpp"
#include "time_to_error_sample.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace quadmc {
namespace {

using test::sample_pair;
using test::sample_reference;
using test::time_to_error_sample_tables;

TEST(TimeToErrorCells, EachMethodsTimeAndEvaluationsToTheTarget) {
  const std::vector<convergence_table> tables = time_to_error_sample_tables();
  const std::vector<time_to_error_cell> cells = time_to_error_cells(tables);
  ASSERT_EQ(cells.size(), 2u);
  const time_to_error_cell& loose = cells[0];
  EXPECT_EQ(loose.family, "genz_x");
  EXPECT_EQ(loose.s, 2u);
  EXPECT_EQ(loose.tolerance, 1e-3);
  EXPECT_TRUE(loose.relative);
  EXPECT_EQ(loose.target, 1e-3 * sample_reference);
  ASSERT_EQ(loose.methods.size(), 3u);
  EXPECT_TRUE(loose.methods[0].reached);
  EXPECT_EQ(loose.methods[0].seconds, 1e-5);
  EXPECT_EQ(loose.methods[0].evaluations, 100u);
  EXPECT_TRUE(loose.methods[1].peer);
  EXPECT_FALSE(loose.methods[0].peer);
  // The ladder: the smallest N whose RMSE meets 2e-3, with that cell's own time.
  EXPECT_TRUE(loose.methods[2].reached);
  EXPECT_EQ(loose.methods[2].evaluations, 256u);
  EXPECT_EQ(loose.methods[2].seconds, 3e-5);
  ASSERT_TRUE(loose.has_both());
  EXPECT_EQ(*loose.best_quadmc, 0u);  // genz_malik's 1e-5 s beats plain_mc's 3e-5 s
  EXPECT_EQ(*loose.best_peer, 1u);
  EXPECT_EQ(loose.ratio, 1e-5 / 2e-5);
  EXPECT_FALSE(loose.paired.has_value());

  // At 1e-6 genz_malik's estimate claimed the target but its true error 1e-5 is above 2e-6: not
  // reached; the ladder never gets there; the peer does, so quadmc's ratio is infinite.
  const time_to_error_cell& tight = cells[1];
  EXPECT_EQ(tight.tolerance, 1e-6);
  EXPECT_TRUE(tight.methods[0].ran);
  EXPECT_FALSE(tight.methods[0].reached);
  EXPECT_FALSE(tight.methods[2].reached);
  EXPECT_FALSE(tight.best_quadmc.has_value());
  EXPECT_FALSE(tight.has_both());
  ASSERT_TRUE(tight.best_peer.has_value());
  EXPECT_EQ(tight.methods[*tight.best_peer].seconds, 1e-4);
  EXPECT_TRUE(std::isinf(tight.ratio));
}

// The winning cell each entry names is the table row whose figures it shows: a tolerance
// method's row at that tolerance, a ladder method's smallest N whose RMSE meets the target (the
// cell the paired timing times again, scene/paired_timing.hpp).
TEST(TimeToErrorCells, EachEntryNamesItsWinningCell) {
  const std::vector<convergence_table> tables = time_to_error_sample_tables();
  const std::vector<time_to_error_cell> cells = time_to_error_cells(tables);
  ASSERT_EQ(cells.size(), 2u);
  for (const time_to_error_cell& c : cells) {
    for (std::size_t k = 0; k < c.methods.size(); ++k) {
      const time_to_error_entry& e = c.methods[k];
      EXPECT_EQ(e.table, k) << e.method;  // one table per method of the group, in order
      if (!e.reached) continue;
      ASSERT_LT(e.row, tables[e.table].rows.size()) << e.method;
      const convergence_row& row = tables[e.table].rows[e.row];
      EXPECT_EQ(row.seconds_per_estimate(), e.seconds) << e.method << " at " << c.tolerance;
      EXPECT_EQ(row.stats.evaluations, e.evaluations) << e.method << " at " << c.tolerance;
      EXPECT_LE(row.stats.rmse, c.target) << e.method << " at " << c.tolerance;
    }
  }
  // genz_malik's 1e-3 cell is its first row (tolerances in decreasing order), the peer's 1e-6
  // cell its second; plain_mc's winner at 1e-3 is N = 256, its second row, not the last.
  EXPECT_EQ(cells[0].methods[0].row, 0u);
  EXPECT_EQ(cells[1].methods[1].row, 1u);
  EXPECT_EQ(tables[2].rows[cells[0].methods[2].row].n, 256u);
}

TEST(TimeToErrorCells, NoCellsWithoutPeersOrWithoutTolerances) {
  const std::vector<convergence_table> tables = time_to_error_sample_tables();
  const std::vector<convergence_table> own{tables[0], tables[2]};
  EXPECT_TRUE(time_to_error_cells(own).empty());
  std::vector<convergence_table> ladder_only{tables[2], tables[2]};
  ladder_only[0].method = "peer_gsl_plain";
  EXPECT_TRUE(time_to_error_cells(ladder_only).empty());
}

TEST(TimeToErrorCells, PeerMethodsAreNamedPeer) {
  EXPECT_TRUE(is_peer_method("peer_hcubature"));
  EXPECT_FALSE(is_peer_method("genz_malik"));
  EXPECT_FALSE(is_peer_method("my_peer_hcubature"));
}

// Rounds 1e-5/2e-5, 3e-5/2e-5, 1e-5/1e-5, 2e-5/4e-5, 5e-5/1e-5: ratios 0.5, 1.5, 1, 0.5, 5 —
// median 1 (of 0.5, 0.5, 1, 1.5, 5), min 0.5, max 5; the sides' medians 2e-5 and 2e-5.
TEST(TimeToErrorCells, APairsRatioIsTheMedianOfItsRoundsWithTheirRange) {
  const time_to_error_pair pair =
      sample_pair({1e-5, 3e-5, 1e-5, 2e-5, 5e-5}, {2e-5, 2e-5, 1e-5, 4e-5, 1e-5});
  const paired_ratio r = summarise_pair(pair);
  ASSERT_EQ(r.rounds(), 5u);
  const double expected[] = {0.5, 1.5, 1.0, 0.5, 5.0};
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_DOUBLE_EQ(r.ratios[i], expected[i]) << "round " << i + 1;
  }
  EXPECT_DOUBLE_EQ(r.median, 1.0);
  EXPECT_DOUBLE_EQ(r.min, 0.5);
  EXPECT_DOUBLE_EQ(r.max, 5.0);
  EXPECT_EQ(r.quadmc_median_seconds, 2e-5);
  EXPECT_EQ(r.peer_median_seconds, 2e-5);
  // An even count: the mean of the middle two (ratios 0.5, 1, 1.5, 2).
  const paired_ratio even = summarise_pair(sample_pair({1.0, 2.0, 3.0, 4.0}, {2.0, 2.0, 2.0, 2.0}));
  EXPECT_DOUBLE_EQ(even.median, 1.25);
}

TEST(TimeToErrorCells, APairNeedsUsableRoundsOnBothSides) {
  EXPECT_THROW((void)summarise_pair(sample_pair({}, {})), invalid_argument);
  EXPECT_THROW((void)summarise_pair(sample_pair({1.0, 2.0}, {1.0})), invalid_argument);
  EXPECT_THROW((void)summarise_pair(sample_pair({1.0}, {0.0})), invalid_argument);
  EXPECT_THROW((void)summarise_pair(sample_pair({std::numeric_limits<double>::quiet_NaN()}, {1.0})),
               invalid_argument);
  try {
    (void)summarise_pair(sample_pair({1.0, 1.0}, {1.0, -2.0}));
    ADD_FAILURE() << "a negative time was accepted";
  } catch (const invalid_argument& e) {
    // Which round, of which pair.
    EXPECT_NE(std::string(e.what()).find("round 2 of genz_malik × peer_hcubature"),
              std::string::npos)
        << e.what();
  }
}

// attach_pairs gives a cell its pair only when integrand, s, tolerance and both winners match;
// the cell's ratio then is the paired median.
TEST(TimeToErrorCells, PairsAttachToTheirCellOnly) {
  const std::vector<convergence_table> tables = time_to_error_sample_tables();
  std::vector<time_to_error_cell> cells = time_to_error_cells(tables);
  std::vector<time_to_error_pair> pairs;
  pairs.push_back(sample_pair({3.0, 3.0, 3.0, 3.0, 3.0}, {2.0, 2.0, 2.0, 2.0, 2.0}));
  time_to_error_pair other_winner = pairs.front();
  other_winner.quadmc_method = "plain_mc";  // not this cell's quadmc best
  time_to_error_pair other_tolerance = pairs.front();
  other_tolerance.tolerance = 1e-6;
  EXPECT_TRUE(pairs_cell(pairs.front(), cells[0]));
  EXPECT_FALSE(pairs_cell(other_winner, cells[0]));
  EXPECT_FALSE(pairs_cell(other_tolerance, cells[0]));
  EXPECT_FALSE(pairs_cell(other_tolerance, cells[1]));  // no quadmc best at 1e-6: nothing to pair
  attach_pairs(cells, pairs);
  ASSERT_TRUE(cells[0].paired.has_value());
  EXPECT_EQ(cells[0].paired->rounds(), 5u);
  EXPECT_DOUBLE_EQ(cells[0].ratio, 1.5);
  EXPECT_FALSE(cells[1].paired.has_value());
  EXPECT_TRUE(std::isinf(cells[1].ratio));
}

}  // namespace
}  // namespace quadmc
