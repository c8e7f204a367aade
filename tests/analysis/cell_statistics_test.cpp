// Tests for cell_statistics.hpp on data small enough to check by hand.
#include "quadmc/analysis/cell_statistics.hpp"

#include "quadmc/core/errors.hpp"
#include "support/floating_point.hpp"
#include "support/invalid_argument_message.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace quadmc {
namespace {

using quadmc::test_support::eps;
using test_support::nan;

TEST(CellStatistics, HandComputedFourRepetitions) {
  // I = 1; errors 0.1, −0.2, 0, 0.3; every std_error 0.1, so the 95% interval is ±0.19600.
  const std::vector<repetition_result> reps = {
      {1.1, 0.1, 100, 0.5}, {0.8, 0.1, 100, 0.5}, {1.0, 0.1, 100, 0.5}, {1.3, 0.1, 100, 0.5}};
  const cell_statistics c = compute_cell_statistics(reps, 1.0);
  EXPECT_EQ(c.repetitions, 4u);
  EXPECT_EQ(c.evaluations, 100u);
  EXPECT_EQ(c.total_evaluations, 400u);
  EXPECT_NEAR(c.estimate_mean, 1.05, 4 * eps);
  // MSE = (0.01 + 0.04 + 0 + 0.09)/4 = 0.035.
  EXPECT_NEAR(c.rmse, std::sqrt(0.035), 8 * eps);
  EXPECT_NEAR(c.mean_abs_error, 0.15, 4 * eps);
  // e² deviations from 0.035: −0.025, 0.005, −0.035, 0.055; Σ² = 0.0049; var = 0.0049/3;
  // se(MSE) = √(var/4); se(RMSE) = se(MSE)/(2√0.035).
  const double se_mse = std::sqrt(0.0049 / 3.0 / 4.0);
  EXPECT_NEAR(c.std_error_of_rmse, se_mse / (2.0 * std::sqrt(0.035)), 1e-14);
  // |e| ≤ 0.196 for 0.1 and 0 only: 2 of 4.
  EXPECT_DOUBLE_EQ(c.coverage_95, 0.5);
  EXPECT_NEAR(c.seconds, 2.0, 4 * eps);
  EXPECT_NEAR(c.evals_per_second, 200.0, 1e-12);
  EXPECT_NEAR(c.seconds_per_repetition(), 0.5, 4 * eps);
}

TEST(CellStatistics, AbsoluteWeightSumIsTheLargestReported) {
  std::vector<repetition_result> reps(3);
  for (auto& r : reps) {
    r.value = 1.0;
    r.evaluations = 10;
  }
  EXPECT_TRUE(std::isnan(compute_cell_statistics(reps, 1.0).absolute_weight_sum));
  reps[1].absolute_weight_sum = 3.5;
  reps[2].absolute_weight_sum = 2.0;
  EXPECT_EQ(compute_cell_statistics(reps, 1.0).absolute_weight_sum, 3.5);
  reps[0].absolute_weight_sum = -1.0;
  EXPECT_THROW(compute_cell_statistics(reps, 1.0), invalid_argument);
}

// The same errors 0.1, −0.2, 0, 0.3 with an own error estimate of 0.15 each (0.45 at 3×): |e| ≤
// 0.15 holds for 0.1 and 0 (2 of 4), |e| ≤ 0.45 for all four. χ²/dof 0.5, 1, 1.5, 3 and Q 0.8,
// 0.4, 0.2, 0.1 average to 1.5 and 0.375.
TEST(CellStatistics, OwnErrorEstimateCoverageAndChiSquared) {
  std::vector<repetition_result> reps = {
      {1.1, 0.1, 100, 0.5}, {0.8, 0.1, 100, 0.5}, {1.0, 0.1, 100, 0.5}, {1.3, 0.1, 100, 0.5}};
  const double chi2[] = {0.5, 1.0, 1.5, 3.0};
  const double q[] = {0.8, 0.4, 0.2, 0.1};
  for (std::size_t r = 0; r < reps.size(); ++r) {
    reps[r].error_estimate = 0.15;
    reps[r].chi2_per_dof = chi2[r];
    reps[r].q_value = q[r];
  }
  const cell_statistics c = compute_cell_statistics(reps, 1.0);
  EXPECT_DOUBLE_EQ(c.estimate_covers, 0.5);
  EXPECT_DOUBLE_EQ(c.estimate_covers_3x, 1.0);
  EXPECT_DOUBLE_EQ(c.chi2_per_dof, 1.5);
  EXPECT_DOUBLE_EQ(c.q_value, 0.375);

  // One repetition without an estimate (or without χ²) leaves the cell's column empty, never a
  // fraction over the others.
  reps[2].error_estimate = nan;
  reps[3].q_value = nan;
  const cell_statistics partial = compute_cell_statistics(reps, 1.0);
  EXPECT_TRUE(std::isnan(partial.estimate_covers));
  EXPECT_TRUE(std::isnan(partial.estimate_covers_3x));
  EXPECT_TRUE(std::isnan(partial.chi2_per_dof));
  EXPECT_TRUE(std::isnan(partial.q_value));
}

TEST(CellStatistics, RejectsANegativeChiSquaredOrAQOutsideTheUnitInterval) {
  std::vector<repetition_result> reps = {{1.0, 0.1, 1, 0.1}, {1.0, 0.1, 1, 0.1}};
  reps[1].chi2_per_dof = -1.0;
  reps[1].q_value = 0.5;
  try {
    compute_cell_statistics(reps, 1.0);
    FAIL() << "a negative chi2 must be rejected";
  } catch (const invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("repetitions[1].chi2_per_dof"), std::string::npos)
        << e.what();
  }
  reps[1].chi2_per_dof = 1.0;
  reps[1].q_value = 1.5;
  EXPECT_THROW(compute_cell_statistics(reps, 1.0), invalid_argument);
}

