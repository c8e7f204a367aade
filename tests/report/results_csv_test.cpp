// Tests for results_csv.hpp: the exact header lines, writer → reader round trip, tolerance of
// added columns, strictness about missing ones.
#include "quadmc/report/results_csv.hpp"

#include "../analysis/series_builder.hpp"

#include "quadmc/core/errors.hpp"
#include "support/floating_point.hpp"
#include "support/temporary_directory.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

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

void write(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

// Two series: a deterministic rule on a jump (no std_error, coverage empty, an error envelope
// 0.5/N that its error 0.3/N stays under) with an awkward integrand name, and a Monte Carlo
// method with coverage and no envelope.
std::vector<convergence_table> csv_sample_tables() {
  convergence_series rule = series_of("step, \"shifted\"", 1, "midpoint", smoothness::discontinuous,
                                      1.0 / 3.0, rule_theory(2, smoothness::discontinuous));
  convergence_series mc = series_of("genz_gaussian", 2, "plain_mc", smoothness::analytic, 0.7,
                                    monte_carlo_theory(smoothness::analytic, 2));
  for (int k = 2; k <= 6; ++k) {
    const double n = std::ldexp(1.0, k);
    const auto nk = static_cast<std::uint64_t>(n);
    rule.cells.push_back(
        cell_at(nk, {repetition(1.0 / 3.0 + 0.3 / n, nan, nk, 1e-7 * n)}, nk, 0.5 / n));
    // Stable timing: the rule's cells timed once (spread empty), the Monte Carlo cells in batches.
    const double once[] = {1e-7 * n};
    rule.cells.back().timing = summarise_timing(once, 1);
    mc.cells.push_back(
        cell_at(nk, {repetition(0.7 + 0.2 / std::sqrt(n), 0.2 / std::sqrt(n), nk, 1e-6),
                     repetition(0.7 - 0.3 / std::sqrt(n), 0.2 / std::sqrt(n), nk, 2e-6)}));
    const double batches[] = {1.1e-6 * n, 1e-6 * n, 1.3e-6 * n};
    mc.cells.back().timing = summarise_timing(batches, 300);
  }
  return {analyse_convergence(rule), analyse_convergence(mc)};
}

TEST(ResultsCsv, ExactHeaderLines) {
  const auto tables = csv_sample_tables();
  const std::string conv = convergence_csv_text("default", tables);
  EXPECT_EQ(conv.substr(0, conv.find('\n')),
            "scene,integrand,s,method,N,evaluations,repetitions,reference,estimate_mean,rmse,"
            "mean_abs_error,std_error_of_rmse,coverage_95,seconds,evals_per_second,floor,"
            "smoothness,envelope,tolerance,error_estimate,estimate_covers,estimate_covers_3x,"
            "chi2_per_dof,q_value,replicate_std_error,l2_star_discrepancy,centered_discrepancy,"
            "wraparound_discrepancy,predicted_error,prediction_ratio,local_slope,rounding_level,"
            "seconds_per_estimate,seconds_spread,timed_estimates,reached,instances,mse_mean,"
            "mse_ci95_low,mse_ci95_high,mse_median,mse_worst");
  const std::string slopes = slopes_csv_text("default", tables);
  EXPECT_EQ(slopes.substr(0, slopes.find('\n')),
            "scene,integrand,s,method,slope,ci_low,ci_high,theory,verdict,points_used,"
            "floor_points,smoothness,fit_status,attainable_accuracy,theory_note,envelope_ratio,"
            "verdict_reason,class_theory,asymptotic_from_n,asymptotic_slope,predicted_points,"
            "worst_prediction_ratio,rounding_model");
}

TEST(ResultsCsv, DeterministicRowHasEmptyCoverageAndFullReference) {
  const auto tables = csv_sample_tables();
  const std::string conv = convergence_csv_text("default", tables);
  // First data row: the quoted name, N = 4, reference 1/3 to 17 digits, empty std error and
  // coverage.
  const std::string first =
      conv.substr(conv.find('\n') + 1, conv.find('\n', conv.find('\n') + 1) - conv.find('\n') - 1);
  EXPECT_EQ(
      first.rfind("default,\"step, \"\"shifted\"\"\",1,midpoint,4,4,1,0.33333333333333331,", 0), 0u)
      << first;
  EXPECT_NE(first.find(",,,"), std::string::npos)
      << "std_error_of_rmse and coverage empty: " << first;
}

TEST(ResultsCsv, RoundTripThroughFiles) {
  const temporary_directory dir{"quadmc_results_csv", temporary_directory::start::empty};
  const auto tables = csv_sample_tables();
  write(dir.path / "convergence.csv", convergence_csv_text("default", tables));
  write(dir.path / "slopes.csv", slopes_csv_text("default", tables));

  const auto rows = read_convergence_csv(dir.path / "convergence.csv");
  ASSERT_EQ(rows.size(), 10u);
  std::size_t i = 0;
  for (const convergence_table& t : tables) {
    for (const convergence_row& row : t.rows) {
      const convergence_record& r = rows[i++];
      EXPECT_EQ(r.scene, "default");
      EXPECT_EQ(r.integrand, t.integrand);
      EXPECT_EQ(r.s, t.s);
      EXPECT_EQ(r.method, t.method);
      EXPECT_EQ(r.n, row.n);
      EXPECT_EQ(r.evaluations, row.stats.evaluations);
      EXPECT_EQ(r.repetitions, row.stats.repetitions);
      // Shortest round-trip text and 17 digits: every double reads back bit for bit.
      EXPECT_EQ(r.reference, t.reference);
      EXPECT_EQ(r.rmse, row.stats.rmse);
      EXPECT_EQ(r.estimate_mean, row.stats.estimate_mean);
      EXPECT_EQ(r.mean_abs_error, row.stats.mean_abs_error);
      EXPECT_EQ(r.seconds, row.stats.seconds);
      EXPECT_EQ(std::isnan(r.coverage_95), std::isnan(row.stats.coverage_95));
      if (!std::isnan(r.coverage_95)) {
        EXPECT_EQ(r.coverage_95, row.stats.coverage_95);
      }
      EXPECT_EQ(r.floor, row.floor);
      // The stable timing: median, spread and calls read back as written.
      EXPECT_EQ(r.timed_estimates, row.timing.estimates);
      EXPECT_EQ(r.seconds_per_estimate, row.timing.seconds_per_estimate);
      EXPECT_EQ(std::isnan(r.seconds_spread), std::isnan(row.timing.spread));
      if (!std::isnan(r.seconds_spread)) {
        EXPECT_EQ(r.seconds_spread, row.timing.spread);
      }
      EXPECT_EQ(r.time_per_estimate(), row.seconds_per_estimate());
      EXPECT_EQ(std::isnan(r.envelope), std::isnan(row.envelope));
      if (!std::isnan(r.envelope)) {
        EXPECT_EQ(r.envelope, row.envelope);
      }
    }
  }

  const auto slopes = read_slopes_csv(dir.path / "slopes.csv");
  ASSERT_EQ(slopes.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(slopes[k].integrand, tables[k].integrand);
    EXPECT_EQ(slopes[k].slope, tables[k].fit.slope);
    EXPECT_EQ(slopes[k].ci_low, tables[k].fit.ci_low);
    EXPECT_EQ(slopes[k].ci_high, tables[k].fit.ci_high);
    EXPECT_EQ(slopes[k].theory, *tables[k].theory.slope);
    EXPECT_EQ(slopes[k].verdict, to_string(tables[k].verdict));
    EXPECT_EQ(slopes[k].points_used, tables[k].points_used());
    EXPECT_EQ(slopes[k].floor_points, tables[k].floor_points());
  }
  // The rule's envelope verdict and ratio reach the file; the Monte Carlo row keeps its slope
  // verdict and leaves the ratio empty.
  EXPECT_EQ(slopes[0].verdict, "within_envelope");
  // error/envelope = 0.3/0.5; the error is read off 1/3 + 0.3/N, whose rounding (ε/3 against
  // 0.3/64 at the largest N) moves the ratio by ≤ 70ε ≈ 1.6e-14.
  EXPECT_NEAR(slopes[0].envelope_ratio, 0.6, 1e-13);
  EXPECT_EQ(slopes[1].verdict, "agrees");
  EXPECT_TRUE(std::isnan(slopes[1].envelope_ratio));
}

// A VEGAS-like series: every repetition with its own error estimate and χ²/dof and Q; the cell's
// coverage of its own estimate and the means reach the file and read back bit for bit.
TEST(ResultsCsv, OwnEstimateCoverageAndChiSquaredRoundTrip) {
  const temporary_directory dir{"quadmc_results_csv", temporary_directory::start::empty};
  convergence_series s = series_of("genz_gaussian", 2, "vegas", smoothness::analytic, 0.7,
                                   monte_carlo_theory(smoothness::analytic, 2));
  for (int k = 6; k <= 9; ++k) {
    const auto n = std::uint64_t{1} << k;
    const double se = 1.0 / static_cast<double>(n);
    repetition_result inside = repetition(0.7 + 0.5 * se, se, n, 1e-6);
    repetition_result outside = repetition(0.7 - 2.0 * se, se, n, 1e-6);
    inside.error_estimate = outside.error_estimate = se;
    inside.chi2_per_dof = 0.75;
    outside.chi2_per_dof = 1.25;
    inside.q_value = 0.625;
    outside.q_value = 0.25;
    s.cells.push_back(cell_at(n, {inside, outside}));
  }
  const std::vector<convergence_table> tables = {analyse_convergence(s)};
  write(dir.path / "convergence.csv", convergence_csv_text("v", tables));
  const auto rows = read_convergence_csv(dir.path / "convergence.csv");
  ASSERT_EQ(rows.size(), 4u);
  for (const convergence_record& r : rows) {
    EXPECT_EQ(r.estimate_covers, 0.5);     // |e| = 0.5·se ≤ se; 2·se > se
    EXPECT_EQ(r.estimate_covers_3x, 1.0);  // both ≤ 3·se
    EXPECT_EQ(r.chi2_per_dof, 1.0);
    EXPECT_EQ(r.q_value, 0.4375);
  }
  // A series without them (csv_sample_tables) leaves the four fields empty.
  write(dir.path / "convergence.csv", convergence_csv_text("default", csv_sample_tables()));
  for (const convergence_record& r : read_convergence_csv(dir.path / "convergence.csv")) {
    EXPECT_TRUE(std::isnan(r.estimate_covers));
    EXPECT_TRUE(std::isnan(r.chi2_per_dof));
  }
}

TEST(ResultsCsv, ReaderToleratesAddedAndReorderedColumnsAndMissingFloor) {
  const temporary_directory dir{"quadmc_results_csv", temporary_directory::start::empty};
  write(dir.path / "slopes.csv",
        "extra,scene,integrand,s,method,slope,ci_low,ci_high,theory,verdict,points_used,"
        "floor_points,later\n"
        "zz,x,f,2,jittered,-1.01,-1.1,-0.92,,no_theory,7,0,q\n");
  const auto slopes = read_slopes_csv(dir.path / "slopes.csv");
  ASSERT_EQ(slopes.size(), 1u);
  EXPECT_EQ(slopes[0].slope, -1.01);
  EXPECT_TRUE(std::isnan(slopes[0].theory));
  EXPECT_EQ(slopes[0].points_used, 7u);

  // A convergence.csv without any of the added columns (an older folder) reads with floor =
  // false and no envelope, tolerance, error estimate, coverage of it or χ².
  const auto tables = csv_sample_tables();
  std::string text = convergence_csv_text("default", tables);
  std::string old;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    std::string line = text.substr(start, end - start);
    // Drop every added column (floor, smoothness, envelope, …): none has a comma here.
    for (std::size_t column = 0; column < convergence_csv_added_columns.size(); ++column) {
      line = line.substr(0, line.rfind(','));
    }
    old += line + '\n';
    start = end + 1;
  }
  write(dir.path / "convergence.csv", old);
  const auto rows = read_convergence_csv(dir.path / "convergence.csv");
  ASSERT_EQ(rows.size(), 10u);
  for (const auto& r : rows) {
    EXPECT_FALSE(r.floor);
    EXPECT_TRUE(std::isnan(r.envelope));
    EXPECT_TRUE(std::isnan(r.tolerance));
    EXPECT_TRUE(std::isnan(r.estimate_covers));
    EXPECT_TRUE(std::isnan(r.q_value));
  }
}

TEST(ResultsCsv, MissingColumnOrBadNumberNamesFileAndColumn) {
  const temporary_directory dir{"quadmc_results_csv", temporary_directory::start::empty};
  const fs::path file = dir.path / "slopes.csv";
  write(file, "scene,integrand,s,method,slope,ci_low,ci_high,verdict,points_used,floor_points\n");
  try {
    read_slopes_csv(file);
    FAIL() << "theory column is missing";
  } catch (const invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(file.string()), std::string::npos) << what;
    EXPECT_NE(what.find("'theory'"), std::string::npos) << what;
  }
  write(file,
        "scene,integrand,s,method,slope,ci_low,ci_high,theory,verdict,points_used,floor_points\n"
        "x,f,1,midpoint,-2.0x,-2.1,-1.9,-2,agrees,5,0\n");
  try {
    read_slopes_csv(file);
    FAIL() << "slope is not a number";
  } catch (const invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'slope' = '-2.0x'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace quadmc
