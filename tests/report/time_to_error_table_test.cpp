// Tests for time_to_error_table.hpp: the page's "Time to error" section and its summary, with and
// without the paired timing's pairs; time_to_error_pairs.csv; no table for a scene without peers
// or tolerances. Which cell wins is analysis/time_to_error_cells.hpp's, tested there.
#include "quadmc/report/time_to_error_table.hpp"

#include "../analysis/time_to_error_sample.hpp"
#include "quadmc/report/csv.hpp"
#include "quadmc/report/markdown_report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace quadmc {
namespace {

using test::sample_pair;
using test::time_to_error_sample_tables;

TEST(TimeToErrorTable, SummaryOverTheCells) {
  const std::vector<convergence_table> tables = time_to_error_sample_tables();
  const std::vector<time_to_error_cell> cells = time_to_error_cells(tables);
  const time_to_error_summary sum = summarise_time_to_error(cells);
  EXPECT_EQ(sum.analytic_cells, 2u);
  EXPECT_EQ(sum.analytic_met, 1u);
  EXPECT_EQ(sum.peer_cells, 2u);
  EXPECT_TRUE(std::isinf(sum.worst_ratio));
  EXPECT_EQ(sum.worst_cell, 1u);
}

TEST(TimeToErrorTable, OnThePageWithItsSummary) {
  const std::vector<convergence_table> tables = time_to_error_sample_tables();
  const std::string page = render_results_markdown(run_info{}, tables);
  EXPECT_NE(page.find("## Time to error"), std::string::npos);
  EXPECT_NE(page.find("| genz_x | 2 | 0.001 ·\\|I\\| | 2.000e-03 | analytic |"), std::string::npos)
      << page;
  EXPECT_NE(page.find("genz_malik (1e-05 s) | peer_hcubature (2e-05 s) | 0.5 |"), std::string::npos)
      << page;
  EXPECT_NE(page.find("1e-05 s, 100"), std::string::npos);
  EXPECT_NE(page.find("3e-05 s, 256"), std::string::npos);
  EXPECT_NE(page.find("not reached"), std::string::npos);
  EXPECT_NE(page.find("peer reaches the target): 1 of 2 (50%)"), std::string::npos) << page;
  EXPECT_NE(page.find("worst ratio among the 2 cells a peer reaches: ∞"), std::string::npos)
      << page;
  // Without a paired timing the page says its ratios are single timings.
  EXPECT_NE(page.find("single stable timings"), std::string::npos) << page;
  EXPECT_EQ(page.find("alternating runs"), std::string::npos) << page;
}

// With a pair, the 1e-3 cell's ratio is the median of its rounds with their min–max, the
// explanation says how it was measured, and the summary counts by the median: here quadmc's
// single timing was faster (0.5) but the paired median is 1.5, so the cell is not met and is the
// worst finite ratio.
TEST(TimeToErrorTable, PairedRatiosWithTheirSpreadAndTheSummaryByTheMedian) {
  const std::vector<convergence_table> tables = time_to_error_sample_tables();
  paired_timing_outcome paired;
  paired.rounds = 5;
  paired.seconds = 0.25;
  paired.pairs.push_back(sample_pair({3.0, 2.0, 4.0, 3.0, 3.0}, {2.0, 2.0, 2.0, 2.0, 2.0}));
  // Ratios 1.5, 1, 2, 1.5, 1.5: median 1.5, min 1, max 2.
  const std::string text = time_to_error_markdown(tables, paired);
  EXPECT_NE(text.find("genz_malik (1e-05 s) | peer_hcubature (2e-05 s) | 1.5 (1–2 over 5 "
                      "alternating runs) |"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("alternately — quadmc, peer, quadmc, peer, … — 5 rounds"), std::string::npos)
      << text;
  EXPECT_NE(text.find("(every round in `time_to_error_pairs.csv`; the paired timing took 0.25 s)"),
            std::string::npos)
      << text;
  // A folder without CSV files does not point at one.
  const std::string no_csv = time_to_error_markdown(tables, paired, 1, false);
  EXPECT_EQ(no_csv.find("time_to_error_pairs.csv"), std::string::npos) << no_csv;
  EXPECT_NE(no_csv.find("(the paired timing took 0.25 s)"), std::string::npos) << no_csv;
  EXPECT_NE(text.find("by the median of the alternating runs where paired: 0 of 2 (0%)"),
            std::string::npos)
      << text;
  // The worst ratio stays the infinite one (quadmc does not reach 1e-6).
  EXPECT_NE(text.find("worst ratio among the 2 cells a peer reaches: ∞ (quadmc not reached; "
                      "genz_x, s = 2, tolerance 1e-06)\n"),
            std::string::npos)
      << text;
  // Where genz_malik meets 1e-6 too (single ratio 4e-5 / 1e-4 = 0.4 there), the worst is the
  // paired median of the 1e-3 cell, with its spread — though its single ratio was 0.5.
  std::vector<convergence_table> both_met = tables;
  both_met[0] = test::to_tolerance("genz_malik", 1e-3, 1e-5, 1e-6, 4e-5);
  const std::string met = time_to_error_markdown(both_met, paired);
  EXPECT_NE(met.find("worst ratio among the 2 cells a peer reaches: 1.5 (1–2 over 5 alternating "
                     "runs; genz_x, s = 2, tolerance 0.001)\n"),
            std::string::npos)
      << met;
  EXPECT_NE(met.find("where paired: 1 of 2 (50%)"), std::string::npos) << met;

  // Over the paired cell alone the worst ratio is its median.
  std::vector<time_to_error_cell> cells = time_to_error_cells(tables);
  attach_pairs(cells, paired.pairs);
  const time_to_error_summary sum = summarise_time_to_error(std::span(cells).first(1));
  EXPECT_EQ(sum.worst_ratio, 1.5);
  EXPECT_EQ(sum.analytic_met, 0u);

  // A cell the pass could not pair is listed with its reason; under mpirun rank 0 is named.
  paired.not_paired.push_back("genz_x, s = 2, tolerance 0.001·|I|: budget spent");
  const std::string mpi = time_to_error_markdown(tables, paired, 2);
  EXPECT_NE(mpi.find("- not paired, single timings: genz_x, s = 2, tolerance 0.001·|I|: budget "
                     "spent\n"),
            std::string::npos)
      << mpi;
  EXPECT_NE(mpi.find("on MPI rank 0 while the other ranks waited idle"), std::string::npos) << mpi;
}

TEST(TimeToErrorTable, PairsCsvHasOneRowPerPairWithEachRound) {
  std::vector<time_to_error_pair> pairs = {
      sample_pair({3.0, 2.0, 4.0, 3.0, 3.0}, {2.0, 2.0, 2.0, 2.0, 2.0})};
  pairs.front().quadmc_n = 0;
  pairs.front().peer_n = 0;
  const csv_table csv =
      parse_csv(time_to_error_pairs_csv_text("unit", pairs), "time_to_error_pairs.csv");
  const std::vector<std::string> header = {"scene",
                                           "family",
                                           "integrand",
                                           "s",
                                           "tolerance",
                                           "tolerance_kind",
                                           "quadmc_method",
                                           "quadmc_N",
                                           "quadmc_evaluations",
                                           "peer_method",
                                           "peer_N",
                                           "peer_evaluations",
                                           "rounds",
                                           "ratio_median",
                                           "ratio_min",
                                           "ratio_max",
                                           "quadmc_seconds_median",
                                           "peer_seconds_median",
                                           "ratios",
                                           "quadmc_seconds",
                                           "peer_seconds"};
  EXPECT_EQ(csv.header, header);
  ASSERT_EQ(csv.rows.size(), 1u);
  auto field = [&](std::string_view column) { return csv.rows[0][csv.column(column)]; };
  EXPECT_EQ(field("scene"), "unit");
  EXPECT_EQ(field("family"), "genz_x");
  EXPECT_EQ(field("integrand"), "genz_x_s2");
  EXPECT_EQ(field("s"), "2");
  EXPECT_EQ(field("tolerance"), "0.001");
  EXPECT_EQ(field("tolerance_kind"), "relative");
  EXPECT_EQ(field("quadmc_method"), "genz_malik");
  EXPECT_EQ(field("quadmc_N"), "0");
  EXPECT_EQ(field("quadmc_evaluations"), "100");
  EXPECT_EQ(field("peer_method"), "peer_hcubature");
  EXPECT_EQ(field("rounds"), "5");
  EXPECT_EQ(field("ratio_median"), "1.5");
  EXPECT_EQ(field("ratio_min"), "1");
  EXPECT_EQ(field("ratio_max"), "2");
  EXPECT_EQ(field("quadmc_seconds_median"), "3");
  EXPECT_EQ(field("peer_seconds_median"), "2");
  // Per round, in the order timed.
  EXPECT_EQ(field("ratios"), "1.5;1;2;1.5;1.5");
  EXPECT_EQ(field("quadmc_seconds"), "3;2;4;3;3");
  EXPECT_EQ(field("peer_seconds"), "2;2;2;2;2");
  // No pairs: the header alone.
  EXPECT_EQ(parse_csv(time_to_error_pairs_csv_text("unit", {}), "empty").rows.size(), 0u);
}

TEST(TimeToErrorTable, NoTableWithoutPeersOrWithoutTolerances) {
  std::vector<convergence_table> tables = time_to_error_sample_tables();
  // Without the peer: nothing to compare with.
  std::vector<convergence_table> own{tables[0], tables[2]};
  EXPECT_EQ(render_results_markdown(run_info{}, own).find("## Time to error"), std::string::npos);
  // Without a method run to a tolerance: no targets.
  std::vector<convergence_table> ladder_only{tables[2]};
  ladder_only[0].method = "peer_gsl_plain";
  ladder_only.push_back(tables[2]);
  EXPECT_TRUE(time_to_error_markdown(ladder_only).empty());
}

}  // namespace
}  // namespace quadmc
