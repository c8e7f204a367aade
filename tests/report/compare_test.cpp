// Tests for compare.hpp: an identical pair passes, a shallower slope is a regression, noise
// within the intervals is not.
#include "quadmc/report/compare.hpp"

#include "../analysis/series_builder.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/report/results_folder.hpp"
#include "support/floating_point.hpp"
#include "support/temporary_directory.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace quadmc {
namespace {

using test::cell_at;
using test::monte_carlo_theory;
using test::repetition;
using test::rule_theory;
using test::series_of;

namespace fs = std::filesystem;
using test_support::nan;

using test_support::temporary_directory;

// A midpoint series with error c·N^rate (exact power law: CI half-width ~0) and time 1e-8·N,
// plus a Monte Carlo series with rate −1/2.
void write_folder(const fs::path& folder, double midpoint_rate, double time_factor) {
  convergence_series rule = series_of("genz_gaussian", 1, "midpoint", smoothness::analytic, 1.0,
                                      rule_theory(2, smoothness::analytic));
  convergence_series mc = series_of("genz_gaussian", 1, "plain_mc", smoothness::analytic, 1.0,
                                    monte_carlo_theory(smoothness::analytic));
  for (int k = 2; k <= 12; ++k) {
    const double n = std::ldexp(1.0, k);
    const auto nk = static_cast<std::uint64_t>(n);
    rule.cells.push_back(cell_at(
        nk, {repetition(1.0 + 0.1 * std::pow(n, midpoint_rate), nan, nk, time_factor * 1e-8 * n)}));
    mc.cells.push_back(
        cell_at(nk, {repetition(1.0 + 0.5 / std::sqrt(n), 0.5 / std::sqrt(n), nk, 1e-7 * n)}));
  }
  const std::vector<convergence_table> tables = {analyse_convergence(rule),
                                                 analyse_convergence(mc)};
  run_info info;
  info.scene = "compare_test";
  write_results_folder(folder, info, tables);
}

TEST(Compare, IdenticalFoldersPass) {
  const temporary_directory dir{"quadmc_compare"};
  write_folder(dir.path / "a", -2.0, 1.0);
  write_folder(dir.path / "b", -2.0, 1.0);
  const compare_result r = compare_results(dir.path / "a", dir.path / "b", 0.1);
  EXPECT_FALSE(r.regression);
  EXPECT_EQ(r.regressions, 0u);
  EXPECT_EQ(r.outcome, compare_outcome::no_regression);
  EXPECT_EQ(r.compared, 2u);
  ASSERT_EQ(r.slopes.size(), 2u);
  for (const slope_comparison& c : r.slopes) EXPECT_EQ(c.status, "ok") << c.method;
  ASSERT_EQ(r.errors.size(), 22u);
  for (const error_comparison& e : r.errors) EXPECT_EQ(e.ratio, 1.0) << e.method << " N=" << e.n;
  // Targets 1e-2 … 1e-8 reached: midpoint 0.1·N⁻² spans 6e-3 … 6e-9 (all 7), plain MC 0.5/√N
  // spans 0.25 … 7.8e-3 (1e-2 only). Counting them keeps the loop from asserting nothing.
  std::size_t timed = 0;
  for (const time_comparison& t : r.times) {
    if (t.ratio) {
      EXPECT_NEAR(*t.ratio, 1.0, 1e-12) << t.method << " " << t.target;
      ++timed;
    }
  }
  EXPECT_EQ(timed, 8u);
  const std::string md = render_compare_markdown(r);
  EXPECT_NE(md.find("No slope regression"), std::string::npos);
}

TEST(Compare, ShallowerSlopeIsARegression) {
  const temporary_directory dir{"quadmc_compare"};
  write_folder(dir.path / "a", -2.0, 1.0);
  write_folder(dir.path / "b", -1.5, 2.0);  // midpoint got shallower (−2 → −1.5) and slower
  const compare_result r = compare_results(dir.path / "a", dir.path / "b", 0.1);
  EXPECT_TRUE(r.regression);
  EXPECT_EQ(r.regressions, 1u);
  const slope_comparison& mid = r.slopes[0];
  EXPECT_EQ(mid.method, "midpoint");
  EXPECT_TRUE(mid.regression);
  EXPECT_NEAR(*mid.slope_b - *mid.slope_a, 0.5, 1e-9);
  EXPECT_DOUBLE_EQ(mid.allowed, 0.1) << "exact power laws: CI half-widths ~0, tolerance rules";
  EXPECT_FALSE(r.slopes[1].regression) << "plain_mc unchanged";
  // The error ratio at N = 2^12: (2^12)^(−1.5)/(2^12)^(−2) = 2^6 = 64. Each error is read off
  // 1 + e, rounded to ε/2 absolute, so the ratio carries a relative error ≤ ε/e_A with
  // e_A = 0.1·2^−24.
  bool found = false;
  for (const error_comparison& e : r.errors) {
    if (e.method == "midpoint" && e.n == 4096) {
      const double e_a = 0.1 * std::ldexp(1.0, -24);
      EXPECT_NEAR(e.ratio, 64.0, 64.0 * std::numeric_limits<double>::epsilon() / e_a);
      found = true;
    }
  }
  EXPECT_TRUE(found);
  const std::string md = render_compare_markdown(r);
  EXPECT_NE(md.find("**REGRESSION**"), std::string::npos) << md;
  // Reversing the roles is an improvement, not a regression.
  const compare_result back = compare_results(dir.path / "b", dir.path / "a", 0.1);
  EXPECT_FALSE(back.regression);
  EXPECT_EQ(back.slopes[0].status, "steeper in B");
}

// A midpoint series on a step with envelope 0.5/N and |error| = scale·N^rate: an envelope series.
void write_jump_folder(const fs::path& folder, double rate, double scale) {
  convergence_series rule = series_of("step", 1, "midpoint", smoothness::discontinuous, 0.25,
                                      rule_theory(2, smoothness::discontinuous));
  for (int k = 2; k <= 12; ++k) {
    const double n = std::ldexp(1.0, k);
    const auto nk = static_cast<std::uint64_t>(n);
    rule.cells.push_back(cell_at(
        nk, {repetition(0.25 + scale * std::pow(n, rate), nan, nk, 1e-8 * n)}, nk, 0.5 / n));
  }
  run_info info;
  info.scene = "compare_test";
  const std::vector<convergence_table> tables = {analyse_convergence(rule)};
  write_results_folder(folder, info, tables);
}

TEST(Compare, EnvelopeSeriesAreJudgedByTheirVerdict) {
  const temporary_directory dir{"quadmc_compare"};
  write_jump_folder(dir.path / "a", -1.0, 0.3);      // under 0.5/N: within
  write_jump_folder(dir.path / "flat", 0.0, 1e-4);   // slope 0, still under 0.5/N up to 2^12
  write_jump_folder(dir.path / "above", -1.0, 0.6);  // 0.6/N > 0.5/N: above the envelope
  // A flat ladder under its envelope: the slope moved by 1, which is not a rate lost.
  const compare_result flat = compare_results(dir.path / "a", dir.path / "flat", 0.1);
  EXPECT_FALSE(flat.regression);
  ASSERT_EQ(flat.slopes.size(), 1u);
  EXPECT_EQ(flat.slopes[0].status, "slope moved, within envelope in B");
  // An error above the a-priori bound is a regression, though the slope is unchanged.
  const compare_result above = compare_results(dir.path / "a", dir.path / "above", 0.1);
  EXPECT_TRUE(above.regression);
  EXPECT_EQ(above.regressions, 1u);
  EXPECT_EQ(above.slopes[0].status, "above envelope in B");
  EXPECT_NE(render_compare_markdown(above).find("above their error envelope"), std::string::npos);
  // And back: B within again is no regression.
  EXPECT_FALSE(compare_results(dir.path / "above", dir.path / "a", 0.1).regression);
}

TEST(Compare, SmallSlopeChangeWithinToleranceAndMissingSeries) {
  const temporary_directory dir{"quadmc_compare"};
  write_folder(dir.path / "a", -2.0, 1.0);
  write_folder(dir.path / "b", -1.95, 1.0);  // 0.05 shallower: within the 0.1 tolerance
  EXPECT_FALSE(compare_results(dir.path / "a", dir.path / "b", 0.1).regression);
  EXPECT_TRUE(compare_results(dir.path / "a", dir.path / "b", 0.01).regression);
  EXPECT_THROW(compare_results(dir.path / "a", dir.path / "missing", 0.1), invalid_argument);
  EXPECT_THROW(compare_results(dir.path / "a", dir.path / "b", -1.0), invalid_argument);
}

// A power-law series c·N^rate on N = 2^2…2^points+1 (fewer than three points: no fit).
convergence_series power_series(const std::string& integrand, const std::string& method,
                                double rate, int points) {
  convergence_series s = series_of(integrand, 1, method, smoothness::analytic, 1.0,
                                   rule_theory(2, smoothness::analytic));
  for (int k = 2; k < 2 + points; ++k) {
    const double n = std::ldexp(1.0, k);
    const auto nk = static_cast<std::uint64_t>(n);
    s.cells.push_back(cell_at(nk, {repetition(1.0 + 0.1 * std::pow(n, rate), nan, nk, 1e-8 * n)}));
  }
  return s;
}

void write_series(const fs::path& folder, const std::vector<convergence_series>& series) {
  std::vector<convergence_table> tables;
  for (const auto& s : series) tables.push_back(analyse_convergence(s));
  run_info info;
  info.scene = "compare_test";
  write_results_folder(folder, info, tables);
}

TEST(Compare, NothingToCompareIsIncomparableNotAPass) {
  // Regression: an empty B, another scene, or B without the fits A had gave "no regression",
  // a silent pass of the CI gate.
  const temporary_directory dir{"quadmc_compare"};
  const auto mid = power_series("f", "midpoint", -2.0, 8);
  const auto simpson = power_series("f", "simpson", -4.0, 8);
  write_series(dir.path / "a", {mid, simpson});

  write_series(dir.path / "empty", {});  // both CSV files with their header only
  const compare_result empty = compare_results(dir.path / "a", dir.path / "empty");
  EXPECT_EQ(empty.outcome, compare_outcome::incomparable);
  EXPECT_FALSE(empty.regression);
  EXPECT_EQ(empty.missing_in_b, 2u);
  EXPECT_EQ(empty.compared, 0u);
  EXPECT_EQ(empty.reason,
            "2 series of A missing in B (first: f (s = 1) midpoint); no series is fitted in both A "
            "and B");
  EXPECT_NE(render_compare_markdown(empty).find("**INCOMPARABLE**: 2 series of A missing"),
            std::string::npos);
  EXPECT_EQ(render_compare_markdown(empty).find("No slope regression"), std::string::npos);

  write_series(dir.path / "other", {power_series("g", "midpoint", -2.0, 8)});
  const compare_result other = compare_results(dir.path / "a", dir.path / "other");
  EXPECT_EQ(other.outcome, compare_outcome::incomparable);
  EXPECT_EQ(other.compared, 0u);

  // Simpson with two points in B: no fit (a NaN slope in slopes.csv) where A had one.
  write_series(dir.path / "lost", {mid, power_series("f", "simpson", -4.0, 2)});
  const compare_result lost = compare_results(dir.path / "a", dir.path / "lost");
  EXPECT_EQ(lost.outcome, compare_outcome::incomparable);
  EXPECT_EQ(lost.lost_fits, 1u);
  EXPECT_EQ(lost.compared, 1u);
  EXPECT_EQ(lost.reason, "1 series fitted in A without a fit in B (first: f (s = 1) simpson)");

  write_series(dir.path / "half", {mid});
  const compare_result half = compare_results(dir.path / "a", dir.path / "half");
  EXPECT_EQ(half.outcome, compare_outcome::incomparable);
  EXPECT_EQ(half.missing_in_b, 1u);
}

TEST(Compare, NewSeriesInBAndFitsNewInBAreFine) {
  const temporary_directory dir{"quadmc_compare"};
  const auto mid = power_series("f", "midpoint", -2.0, 8);
  write_series(dir.path / "a", {mid, power_series("f", "simpson", -4.0, 2)});  // simpson: no fit
  write_series(dir.path / "b", {mid, power_series("f", "simpson", -4.0, 8),
                                power_series("f", "trapezoid", -2.0, 8)});
  const compare_result r = compare_results(dir.path / "a", dir.path / "b");
  EXPECT_EQ(r.outcome, compare_outcome::no_regression);
  EXPECT_EQ(r.reason, "");
  EXPECT_EQ(r.compared, 1u);
  EXPECT_EQ(r.missing_in_b + r.lost_fits, 0u);
}

TEST(Compare, ARegressionOutranksIncomparabilityAndTheReasonNamesBoth) {
  const temporary_directory dir{"quadmc_compare"};
  write_series(dir.path / "a",
               {power_series("f", "midpoint", -2.0, 8), power_series("f", "simpson", -4.0, 8)});
  write_series(dir.path / "b", {power_series("f", "midpoint", -1.0, 8)});
  const compare_result r = compare_results(dir.path / "a", dir.path / "b");
  EXPECT_EQ(r.outcome, compare_outcome::regression);
  EXPECT_EQ(r.reason,
            "1 regression (first: f (s = 1) midpoint); 1 series of A missing in B (first: f "
            "(s = 1) simpson)");
}

}  // namespace
}  // namespace quadmc
