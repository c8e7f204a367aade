// Tests for convergence_table.hpp: a whole series from repetitions to verdict.
#include "quadmc/analysis/convergence_table.hpp"

#include "quadmc/core/errors.hpp"

#include "series_builder.hpp"
#include "support/floating_point.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace quadmc {
namespace {

using test::cell_at;
using test::repetition;
using test::series_of;

using test_support::nan;

// A deterministic midpoint-like series: value = I + 0.1·N⁻² + a rounding floor of 4e-16 that
// alternates in sign, N = 2^1 … 2^28, cells given in reverse order to check the sort.
convergence_series midpoint_series() {
  convergence_series series = series_of("genz_gaussian", 1, "midpoint", smoothness::analytic, 0.5,
                                        composite_rule_rate(2, {smoothness::analytic, 1}));
  for (int k = 28; k >= 1; --k) {
    const double n = std::ldexp(1.0, k);
    const double value = 0.5 + 0.1 / (n * n) + (k % 2 == 0 ? 4e-16 : -4e-16);
    const auto count = static_cast<std::uint64_t>(n);
    series.cells.push_back(cell_at(count, {repetition(value, nan, count, 1e-9 * n)}));
  }
  return series;
}

TEST(ConvergenceTable, DeterministicSeriesWithFloor) {
  const convergence_table table = analyse_convergence(midpoint_series());
  ASSERT_EQ(table.rows.size(), 28u);
  for (std::size_t k = 1; k < table.rows.size(); ++k) {
    EXPECT_GT(table.rows[k].n, table.rows[k - 1].n) << "rows sorted by N";
  }
  EXPECT_TRUE(table.floor.reached());
  EXPECT_GT(table.floor_points(), 0u);
  EXPECT_TRUE(table.rows.back().floor);
  EXPECT_FALSE(table.rows.front().floor);
  EXPECT_EQ(table.points_used() + table.floor_points(), table.rows.size());
  ASSERT_TRUE(table.fit.ok());
  // The fitted errors are 0.1·N⁻² perturbed by the ±4e-16 floor term and the rounding of
  // 0.5 + … and of value − 0.5 (≤ 2 ulp of 0.5 = 2.2e-16): relative δ_k ≤ 6.2e-16·N²/0.1. The OLS
  // slope moves by at most Σ_k |w_k|·|ln(1 − δ_k)|, w_k = (x_k − x̄)/Sxx over the fitted x = ln N.
  // Fitting one floor point too many (δ ≈ 1) or one clean point too few changes it far more.
  std::vector<double> x;
  for (const convergence_row& row : table.rows) {
    if (!row.floor) x.push_back(std::log(static_cast<double>(row.n)));
  }
  ASSERT_EQ(x.size(), table.points_used());
  double mean = 0.0, sxx = 0.0, tolerance = 0.0;
  for (double v : x) mean += v / static_cast<double>(x.size());
  for (double v : x) sxx += (v - mean) * (v - mean);
  for (double v : x) {
    const double delta = 6.2e-16 * std::exp(2.0 * v) / 0.1;
    ASSERT_LT(delta, 0.5) << "a fitted point at N = " << std::exp(v) << " is floor-dominated";
    tolerance += std::abs(v - mean) / sxx * -std::log(1.0 - delta);
  }
  EXPECT_NEAR(table.fit.slope, -2.0, tolerance);
  ASSERT_TRUE(table.theory.slope.has_value());
  EXPECT_EQ(*table.theory.slope, -2.0);
  EXPECT_EQ(table.verdict, slope_verdict::agrees);
  // Time per repetition 1e-9·N; error 0.1·N⁻² reaches 1e-2 at N = √10: between the first two
  // points (N = 2: 2.5e-2; N = 4: 6.25e-3), so the target is reached by interpolation.
  ASSERT_EQ(table.work_precision.size(), 7u);
  EXPECT_EQ(table.work_precision[0].status, target_status::reached);
  // t ∝ N and e ∝ N⁻² between the points: t(1e-2) = 1e-9·√10 exactly under the log-log model.
  EXPECT_NEAR(*table.work_precision[0].seconds, 1e-9 * std::sqrt(10.0), 1e-20);
}

// A reference known to ± u: errors below 10u are floor points, never fitted
// (docs/theory.md#references-without-a-closed-form). The midpoint series' errors are 0.1·N⁻²
// (plus ≤ 6.2e-16 of rounding, see above), so with u = 1e-9 the first below 10u = 1e-8 is at
// N = 4096 (0.1/4096² = 6.0e-9; N = 2048 gives 2.4e-8): rows 0…10 (N = 2 … 2048) are fitted and
// the 17 from N = 4096 on are floor points, long before the rounding floor (≈ N = 2^23).
TEST(ConvergenceTable, ErrorsBelowTenTimesTheReferenceUncertaintyAreNotFitted) {
  convergence_series series = midpoint_series();
  series.reference_uncertainty = 1e-9;
  const convergence_table table = analyse_convergence(series);
  ASSERT_EQ(table.rows.size(), 28u);
  EXPECT_EQ(table.reference_uncertainty, 1e-9);
  ASSERT_TRUE(table.floor.first.has_value());
  EXPECT_EQ(*table.floor.first, 11u);
  ASSERT_TRUE(table.floor.reference_first.has_value());
  EXPECT_EQ(*table.floor.reference_first, 11u);
  for (const convergence_row& row : table.rows) {
    EXPECT_EQ(row.floor, row.stats.rmse < 1e-8) << "N = " << row.n << ", error " << row.stats.rmse;
  }
  EXPECT_EQ(table.points_used(), 11u);
  EXPECT_EQ(table.floor_points(), 17u);
  // The fitted errors are 0.1·N⁻²·(1 + δ), |δ| ≤ 6.2e-16·2048²/0.1 = 2.6e-8 at the largest fitted
  // N, so the OLS slope is within Σ|w_k|·|δ_k| < 1e-7 of −2 (Σ|w_k| < 1 over ln 2 … ln 2048).
  ASSERT_TRUE(table.fit.ok());
  EXPECT_NEAR(table.fit.slope, -2.0, 1e-7);
  // The attainable accuracy is the smallest fitted error: 0.1/2048².
  EXPECT_NEAR(table.floor.attainable_accuracy, 0.1 / (2048.0 * 2048.0), 1e-15);
}

TEST(ConvergenceTable, ReferenceUncertaintyZeroChangesNothing) {
  const convergence_table plain = analyse_convergence(midpoint_series());
  convergence_series series = midpoint_series();
  series.reference_uncertainty = 0.0;
  const convergence_table table = analyse_convergence(series);
  EXPECT_EQ(table.floor.first, plain.floor.first);
  EXPECT_FALSE(table.floor.reference_first.has_value());
  EXPECT_EQ(table.fit.slope, plain.fit.slope);
  EXPECT_EQ(table.verdict_reason, plain.verdict_reason);
}

TEST(ConvergenceTable, ALadderBelowTheReferenceFloorIsAtFloorAndSaysWhy) {
  convergence_series series = midpoint_series();
  series.reference_uncertainty = 1.0;  // 10u = 10 is above every error (≤ 0.025)
  const convergence_table table = analyse_convergence(series);
  EXPECT_EQ(table.points_used(), 0u);
  EXPECT_EQ(table.floor_points(), table.rows.size());
  EXPECT_EQ(table.verdict, slope_verdict::at_floor);
  EXPECT_NE(table.verdict_reason.find("the reference's floor"), std::string::npos)
      << table.verdict_reason;
}

// A sparse-grid-like ladder: errors fall as N^-3 to 2e-12 (relative to I = 1) and stay there,
// the level a rule with Σ|w| = 2000 reaches by rounding (2ε·2000·log₂N ≈ 1.8e-11 at N = 2^20).
// Without Σ|w| the floor rule sees errors far above 2ε·log₂N and no stall within 10⁴ of it …
// with it, the flat points are at the floor and are kept out of the fit.
TEST(ConvergenceTable, FloorScalesWithTheAbsoluteWeightSumARuleReports) {
  auto ladder = [](double weight_sum) {
    convergence_series series = series_of("g", 8, "smolyak", smoothness::analytic, 1.0,
                                          sparse_grid_rate({smoothness::analytic, 8}));
    for (int k = 10; k <= 20; k += 2) {
      const auto n = std::uint64_t{1} << k;
      const double error = std::max(std::pow(static_cast<double>(n), -3.0) * 1e6, 2e-12);
      repetition_result r = repetition(1.0 + error, nan, n, 1e-6);
      r.absolute_weight_sum = weight_sum;
      series.cells.push_back(cell_at(n, {r}));
    }
    return analyse_convergence(series);
  };
  const convergence_table unscaled = ladder(nan);
  const convergence_table scaled = ladder(2000.0);
  EXPECT_FALSE(unscaled.floor.reached());
  ASSERT_TRUE(scaled.floor.reached());
  EXPECT_TRUE(scaled.rows.back().floor);
  EXPECT_FALSE(scaled.rows.front().floor);
  EXPECT_EQ(scaled.rows.back().stats.absolute_weight_sum, 2000.0);
}

TEST(ConvergenceTable, MonteCarloSeriesUsesRmseAndCoverage) {
  // Four repetitions per N with errors ±c/√N (two each sign) and std_error c/√N: RMSE = c/√N
  // exactly, coverage 1 (|e| = se ≤ 1.96·se), slope −1/2 exactly.
  convergence_series series =
      series_of("genz_oscillatory", 2, "plain_mc", smoothness::analytic, 1.0,
                root_n_rate({smoothness::analytic, 2}, "σ/√N", "docs/theory.md#plain-monte-carlo"));
  for (int k = 4; k <= 12; ++k) {
    const double n = std::ldexp(1.0, k);
    const double se = 0.3 / std::sqrt(n);
    convergence_cell cell = cell_at(static_cast<std::uint64_t>(n), {});
    for (double sign : {1.0, -1.0, 1.0, -1.0}) {
      cell.repetitions.push_back(
          repetition(1.0 + sign * se, se, static_cast<std::uint64_t>(n), 1e-6));
    }
    series.cells.push_back(cell);
  }
  const convergence_table table = analyse_convergence(series);
  EXPECT_FALSE(table.floor.reached());
  EXPECT_NEAR(table.fit.slope, -0.5, 1e-6);
  EXPECT_EQ(table.verdict, slope_verdict::agrees);
  for (const convergence_row& row : table.rows) {
    EXPECT_EQ(row.stats.repetitions, 4u);
    EXPECT_DOUBLE_EQ(row.stats.coverage_95, 1.0) << "N = " << row.n;
  }
}

// Four repetitions per N with errors ±e(N) (two each sign): RMSE = e(N) exactly.
convergence_series scrambled_net_series(std::size_t s, double (*error)(double)) {
  convergence_series series = series_of("genz_gaussian", s, "sobol", smoothness::analytic, 1.0,
                                        scrambled_net_rate({smoothness::analytic, s}));
  for (int k = 10; k <= 20; k += 2) {
    const double n = std::ldexp(1.0, k);
    convergence_cell cell = cell_at(static_cast<std::uint64_t>(n), {});
    for (double sign : {1.0, -1.0, 1.0, -1.0}) {
      cell.repetitions.push_back(
          repetition(1.0 + sign * error(n), nan, static_cast<std::uint64_t>(n), 1e-6));
    }
    series.cells.push_back(cell);
  }
  return series;
}

TEST(ConvergenceTable, AScrambledNetsLogFactorIsAComputedReason) {
  // s = 16: the bound N^−3/2·(log N)^7.5 falls with the local slope
  // −1.5 + 7.5·ln(20/10)/(10·ln 2) = −0.75 over N = 2^10 … 2^20. A ladder that follows the bound
  // fits that slope, not −1.5: pre_asymptotic, with the local slope in the reason.
  const auto bound = [](double n) { return 1e-2 * std::pow(n, -1.5) * std::pow(std::log(n), 7.5); };
  const convergence_table table = analyse_convergence(scrambled_net_series(16, bound));
  EXPECT_NEAR(table.fit.slope, -0.75, 0.02);
  EXPECT_EQ(table.verdict, slope_verdict::pre_asymptotic) << table.verdict_reason;
  EXPECT_NE(table.verdict_reason.find("local slope -0.750"), std::string::npos)
      << table.verdict_reason;
  // A log factor of a lower power, (log N)^3, gives a slope between −1.5 and the bound's −0.75:
  // −1.5 + 3·ln 2/(10 ln 2) = −1.2, within what the bound allows.
  const auto milder = [](double n) {
    return 1e-2 * std::pow(n, -1.5) * std::pow(std::log(n), 3.0);
  };
  const convergence_table between = analyse_convergence(scrambled_net_series(16, milder));
  EXPECT_NEAR(between.fit.slope, -1.2, 0.02);
  EXPECT_EQ(between.verdict, slope_verdict::pre_asymptotic) << between.verdict_reason;
  EXPECT_NE(between.verdict_reason.find("lies between it and -1.5"), std::string::npos)
      << between.verdict_reason;
  // Steeper than −1.5 is no log factor's doing either: a finding.
  const auto fast = [](double n) { return 1e-2 * std::pow(n, -2.0); };
  EXPECT_EQ(analyse_convergence(scrambled_net_series(16, fast)).verdict, slope_verdict::steeper);
  // N^−1/2 is no log factor's doing: it stays a finding.
  const auto root_n = [](double n) { return 1e-2 / std::sqrt(n); };
  const convergence_table slow = analyse_convergence(scrambled_net_series(16, root_n));
  EXPECT_EQ(slow.verdict, slope_verdict::shallower) << slow.verdict_reason;
  EXPECT_NE(slow.verdict_reason.find("finding"), std::string::npos);
}

// An adaptive method's ladder: four repetitions per N with errors ±e(N) (RMSE = e(N) exactly),
// each reporting the error estimate claim(N).
convergence_series adaptive_series(double (*error)(double), double (*claim)(double)) {
  convergence_series series = series_of(
      "genz_corner_peak", 2, "vegas", smoothness::analytic, 1.0,
      adaptive_monte_carlo_rate({smoothness::analytic, 2}, "σ/√N", "docs/theory.md#vegas"));
  for (int k = 10; k <= 20; k += 2) {
    const double n = std::ldexp(1.0, k);
    convergence_cell cell = cell_at(static_cast<std::uint64_t>(n), {});
    for (double sign : {1.0, -1.0, 1.0, -1.0}) {
      repetition_result r =
          repetition(1.0 + sign * error(n), claim(n), static_cast<std::uint64_t>(n), 1e-6);
      r.error_estimate = claim(n);
      cell.repetitions.push_back(r);
    }
    series.cells.push_back(cell);
  }
  return series;
}

TEST(ConvergenceTable, AnAdaptiveMethodsReportedVarianceIsAComputedReason) {
  // σ_N = N^(−0.4) while it adapts: the error falls as N^(−0.9), and so does the σ̂/√N it
  // reports. Steeper than −1/2, explained by its own variance: pre_asymptotic, with the
  // reported slope and σ̂ at both ends in the reason.
  const auto adapting = [](double n) { return std::pow(n, -0.9); };
  const convergence_table table = analyse_convergence(adaptive_series(adapting, adapting));
  EXPECT_NEAR(table.fit.slope, -0.9, 1e-9);
  EXPECT_EQ(table.verdict, slope_verdict::pre_asymptotic) << table.verdict_reason;
  EXPECT_NE(table.verdict_reason.find("adapting: the error σ̂/√N it reports falls with slope "
                                      "-0.900 over the fitted N = 1024 … 1048576"),
            std::string::npos)
      << table.verdict_reason;
  EXPECT_NE(table.verdict_reason.find("from 0.0625 to 0.00391"), std::string::npos)
      << table.verdict_reason;  // σ̂ = N^(−0.4) at N = 2^10 and 2^20
  // The same error with a claim that stays at σ/√N: its variance does not explain the slope, a
  // finding.
  const auto root_n = [](double n) { return 1.0 / std::sqrt(n); };
  const convergence_table unexplained = analyse_convergence(adaptive_series(adapting, root_n));
  EXPECT_EQ(unexplained.verdict, slope_verdict::steeper) << unexplained.verdict_reason;
  EXPECT_NE(unexplained.verdict_reason.find("finding"), std::string::npos);
  // A method not marked adaptive gets no such reason from the same numbers.
  convergence_series plain = adaptive_series(adapting, adapting);
  plain.theory = root_n_rate({smoothness::analytic, 2}, "σ/√N", "docs/theory.md#plain-monte-carlo");
  EXPECT_EQ(analyse_convergence(plain).verdict, slope_verdict::steeper);
}

TEST(ConvergenceTable, ShortLadderGivesNoFitNotAnError) {
  convergence_series series = midpoint_series();
  series.cells.resize(2);  // N = 2^28 and 2^27: both at the floor, nothing to fit
  const convergence_table table = analyse_convergence(series);
  EXPECT_EQ(table.fit.status, fit_status::too_few_points);
  // The floor, not the ladder's length, stopped the fit: the verdict names it.
  EXPECT_EQ(table.verdict, slope_verdict::at_floor) << table.verdict_reason;
  EXPECT_NE(table.verdict_reason.find("rounding floor"), std::string::npos);
  // Two clean points above any floor: too few to fit, and nothing else to blame.
  convergence_series two = midpoint_series();
  two.cells.erase(two.cells.begin(), two.cells.end() - 2);
  const convergence_table short_ladder = analyse_convergence(two);
  ASSERT_FALSE(short_ladder.floor.reached());
  EXPECT_EQ(short_ladder.verdict, slope_verdict::no_fit) << short_ladder.verdict_reason;
}

// A step at c = 1/2 + 1/4 + 1/8 + 1/16 + 2⁻²⁰ under the midpoint rule on n = 2⁴ … 2¹⁶ panels
// (N = n): |error| = h·dist(n·c, nearest node count) (the nodes right of c number n − ⌈nc − 1/2⌉),
// and n·c = integer + n·2⁻²⁰ with n·2⁻²⁰ ≤ 1/16 for these n, so |error| = h·n·2⁻²⁰ = 2⁻²⁰ at
// every n: flat over twelve doublings. The envelope is |J|·h/2 = 1/(2n) ≥ 2⁻¹⁷ > 2⁻²⁰.
convergence_series run_of_ones_series() {
  const double c = 0.5 + 0.25 + 0.125 + 0.0625 + std::ldexp(1.0, -20);
  convergence_series series = series_of("step", 1, "midpoint", smoothness::discontinuous, 1.0 - c,
                                        composite_rule_rate(2, {smoothness::discontinuous, 1}));
  for (int k = 4; k <= 16; ++k) {
    const auto n = static_cast<std::uint64_t>(1) << k;
    convergence_cell cell;
    cell.n = n;
    cell.per_axis = n;
    cell.error_envelope = 0.5 / static_cast<double>(n);
    cell.repetitions.push_back(repetition(1.0 - c + std::ldexp(1.0, -20), nan, n, 1e-9));
    series.cells.push_back(cell);
  }
  return series;
}

TEST(ConvergenceTable, FlatJumpLadderIsWithinItsEnvelopeNotShallower) {
  const convergence_table table = analyse_convergence(run_of_ones_series());
  EXPECT_FALSE(table.floor.reached());
  // What the slope verdict alone says of this ladder: slope 0 against the theory −1.
  ASSERT_TRUE(table.fit.ok());
  EXPECT_NEAR(table.fit.slope, 0.0, 1e-12);
  ASSERT_TRUE(table.theory.slope.has_value());
  EXPECT_EQ(*table.theory.slope, -1.0);
  EXPECT_EQ(judge_slope(table.fit, table.theory.slope), slope_verdict::shallower);
  // The verdict judges the envelope; fit, interval and theory stay beside it.
  EXPECT_TRUE(table.has_envelope());
  EXPECT_EQ(table.verdict, slope_verdict::within_envelope);
  // Largest error/envelope at the last point: 2⁻²⁰/(1/2¹⁷) = 1/8.
  EXPECT_DOUBLE_EQ(table.envelope_ratio, 0.125);
  EXPECT_EQ(table.rows.front().per_axis, 16u);
  EXPECT_EQ(table.rows.back().envelope, 0.5 / 65536.0);
}

TEST(ConvergenceTable, OnePointOverItsEnvelopeIsAboveEnvelope) {
  convergence_series series = run_of_ones_series();
  series.cells[5].error_envelope = std::ldexp(1.0, -21);  // half the error there
  const convergence_table table = analyse_convergence(series);
  EXPECT_EQ(table.verdict, slope_verdict::above_envelope);
  EXPECT_DOUBLE_EQ(table.envelope_ratio, 2.0);
}

TEST(ConvergenceTable, RoundingLevelIsAllowedAboveAnAttainedEnvelope) {
  // An error that attains its envelope, plus rounding of a few ε·|I| (a sum of n weights 1/n
  // with n not a power of two): still within, since the envelope is exact arithmetic and the
  // allowance is rounding_floor.hpp's level ℓ(N) = 2ε·|I|·log₂N.
  convergence_series series = run_of_ones_series();
  const double eps = std::numeric_limits<double>::epsilon();
  for (convergence_cell& cell : series.cells) {
    cell.error_envelope = 0.25 / static_cast<double>(cell.n);
    cell.repetitions[0].value = series.reference + cell.error_envelope + 2 * eps * series.reference;
  }
  EXPECT_EQ(analyse_convergence(series).verdict, slope_verdict::within_envelope);
  // Far beyond the rounding level it is a real excess.
  for (convergence_cell& cell : series.cells) {
    cell.repetitions[0].value = series.reference + 1.001 * cell.error_envelope;
  }
  EXPECT_EQ(analyse_convergence(series).verdict, slope_verdict::above_envelope);
}

TEST(ConvergenceTable, EnvelopeOnSomeCellsOnlyIsRejected) {
  convergence_series series = run_of_ones_series();
  series.cells[3].error_envelope = nan;
  EXPECT_THROW(analyse_convergence(series), invalid_argument);
  series.cells[3].error_envelope = -1.0;
  EXPECT_THROW(analyse_convergence(series), invalid_argument);
  // Without envelopes at all the slope verdict is back (the old behaviour).
  for (convergence_cell& cell : series.cells) cell.error_envelope = nan;
  const convergence_table table = analyse_convergence(series);
  EXPECT_FALSE(table.has_envelope());
  EXPECT_EQ(table.verdict, slope_verdict::shallower);
  EXPECT_TRUE(std::isnan(table.envelope_ratio));
}

TEST(ConvergenceTable, RejectsBrokenSeriesNamingTheCell) {
  convergence_series empty = series_of("f", 1, "midpoint", smoothness::smooth, 1.0, {});
  EXPECT_THROW(analyse_convergence(empty), invalid_argument);

  convergence_series no_dimension = midpoint_series();
  no_dimension.s = 0;
  EXPECT_THROW(analyse_convergence(no_dimension), invalid_argument);

  convergence_series fewer = midpoint_series();
  fewer.cells[0].repetitions[0].evaluations = 3;  // N = 2^28 spent 3: fewer than N = 2^27's
  EXPECT_THROW(analyse_convergence(fewer), invalid_argument);

  convergence_series mixed = midpoint_series();
  mixed.cells[2].tolerance = 1e-6;  // one cell run to a tolerance among sized cells
  EXPECT_THROW(analyse_convergence(mixed), invalid_argument);

  convergence_series duplicate = midpoint_series();
  duplicate.cells.push_back(duplicate.cells.front());
  EXPECT_THROW(analyse_convergence(duplicate), invalid_argument);

  convergence_series no_reps = midpoint_series();
  no_reps.cells[3].repetitions.clear();
  try {
    analyse_convergence(no_reps);
    FAIL() << "a cell without repetitions must be rejected";
  } catch (const invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("cell N = "), std::string::npos) << e.what();
  }
}

// The floor, fit and work-precision steps name their inputs by position ("error[0]",
// "target"); the series goes in front of the message, so it says which integrand and method.
TEST(ConvergenceTable, StepErrorsNameTheSeries) {
  analysis_options options;
  options.error_targets = {-1.0};
  try {
    analyse_convergence(midpoint_series(), options);
    ADD_FAILURE() << "no error";
  } catch (const invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("genz_gaussian / s = 1 / midpoint: invalid target", 0),
              0u)
        << e.what();
  }
}

}  // namespace
}  // namespace quadmc