// A tolerance cell's `reached`: the fraction of repetitions whose own error estimate is at or
// below the target (equal counts); one without an estimate claims nothing. A sized cell has none,
// and a target on some repetitions only is refused (the runner sets it on all or none).
TEST(CellStatistics, ReachedCountsRepetitionsWhoseEstimateMetTheTarget) {
  std::vector<repetition_result> reps = {
      {1.0, nan, 10, 0.1}, {1.0, nan, 10, 0.1}, {1.0, nan, 10, 0.1}, {1.0, nan, 10, 0.1}};
  const double estimates[] = {1e-4, 1e-3, 2e-3, 5e-4};
  for (std::size_t r = 0; r < reps.size(); ++r) {
    reps[r].error_estimate = estimates[r];
    reps[r].target = 1e-3;
  }
  EXPECT_EQ(compute_cell_statistics(reps, 1.0).reached, 0.75);
  reps[0].error_estimate = nan;
  EXPECT_EQ(compute_cell_statistics(reps, 1.0).reached, 0.5);
  for (auto& r : reps) r.target = nan;
  EXPECT_TRUE(std::isnan(compute_cell_statistics(reps, 1.0).reached));
  reps[2].target = 1e-3;
  const std::string m = test_support::message_of([&] { compute_cell_statistics(reps, 1.0); });
  EXPECT_NE(m.find("invalid repetitions[2].target"), std::string::npos) << m;
  reps[2].target = -1.0;
  EXPECT_THROW(compute_cell_statistics(reps, 1.0), invalid_argument);
}

TEST(CellStatistics, DeterministicRuleHasNoSpreadAndNoCoverage) {
  const std::vector<repetition_result> reps = {{0.75, nan, 17, 0.0}};
  const cell_statistics c = compute_cell_statistics(reps, 1.0);
  EXPECT_DOUBLE_EQ(c.rmse, 0.25);
  EXPECT_DOUBLE_EQ(c.mean_abs_error, 0.25);
  EXPECT_TRUE(std::isnan(c.std_error_of_rmse)) << "one repetition has no spread";
  EXPECT_TRUE(std::isnan(c.coverage_95)) << "a rule has no std_error";
  EXPECT_TRUE(std::isnan(c.evals_per_second)) << "zero time: no rate";
}

TEST(CellStatistics, CoverageIsEmptyWhenAnyRepetitionLacksStdError) {
  const std::vector<repetition_result> reps = {{1.0, 0.1, 10, 1.0}, {1.0, nan, 10, 1.0}};
  EXPECT_TRUE(std::isnan(compute_cell_statistics(reps, 1.0).coverage_95));
}

TEST(CellStatistics, ExactRepetitionsHaveZeroSpread) {
  const std::vector<repetition_result> reps = {{2.0, 0.0, 10, 1.0}, {2.0, 0.0, 10, 1.0}};
  const cell_statistics c = compute_cell_statistics(reps, 2.0);
  EXPECT_EQ(c.rmse, 0.0);
  EXPECT_EQ(c.std_error_of_rmse, 0.0);
  EXPECT_EQ(c.coverage_95, 1.0) << "|e| = 0 ≤ z·0";
}

TEST(CellStatistics, CompensatedSumsKeepTinyErrorsOfLargeValues) {
  // 1000 repetitions of I + 1e-9 with I = 1e6: the naive mean of values would lose ~1e-10·…;
  // the RMSE must be the error itself to ~1e-16 relative of I (the rounding of v − I itself).
  const double reference = 1e6;
  std::vector<repetition_result> reps(1000, {reference + 1e-9, 1e-9, 1, 1e-3});
  const cell_statistics c = compute_cell_statistics(reps, reference);
  const double error = (reference + 1e-9) - reference;  // the representable error
  EXPECT_NEAR(c.rmse, error, 4 * eps * error);
  EXPECT_NEAR(c.estimate_mean, reference + 1e-9, 2 * eps * reference);
}

