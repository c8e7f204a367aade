// Tests of the runner's error envelopes (scene/run.hpp with rules/jump_error_envelope.hpp): a
// deterministic rule on an integrand with jumps gets, per cell, its panel count and the a-priori
// bound on |error|, so the analysis judges the envelope instead of the slope. Kept apart from
// run_test.cpp, which tests the runner's execution of methods and ensembles.
#include "quadmc/rules/jump_error_envelope.hpp"
#include "quadmc/scene/parse.hpp"
#include "quadmc/scene/run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>

namespace quadmc {
namespace {

convergence_table run_single_series(std::string_view text) {
  const plan p = make_plan(parse_scene(text, "envelope.toml"));
  const run_output out = run_plan(p);
  EXPECT_EQ(out.series.size(), 1u);
  return analyse_convergence(out.series.at(0));
}

// c = 1/2 + 1/4 + 1/8 + 1/16 + 2⁻²⁰: a run of ones in binary. On n = 2⁴ … 2¹⁶ panels the midpoint
// rule's nodes never resolve the 2⁻²⁰, and its error is exactly 2⁻²⁰ at every n
// (convergence_table_test.cpp derives it): a flat ladder whose slope 0 the slope verdict calls
// "shallower" (what slopes.csv said before the envelope), every point under |J|·h/2.
constexpr std::string_view run_of_ones = R"(name = "ones"
threads = 1
[[integrand]]
family = "step"
c = 0.93750095367431640625
[[method]]
name = "midpoint"
[budget]
N = { from = 16, to = 65536, factor = 2 }
)";

TEST(RunEnvelope, FlatMidpointLadderOnARunOfOnesIsWithinEnvelope) {
  const convergence_table table = run_single_series(run_of_ones);
  ASSERT_EQ(table.rows.size(), 13u);
  for (const convergence_row& row : table.rows) {
    EXPECT_EQ(row.stats.rmse, std::ldexp(1.0, -20)) << "N = " << row.n;
    EXPECT_EQ(row.per_axis, row.n) << "1D midpoint: N = n panels";
    EXPECT_EQ(row.envelope, 0.5 / static_cast<double>(row.n)) << "|J|·h/2, M₁ = 0";
  }
  ASSERT_TRUE(table.fit.ok());
  EXPECT_NEAR(table.fit.slope, 0.0, 1e-12);
  EXPECT_EQ(judge_slope(table.fit, table.theory.slope), slope_verdict::shallower);
  EXPECT_EQ(table.verdict, slope_verdict::within_envelope);
}

// The bound attained at every point: the right rectangle counts the node at c = 1/2 as 1 and errs
// by exactly h on dyadic n (exact arithmetic), so error/envelope = 1 throughout. An envelope
// constant smaller than the derived K = 1 (say halved) turns this into above_envelope.
TEST(RunEnvelope, AttainedEnvelopeIsWithinAndAnySmallerConstantIsNot) {
  const convergence_table table = run_single_series(R"(name = "tight"
threads = 1
[[integrand]]
family = "step"
c = 0.5
[[method]]
name = "right_rectangle"
panels = [2, 4, 8, 16, 32, 64, 128, 256, 512, 1024]
[budget]
N = [1]
)");
  ASSERT_EQ(table.rows.size(), 10u);
  EXPECT_EQ(table.envelope_ratio, 1.0);
  EXPECT_EQ(table.verdict, slope_verdict::within_envelope);
  // The slope is −1 here: the envelope verdict replaces the slope verdict, it does not need it.
  EXPECT_NEAR(table.fit.slope, -1.0, 1e-12);
}

// Midpoint with odd n puts the node (n/2)/n = 1/2 exactly on the jump: |error| = h/2, the bound,
// up to the rounding of a sum of weights 1/n (not exact for odd n): within thanks to the
// rounding allowance, at error/envelope = 1 to that rounding.
TEST(RunEnvelope, MidpointOnItsNodeAttainsTheEnvelopeUpToRounding) {
  const convergence_table table = run_single_series(R"(name = "node"
threads = 1
[[integrand]]
family = "step"
c = 0.5
[[method]]
name = "midpoint"
panels = [1, 3, 9, 27, 81, 243, 729, 2187]
[budget]
N = [1]
)");
  EXPECT_NEAR(table.envelope_ratio, 1.0, 1e-12);
  EXPECT_EQ(table.verdict, slope_verdict::within_envelope);
}

// An ensemble of Genz discontinuous instances in s = 2 under tensor Simpson: a cell's envelope is
// the largest of its instances' (its RMSE over the instances is at most the largest error).
TEST(RunEnvelope, EnsembleCellTakesTheLargestInstanceEnvelope) {
  constexpr std::string_view text = R"(name = "genz"
seed = 3
threads = 1
[[integrand]]
family = "genz_discontinuous"
dimension = 2
ensemble = 3
[[method]]
name = "simpson"
[budget]
N = [25, 81, 289, 1089, 4225]
)";
  const plan p = make_plan(parse_scene(text, "genz.toml"));
  const run_output out = run_plan(p);
  ASSERT_EQ(out.series.size(), 1u);
  const convergence_series& series = out.series[0];
  ASSERT_EQ(series.cells.size(), 5u);
  for (const convergence_cell& cell : series.cells) {
    double largest = 0.0;
    for (const plan_instance& inst : p.instances) {
      largest = std::max(largest,
                         *jump_error_envelope(simpson_rule{}, inst.function.info(), cell.per_axis));
    }
    EXPECT_EQ(cell.error_envelope, largest) << "N = " << cell.n;
    EXPECT_EQ(cell.repetitions.size(), 3u);
  }
  EXPECT_EQ(analyse_convergence(series).verdict, slope_verdict::within_envelope);
}

TEST(RunEnvelope, RombergOnAStepIsJudgedAgainstItsEnvelope) {
  const convergence_table table = run_single_series(R"(name = "romberg"
threads = 1
[[integrand]]
family = "step"
c = 0.7071067811865476
[[method]]
name = "romberg"
[budget]
N = { from = 3, to = 65537, factor = 2 }
)");
  EXPECT_TRUE(table.has_envelope());
  EXPECT_EQ(table.verdict, slope_verdict::within_envelope);
}

// Random methods and jumps across curved surfaces get no envelope: the slope verdict stays.
TEST(RunEnvelope, NoEnvelopeForRandomMethodsOrACurvedBoundary) {
  const plan p = make_plan(parse_scene(R"(name = "none"
seed = 1
threads = 1
[[integrand]]
name = "step"
family = "step"
[[integrand]]
name = "disk"
family = "disk_indicator"
dimension = 2
[[method]]
name = "plain_mc"
repetitions = 4
integrands = ["step"]
[[method]]
name = "simpson"
integrands = ["disk"]
[budget]
N = [81, 289, 1089]
)",
                                       "none.toml"));
  const run_output out = run_plan(p);
  ASSERT_EQ(out.series.size(), 2u);
  for (const convergence_series& series : out.series) {
    for (const convergence_cell& cell : series.cells) {
      EXPECT_TRUE(std::isnan(cell.error_envelope)) << series.integrand << " " << series.method;
    }
    EXPECT_FALSE(analyse_convergence(series).has_envelope());
  }
  EXPECT_EQ(out.series[0].cells[0].per_axis, 0u) << "plain MC has no grid";
  EXPECT_GT(out.series[1].cells[0].per_axis, 0u);
}

}  // namespace
}  // namespace quadmc
