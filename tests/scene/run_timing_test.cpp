// Tests of the runner's stable timing (scene/run.hpp, analysis/cell_timing.hpp): every cell is
// timed apart from its repetitions, the minimum is a scene setting with a run-time override, a
// cell whose first call takes the minimum is timed once, and work-precision curves of
// deterministic rules come out monotone in N within the spread the timing states.
#include "quadmc/scene/run.hpp"

#include "quadmc/scene/parse.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <string_view>

namespace quadmc {
namespace {

// A cheap integrand (eˣ on [0, 1], a few ns per value) and two deterministic rules on a ladder
// whose work grows 16× per step, from 16 evaluations (where one clock reading around one call used
// to time thread and cache effects, not the rule) to 2^20. One thread: no thread start-up in a
// call.
constexpr std::string_view ladder_scene = R"(name = "timing"
threads = 1
[[integrand]]
family = "exp"
[[method]]
name = "midpoint"
[[method]]
name = "simpson"
[budget]
N = [16, 256, 4096, 65536, 1048576]
timing_min_seconds = 0.02
)";

TEST(RunTiming, EveryCellIsTimedApartFromItsRepetitions) {
  const plan p = make_plan(parse_scene(ladder_scene, "timing.toml"));
  const run_output out = run_plan(p);
  ASSERT_EQ(out.series.size(), 2u);
  for (const convergence_series& series : out.series) {
    ASSERT_GE(series.cells.size(), 4u) << series.method;
    for (const convergence_cell& cell : series.cells) {
      const cell_timing& t = cell.timing;
      ASSERT_TRUE(t.timed()) << series.method << " N = " << cell.n;
      EXPECT_GT(t.seconds_per_estimate, 0.0) << series.method << " N = " << cell.n;
      // The statistics still come from the one repetition of a deterministic rule.
      EXPECT_EQ(cell.repetitions.size(), 1u);
      if (t.timed_once()) {
        // Only a call that alone took the minimum is timed once, by that call.
        EXPECT_GE(cell.repetitions.front().seconds, 0.02) << series.method << " N = " << cell.n;
        EXPECT_EQ(t.seconds_per_estimate, cell.repetitions.front().seconds);
      } else {
        EXPECT_GE(t.estimates, 2u);
        EXPECT_GE(t.spread, 0.0);
        // At least the minimum was spent: estimates × median ≈ the time, within the spread.
        EXPECT_GE(static_cast<double>(t.estimates) * t.seconds_per_estimate * (1.0 + t.spread),
                  0.02)
            << series.method << " N = " << cell.n;
      }
    }
  }
}

// The monotonicity the issue asks for: a deterministic rule's time per estimate does not fall as
// N grows 16×. Judged within the stated spread: every batch's time per estimate of cell k lies in
// t_k·[1 − spread_k, 1 + spread_k] (cell_timing.hpp), so the curve is monotone within its
// measured noise when t_{k+1}·(1 + spread_{k+1}) ≥ t_k·(1 − spread_k): the slowest batch of the
// larger cell is not faster than the fastest batch of the smaller one. Not a speed assertion: no
// time is compared with a constant. A timed-once cell (spread NaN) has spread 0 here.
TEST(RunTiming, WorkPrecisionOfDeterministicRulesIsMonotoneInN) {
  const plan p = make_plan(parse_scene(ladder_scene, "timing.toml"));
  const run_output out = run_plan(p);
  for (const convergence_series& series : out.series) {
    for (std::size_t k = 1; k < series.cells.size(); ++k) {
      const cell_timing& a = series.cells[k - 1].timing;
      const cell_timing& b = series.cells[k].timing;
      const double sa = std::isnan(a.spread) ? 0.0 : a.spread;
      const double sb = std::isnan(b.spread) ? 0.0 : b.spread;
      EXPECT_GE(b.seconds_per_estimate * (1.0 + sb), a.seconds_per_estimate * (1.0 - sa))
          << series.method << ": N = " << series.cells[k - 1].n << " took "
          << a.seconds_per_estimate << " s (spread " << sa << "), N = " << series.cells[k].n
          << " took " << b.seconds_per_estimate << " s (spread " << sb << ")";
    }
  }
}

// A cell timed again after the run (time_cell_estimate, for scene/paired_timing.hpp) goes through
// the same procedure: below the minimum, batches until it has passed; at 0, one call.
TEST(RunTiming, ACellTimedAgainFollowsTheRunnersProcedure) {
  const plan p = make_plan(parse_scene(ladder_scene, "timing.toml"));
  const run_context context{p.source.seed, 1};
  for (std::size_t index = 0; index < p.cells.size(); ++index) {
    const cell_timing t = time_cell_estimate(p, index, context, 0.02);
    ASSERT_TRUE(t.timed()) << "cell " << index;
    EXPECT_GT(t.seconds_per_estimate, 0.0) << "cell " << index;
    if (!t.timed_once()) {
      EXPECT_GE(t.estimates, 2u) << "cell " << index;
      EXPECT_GE(static_cast<double>(t.estimates) * t.seconds_per_estimate * (1.0 + t.spread), 0.02)
          << "cell " << index;
    }
    const cell_timing once = time_cell_estimate(p, index, context, 0.0);
    EXPECT_TRUE(once.timed_once()) << "cell " << index;
    EXPECT_TRUE(std::isnan(once.spread)) << "cell " << index;
  }
  EXPECT_THROW((void)time_cell_estimate(p, p.cells.size(), context, 0.0), invalid_argument);
  EXPECT_THROW((void)time_cell_estimate(p, 0, context, -1.0), invalid_argument);
}

TEST(RunTiming, ZeroMinimumTimesTheFirstCallOnce) {
  const plan p = make_plan(parse_scene(ladder_scene, "timing.toml"));
  run_options options;
  options.timing_min_seconds = 0.0;  // the run-time override of budget.timing_min_seconds
  const run_output out = run_plan(p, options);
  for (const convergence_series& series : out.series) {
    for (const convergence_cell& cell : series.cells) {
      EXPECT_TRUE(cell.timing.timed_once()) << series.method << " N = " << cell.n;
      EXPECT_EQ(cell.timing.seconds_per_estimate, cell.repetitions.front().seconds);
      EXPECT_TRUE(std::isnan(cell.timing.spread));
    }
  }
}

}  // namespace
}  // namespace quadmc