TEST(CellStatistics, RejectsBadInputNamingTheRepetition) {
  EXPECT_THROW(compute_cell_statistics({}, 1.0), invalid_argument);
  const std::vector<repetition_result> good = {{1.0, 0.1, 1, 0.1}};
  EXPECT_THROW(compute_cell_statistics(good, nan), invalid_argument);
  const std::vector<repetition_result> bad = {{1.0, 0.1, 1, 0.1}, {nan, 0.1, 1, 0.1}};
  try {
    compute_cell_statistics(bad, 1.0);
    FAIL() << "a NaN value must be rejected";
  } catch (const invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("repetitions[1].value"), std::string::npos) << e.what();
  }
  const std::vector<repetition_result> negative_time = {{1.0, 0.1, 1, -1.0}};
  EXPECT_THROW(compute_cell_statistics(negative_time, 1.0), invalid_argument);
  const std::vector<repetition_result> negative_se = {{1.0, -0.1, 1, 1.0}};
  EXPECT_THROW(compute_cell_statistics(negative_se, 1.0), invalid_argument);
}

// Errors of 1e200 and −3e200 (an integral of 1e210 estimated to 1e-10): e² overflows double, and
// the RMSE came out inf and its standard error NaN ("invalid error[0] = -nan" further on). The
// errors are scaled by a power of two before squaring: RMSE = 1e200·√((1 + 9)/2) = √5·1e200,
// se(MSE) = sd(e²)/√2 with sd({1, 9}·1e400) = √32·1e400, and se(RMSE) = se(MSE)/(2·RMSE).
TEST(CellStatistics, HugeErrorsGiveFiniteStatistics) {
  const std::vector<repetition_result> reps = {{1e210 + 1e200, 0.0, 10, 1.0},
                                               {1e210 - 3e200, 0.0, 10, 1.0}};
  const double reference = 1e210;
  const cell_statistics c = compute_cell_statistics(reps, reference);
  // The errors as double computes them (1e210 ± 1e200 carries the rounding of 1e210, whose ulp
  // is 1.5e194), in units of 1e200; for two values, sd(e²)/√2 = |e₁² − e₂²|/2.
  const double e1 = (reps[0].value - reference) / 1e200, e2 = (reps[1].value - reference) / 1e200;
  EXPECT_NEAR(e1, 1.0, 1e-5);
  EXPECT_NEAR(e2, -3.0, 1e-5);
  const double rmse = std::sqrt((e1 * e1 + e2 * e2) / 2.0);
  EXPECT_NEAR(c.rmse, rmse * 1e200, 1e-14 * rmse * 1e200);
  EXPECT_NEAR(c.mean_abs_error, (std::abs(e1) + std::abs(e2)) / 2.0 * 1e200, 1e-14 * 2e200);
  const double se_rmse = std::abs(e1 * e1 - e2 * e2) / 2.0 / (2.0 * rmse);
  EXPECT_NEAR(c.std_error_of_rmse, se_rmse * 1e200, 1e-14 * se_rmse * 1e200);
  // The largest finite errors, near DBL_MAX, still give a finite RMSE.
  const std::vector<repetition_result> extreme = {{1.7e308, nan, 1, 0.0}};
  EXPECT_DOUBLE_EQ(compute_cell_statistics(extreme, 0.0).rmse, 1.7e308);
  // An error that itself overflows (estimate and reference of opposite signs) is named.
  const std::vector<repetition_result> opposite = {{1.7e308, nan, 1, 0.0}};
  try {
    compute_cell_statistics(opposite, -1.7e308);
    ADD_FAILURE() << "no error";
  } catch (const invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("repetitions[0].value − reference = inf"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace quadmc

namespace quadmc {
namespace {

// Replicate error bars (randomized QMC): no repetition has its own std_error; the spread of the
// R values gives error_estimate = s_R, replicate_std_error = s_R/√R, and coverage_95 the fraction
// of r with |e_r| ≤ t(0.975, R − 2)·s_(−r). I = 1, errors 0.01, −0.01, 0, 0.02, 1: the outlier's
// leave-one-out interval is t(0.975, 3)·s(0.01, −0.01, 0, 0.02) = 3.1824·0.012910 = 0.0411 < 1,
// while each other value's interval includes the outlier's spread (s_(−r) > 0.4): 4 of 5.
TEST(CellStatistics, ReplicateErrorBarsComeFromTheSpreadOfTheValues) {
  const std::vector<double> errors{0.01, -0.01, 0.0, 0.02, 1.0};
  std::vector<repetition_result> reps;
  for (double e : errors) reps.push_back({1.0 + e, nan, 64, 0.1});
  const cell_statistics c = compute_cell_statistics(reps, 1.0, error_bars::replicates);
  // s_R by two passes over the errors (computed here, independently of the Welford update).
  double mean = 0.0;
  for (double e : errors) mean += e / 5.0;
  double m2 = 0.0;
  for (double e : errors) m2 += (e - mean) * (e - mean);
  const double sd = std::sqrt(m2 / 4.0);
  EXPECT_NEAR(c.error_estimate, sd, 1e-14);
  EXPECT_NEAR(c.replicate_std_error, sd / std::sqrt(5.0), 1e-14);
  EXPECT_DOUBLE_EQ(c.coverage_95, 0.8);
  // The same values with their own error bars: none (NaN std_error), so no coverage and no
  // error estimate; the replicates' standard error is reported either way.
  const cell_statistics own = compute_cell_statistics(reps, 1.0);
  EXPECT_TRUE(std::isnan(own.coverage_95));
  EXPECT_TRUE(std::isnan(own.error_estimate));
  EXPECT_NEAR(own.replicate_std_error, sd / std::sqrt(5.0), 1e-14);
}

TEST(CellStatistics, ReplicateCoverageNeedsThreeAndAStandardErrorTwo) {
  const std::vector<repetition_result> two = {{1.1, nan, 8, 0.1}, {0.9, nan, 8, 0.1}};
  const cell_statistics c = compute_cell_statistics(two, 1.0, error_bars::replicates);
  EXPECT_TRUE(std::isnan(c.coverage_95)) << "R − 2 = 0 degrees of freedom";
  EXPECT_NEAR(c.error_estimate, std::sqrt(0.02), 1e-15);
  const std::vector<repetition_result> one = {{1.1, nan, 8, 0.1}};
  const cell_statistics single = compute_cell_statistics(one, 1.0, error_bars::replicates);
  EXPECT_TRUE(std::isnan(single.replicate_std_error));
  EXPECT_TRUE(std::isnan(single.error_estimate));
}

// With normal replicate errors, (v_r − I)/s_(−r) has Student's t law with R − 2 degrees of
// freedom exactly, so the expected coverage is 0.95. Over K = 2000 cells of R = 10 normal
// replicates (a fixed-seed Box–Muller stream of splitmix64), the mean coverage is within 4.4
// standard errors of 0.95 (per cell coverage is in [0, 1]; its sd is estimated from the cells):
// a false alarm of 1e-5 under the CLT.
TEST(CellStatistics, ReplicateCoverageOfNormalErrorsIsNinetyFivePercent) {
  std::uint64_t state = 12345;
  auto uniform = [&state] {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return (static_cast<double>(z >> 11) + 0.5) * 0x1.0p-53;
  };
  constexpr int K = 2000;
  double sum = 0.0, sum2 = 0.0;
  for (int k = 0; k < K; ++k) {
    std::vector<repetition_result> reps;
    for (int r = 0; r < 10; ++r) {
      const double g =
          std::sqrt(-2.0 * std::log(uniform())) * std::cos(2.0 * std::numbers::pi * uniform());
      reps.push_back({3.0 + 0.01 * g, nan, 16, 0.1});
    }
    const double cover = compute_cell_statistics(reps, 3.0, error_bars::replicates).coverage_95;
    sum += cover;
    sum2 += cover * cover;
  }
  const double mean = sum / K;
  const double se = std::sqrt((sum2 / K - mean * mean) / (K - 1));
  EXPECT_NEAR(mean, 0.95, 4.4 * se);
}

TEST(CellStatistics, DiscrepancyColumnsAreRootMeanSquaresOrEmpty) {
  std::vector<repetition_result> reps = {{1.0, nan, 8, 0.1}, {1.0, nan, 8, 0.1}};
  reps[0].l2_star_discrepancy = 0.3;
  reps[1].l2_star_discrepancy = 0.4;
  const cell_statistics c = compute_cell_statistics(reps, 1.0, error_bars::replicates);
  EXPECT_NEAR(c.l2_star_discrepancy, std::sqrt((0.09 + 0.16) / 2), 1e-15);
  EXPECT_TRUE(std::isnan(c.centered_discrepancy)) << "no repetition measured it";
  // An ensemble measures its first instance only: the others' NaN are left out, not zeros.
  reps.push_back({1.0, nan, 8, 0.1});
  const cell_statistics pooled = compute_cell_statistics(reps, 1.0, error_bars::replicates);
  EXPECT_NEAR(pooled.l2_star_discrepancy, std::sqrt((0.09 + 0.16) / 2), 1e-15);
}

}  // namespace
}  // namespace quadmc
