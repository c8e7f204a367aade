// Tests for time_to_error_table.hpp: what each method needs to reach a tolerance (true error, not
// its own claim; the smallest ladder N by RMSE), quadmc's best against the best peer, the summary,
// and no table for a scene without peers or tolerances.
#include "quadmc/report/time_to_error_table.hpp"

#include "../analysis/series_builder.hpp"
#include "quadmc/report/markdown_report.hpp"
#include "support/floating_point.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace quadmc {
namespace {

using test::cell_at;
using test::monte_carlo_theory;
using test::repetition;
using test::rule_theory;
using test::series_of;

using test_support::nan;
constexpr double reference = 2.0;  // relative tolerances 1e-3, 1e-6 are errors 2e-3, 2e-6

cell_timing timed(double seconds) {
  cell_timing t;
  t.seconds_per_estimate = seconds;
  t.spread = 0.1;
  t.estimates = 100;
  return t;
}

// A method run to the relative tolerances 1e-3 and 1e-6: its true error, evaluations and stable
// time at each (its own estimate claims the tolerance every time).
convergence_table to_tolerance(const std::string& method, double error3, double seconds3,
                               double error6, double seconds6) {
  convergence_series series = series_of("genz_x_s2", 2, method, smoothness::analytic, reference,
                                        rule_theory(2, smoothness::analytic, 2));
  series.relative_tolerance = true;
  const double tolerances[] = {1e-3, 1e-6};
  const double errors[] = {error3, error6};
  const double seconds[] = {seconds3, seconds6};
  const std::uint64_t evaluations[] = {100, 1000};
  for (int k = 0; k < 2; ++k) {
    repetition_result r = repetition(reference + errors[k], nan, evaluations[k], seconds[k]);
    r.error_estimate = tolerances[k] * reference;
    convergence_cell cell = cell_at(0, {r});
    cell.tolerance = tolerances[k];
    cell.timing = timed(seconds[k]);
    series.cells.push_back(cell);
  }
  return analyse_convergence(series);
}

std::vector<convergence_table> time_to_error_sample_tables() {
  std::vector<convergence_table> tables;
  // Meets 1e-3 (error 1e-3 ≤ 2e-3) in 1e-5 s; misses 1e-6 (error 1e-5 > 2e-6).
  tables.push_back(to_tolerance("genz_malik", 1e-3, 1e-5, 1e-5, 4e-5));
  // Meets both: 2e-5 s and 1e-4 s.
  tables.push_back(to_tolerance("peer_hcubature", 5e-4, 2e-5, 1e-6, 1e-4));
  // A Monte Carlo ladder: RMSE 1e-2 at N = 64, 1.5e-3 at 256 (≤ 2e-3: reached there, in 3e-5 s),
  // 1e-3 at 1024; never 2e-6.
  convergence_series mc = series_of("genz_x_s2", 2, "plain_mc", smoothness::analytic, reference,
                                    monte_carlo_theory(smoothness::analytic, 2));
  const std::uint64_t ns[] = {64, 256, 1024};
  const double rmse[] = {1e-2, 1.5e-3, 1e-3};
  const double seconds[] = {1e-6, 3e-5, 9e-5};
  for (int k = 0; k < 3; ++k) {
    // Two repetitions ±e: RMSE e.
    convergence_cell cell = cell_at(ns[k], {repetition(reference + rmse[k], rmse[k], ns[k], 1e-9),
                                            repetition(reference - rmse[k], rmse[k], ns[k], 1e-9)});
    cell.timing = timed(seconds[k]);
    mc.cells.push_back(cell);
  }
  tables.push_back(analyse_convergence(mc));
  return tables;
}

TEST(TimeToErrorTable, EachMethodsTimeAndEvaluationsToTheTarget) {
  const std::vector<convergence_table> tables = time_to_error_sample_tables();
  const std::vector<time_to_error_cell> cells = time_to_error_cells(tables);
  ASSERT_EQ(cells.size(), 2u);
  const time_to_error_cell& loose = cells[0];
  EXPECT_EQ(loose.family, "genz_x");
  EXPECT_EQ(loose.s, 2u);
  EXPECT_EQ(loose.tolerance, 1e-3);
  EXPECT_TRUE(loose.relative);
  EXPECT_EQ(loose.target, 1e-3 * reference);
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
  ASSERT_TRUE(loose.best_quadmc && loose.best_peer);
  EXPECT_EQ(*loose.best_quadmc, 0u);  // genz_malik's 1e-5 s beats plain_mc's 3e-5 s
  EXPECT_EQ(*loose.best_peer, 1u);
  EXPECT_EQ(loose.ratio, 1e-5 / 2e-5);

  // At 1e-6 genz_malik's estimate claimed the target but its true error 1e-5 is above 2e-6: not
  // reached; the ladder never gets there; the peer does, so quadmc's ratio is infinite.
  const time_to_error_cell& tight = cells[1];
  EXPECT_EQ(tight.tolerance, 1e-6);
  EXPECT_TRUE(tight.methods[0].ran);
  EXPECT_FALSE(tight.methods[0].reached);
  EXPECT_FALSE(tight.methods[2].reached);
  EXPECT_FALSE(tight.best_quadmc.has_value());
  ASSERT_TRUE(tight.best_peer.has_value());
  EXPECT_EQ(tight.methods[*tight.best_peer].seconds, 1e-4);
  EXPECT_TRUE(std::isinf(tight.ratio));

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
}

TEST(TimeToErrorTable, NoTableWithoutPeersOrWithoutTolerances) {
  std::vector<convergence_table> tables = time_to_error_sample_tables();
  // Without the peer: nothing to compare with.
  std::vector<convergence_table> own{tables[0], tables[2]};
  EXPECT_TRUE(time_to_error_cells(own).empty());
  EXPECT_EQ(render_results_markdown(run_info{}, own).find("## Time to error"), std::string::npos);
  // Without a method run to a tolerance: no targets.
  std::vector<convergence_table> ladder_only{tables[2]};
  ladder_only[0].method = "peer_gsl_plain";
  ladder_only.push_back(tables[2]);
  EXPECT_TRUE(time_to_error_cells(ladder_only).empty());
  EXPECT_TRUE(time_to_error_markdown(ladder_only).empty());
}

TEST(TimeToErrorTable, PeerMethodsAreNamedPeer) {
  EXPECT_TRUE(is_peer_method("peer_hcubature"));
  EXPECT_FALSE(is_peer_method("genz_malik"));
  EXPECT_FALSE(is_peer_method("my_peer_hcubature"));
}

}  // namespace
}  // namespace quadmc
