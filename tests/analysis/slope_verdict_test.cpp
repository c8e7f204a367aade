// Tests for slope_verdict.hpp: the band max(CI half-width, 0.1·|theory|), the envelope verdict
// and the verdict strings.
#include "quadmc/analysis/slope_verdict.hpp"

#include "quadmc/core/errors.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace quadmc {
namespace {

power_law_fit fitted(double slope, double half_width) {
  power_law_fit fit;
  fit.status = fit_status::ok;
  fit.slope = slope;
  fit.ci_low = slope - half_width;
  fit.ci_high = slope + half_width;
  fit.points = 10;
  return fit;
}

TEST(SlopeVerdict, TheoryInsideTheIntervalAgrees) {
  EXPECT_EQ(judge_slope(fitted(-0.45, 0.1), -0.5), slope_verdict::agrees);
  EXPECT_DOUBLE_EQ(verdict_band(fitted(-0.45, 0.1), -0.5), 0.1);
}

TEST(SlopeVerdict, TinyIntervalUsesTheRelativeBand) {
  // CI ±1e-6 around −1.95: theory −2 lies outside the CI but within 0.1·2 = 0.2.
  EXPECT_EQ(judge_slope(fitted(-1.95, 1e-6), -2.0), slope_verdict::agrees);
  EXPECT_DOUBLE_EQ(verdict_band(fitted(-1.95, 1e-6), -2.0), 0.2);
}

TEST(SlopeVerdict, SteeperAndShallower) {
  EXPECT_EQ(judge_slope(fitted(-2.5, 0.05), -2.0), slope_verdict::steeper);
  EXPECT_EQ(judge_slope(fitted(-1.5, 0.05), -2.0), slope_verdict::shallower);
  EXPECT_EQ(judge_slope(fitted(-1.5, 0.05), -2.0, 0.3), slope_verdict::agrees)
      << "0.3·2 = 0.6 covers the gap 0.5";
}

TEST(SlopeVerdict, NoFitAndNoTheory) {
  power_law_fit failed;
  failed.status = fit_status::too_few_points;
  EXPECT_EQ(judge_slope(failed, -2.0), slope_verdict::no_fit);
  EXPECT_EQ(judge_slope(fitted(-2.0, 0.1), std::nullopt), slope_verdict::no_theory);
  EXPECT_TRUE(std::isnan(verdict_band(failed, -2.0)));
}

TEST(SlopeVerdict, StringsRoundTrip) {
  for (slope_verdict v :
       {slope_verdict::agrees, slope_verdict::steeper, slope_verdict::shallower,
        slope_verdict::no_theory, slope_verdict::no_fit, slope_verdict::within_envelope,
        slope_verdict::above_envelope, slope_verdict::superconvergent,
        slope_verdict::pre_asymptotic, slope_verdict::at_floor}) {
    EXPECT_EQ(parse_slope_verdict(to_string(v)), v) << to_string(v);
  }
  // The strings slopes.csv carries (results_csv.hpp's contract): fixed, not just round-tripping.
  EXPECT_STREQ(to_string(slope_verdict::within_envelope), "within_envelope");
  EXPECT_STREQ(to_string(slope_verdict::above_envelope), "above_envelope");
  EXPECT_STREQ(to_string(slope_verdict::superconvergent), "superconvergent");
  EXPECT_STREQ(to_string(slope_verdict::pre_asymptotic), "pre_asymptotic");
  EXPECT_STREQ(to_string(slope_verdict::at_floor), "at_floor");
  EXPECT_THROW(parse_slope_verdict("agree"), invalid_argument);
  EXPECT_THROW(parse_slope_verdict("within"), invalid_argument);
}

TEST(SlopeVerdict, EnvelopeVerdictAsksEveryPointToBeUnderItsBound) {
  const std::vector<double> envelope = {0.5, 0.25, 0.125};
  EXPECT_EQ(judge_envelope(std::vector<double>{0.5, 0.1, 0.125}, envelope),
            slope_verdict::within_envelope)
      << "equality is within: the bound is attained with the jump on a node";
  EXPECT_EQ(judge_envelope(std::vector<double>{0.1, 0.26, 0.01}, envelope),
            slope_verdict::above_envelope)
      << "one point above is enough";
  // A flat ladder under a falling envelope is within it: the slope is not the question.
  EXPECT_EQ(judge_envelope(std::vector<double>{0.1, 0.1, 0.1}, envelope),
            slope_verdict::within_envelope);
  EXPECT_EQ(judge_envelope({}, {}), slope_verdict::no_fit);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(judge_envelope(std::vector<double>{1e9}, std::vector<double>{inf}),
            slope_verdict::within_envelope);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(judge_envelope(std::vector<double>{0.1}, std::vector<double>{nan}),
               invalid_argument);
  EXPECT_THROW(judge_envelope(std::vector<double>{-0.1}, std::vector<double>{1.0}),
               invalid_argument);
  EXPECT_THROW(judge_envelope(std::vector<double>{0.1, 0.2}, std::vector<double>{1.0}),
               invalid_argument);
}

}  // namespace
}  // namespace quadmc
