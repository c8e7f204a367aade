// Tests for estimate_reliability.hpp on hand-made series whose coverage is counted by hand.
#include "quadmc/analysis/estimate_reliability.hpp"

#include "series_builder.hpp"
#include "support/floating_point.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace quadmc {
namespace {

using test::cell_at;
using test::monte_carlo_theory;
using test::repetition;
using test::series_of;

using test_support::nan;

// Cells at N = 4^k of R repetitions with errors `errors[r]`·ê and the estimate ê = 1/N.
convergence_series with_estimates(std::string integrand, std::string method, smoothness cls,
                                  const std::vector<double>& errors, double chi2 = nan) {
  convergence_series s =
      series_of(std::move(integrand), 2, std::move(method), cls, 1.0, monte_carlo_theory(cls, 2));
  for (int k = 2; k <= 4; ++k) {
    const auto n = std::uint64_t{1} << (2 * k);
    const double estimate = 1.0 / static_cast<double>(n);
    std::vector<repetition_result> reps;
    for (double e : errors) {
      repetition_result r = repetition(1.0 + e * estimate, estimate, n, 1e-6);
      r.error_estimate = estimate;
      r.chi2_per_dof = chi2;
      r.q_value = std::isnan(chi2) ? nan : 0.5;
      reps.push_back(r);
    }
    s.cells.push_back(cell_at(n, std::move(reps)));
  }
  return s;
}

TEST(EstimateReliability, PoolsRepetitionsPerMethodAndClass) {
  // vegas on two analytic integrands: 3 cells × 4 repetitions each; errors 0.5ê, −2ê, 0.25ê, 4ê
  // in the first (2 of 4 within ê, 3 within 3ê) and 0.1ê, 0.2ê in the second (all within ê).
  // vegas on a discontinuous one is its own entry; a rule without estimates does not appear.
  std::vector<convergence_table> tables = {
      analyse_convergence(
          with_estimates("f", "vegas", smoothness::analytic, {0.5, -2, 0.25, 4}, 1.25)),
      analyse_convergence(
          with_estimates("g", "vegas", smoothness::analytic, {0.1, 0.2, -0.1, 0.3}, 0.75)),
      analyse_convergence(with_estimates("d", "vegas", smoothness::discontinuous, {5, 6, 7, 8})),
  };
  convergence_series rule = series_of("f", 2, "simpson", smoothness::analytic, 1.0,
                                      monte_carlo_theory(smoothness::analytic, 2));
  for (std::uint64_t n : {9u, 25u, 81u}) {
    rule.cells.push_back(cell_at(n, {repetition(1.0 + 1.0 / static_cast<double>(n), nan, n, 0)}));
  }
  tables.push_back(analyse_convergence(rule));

  const std::vector<estimate_reliability> r = summarise_estimate_reliability(tables);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].method, "vegas");
  EXPECT_EQ(r[0].regularity, smoothness::analytic);
  EXPECT_EQ(r[0].series, 2u);
  EXPECT_EQ(r[0].cells, 6u);
  EXPECT_EQ(r[0].estimates, 24u);
  EXPECT_DOUBLE_EQ(r[0].covered, (3 * 2 + 3 * 4) / 24.0);
  EXPECT_DOUBLE_EQ(r[0].covered_3x, (3 * 3 + 3 * 4) / 24.0);
  EXPECT_DOUBLE_EQ(r[0].chi2_per_dof, 1.0);  // mean of 1.25 over 3 cells and 0.75 over 3
  // RMSE/ê of the first series: √((0.25 + 4 + 0.0625 + 16)/4) = √5.078125.
  EXPECT_NEAR(r[0].worst_ratio, std::sqrt(5.078125), 1e-12);

  EXPECT_EQ(r[1].regularity, smoothness::discontinuous);
  EXPECT_EQ(r[1].covered, 0.0);
  EXPECT_EQ(r[1].covered_3x, 0.0);
  EXPECT_TRUE(std::isnan(r[1].chi2_per_dof));
}

TEST(EstimateReliability, NothingWithoutEstimates) {
  convergence_series rule = series_of("f", 1, "midpoint", smoothness::analytic, 1.0,
                                      monte_carlo_theory(smoothness::analytic));
  for (std::uint64_t n : {4u, 8u, 16u}) {
    rule.cells.push_back(cell_at(n, {repetition(1.0 + 1.0 / static_cast<double>(n), nan, n, 0)}));
  }
  const std::vector<convergence_table> tables = {analyse_convergence(rule)};
  EXPECT_TRUE(summarise_estimate_reliability(tables).empty());
}

}  // namespace
}  // namespace quadmc
