// Tests of bench/peers/targets.cpp, the marks of results/peers' targets table, on synthetic rows
// (no timing: speed is never asserted in tests): met at and above the goal, missed below it, ⚠
// when either run got less than 0.75 of a core per thread whatever the ratio, the integrand
// alone's ratio shown beside a two-thread cell without changing its mark, shown but not counted
// outside the goal's s or below its N, "—" when a row is missing; the tally counts only ✅ and ❌
// as measured; memory is constant in N below the bound only.
#include "targets.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace quadmc::peers {
namespace {

// A throughput row that ran `evaluations` evaluations in 1 s on `cores` of the machine.
row throughput(const std::string& method, unsigned threads, std::size_t s, double evaluations,
               double cores, const std::string& integrand = "genz_gaussian") {
  row r;
  r.run = "throughput";
  r.method = method;
  r.integrand = integrand;
  r.s = s;
  r.threads = threads;
  r.evaluations = evaluations;
  r.seconds = 1.0;
  r.cpu_seconds = cores;
  r.rate = evaluations;
  return r;
}

target_spec spec(const std::string& numerator, unsigned numerator_threads,
                 const std::string& denominator, double goal) {
  target_spec t;
  t.label = numerator + " / " + denominator;
  t.run = "throughput";
  t.numerator = numerator;
  t.numerator_threads = numerator_threads;
  t.denominator = denominator;
  t.goal = goal;
  t.integrands = {"genz_gaussian"};
  return t;
}

TEST(PeersTargetMarks, MetAtAndAboveTheGoalMissedBelow) {
  const run_share one{1.0, 1};
  EXPECT_EQ(judge(0.85, 0.85, one, one), mark::met);
  EXPECT_EQ(judge(2.0, 0.85, one, one), mark::met);
  EXPECT_EQ(judge(std::nextafter(0.85, 0.0), 0.85, one, one), mark::missed);
  EXPECT_EQ(judge(0.0, 0.5, one, one), mark::missed);
}

TEST(PeersTargetMarks, AStarvedRunOnEitherSideIsNotMeasurableWhateverTheRatio) {
  const run_share one{1.0, 1};
  const run_share starved_one{0.74, 1};
  EXPECT_EQ(judge(10.0, 1.0, starved_one, one), mark::not_measurable);
  EXPECT_EQ(judge(0.1, 1.0, one, starved_one), mark::not_measurable);
  // Two threads need 1.5 cores; 0.75 of one core per thread exactly is enough.
  EXPECT_EQ(judge(1.95, 1.9, run_share{1.49, 2}, one), mark::not_measurable);
  EXPECT_EQ(judge(1.95, 1.9, run_share{1.5, 2}, one), mark::met);
  EXPECT_EQ(judge(1.80, 1.9, run_share{1.99, 2}, one), mark::missed);
  // A subprocess's share is unknown (NaN): never the reason for ⚠.
  EXPECT_FALSE(starved(run_share{NAN, 1}));
  EXPECT_EQ(judge(3.5, 3.0, one, run_share{NAN, 1}), mark::met);
}

// The integrand alone's ratio at the same thread counts is printed beside a two-thread cell for
// the reader, and never changes its mark: 1.55× is ❌ against 1.9× whether the integrand alone got
// 1.6× or 2×, and the same rows without the reference give the same mark and no reference.
TEST(PeersTargetMarks, TheIntegrandAlonesRatioIsShownBesideTheCellAndNeverChangesItsMark) {
  std::vector<row> rows{
      throughput("quadmc plain MC", 1, 2, 100.0, 1.0),
      throughput("quadmc plain MC", 2, 2, 155.0, 2.0),
      throughput("integrand only (batch in cache)", 1, 2, 400.0, 1.0),
      throughput("integrand only (batch in cache)", 2, 2, 640.0, 2.0),
  };
  // Two-thread runs: the rate is evaluations per second, the time one second as for every row.
  target_spec t = spec("quadmc plain MC", 2, "quadmc plain MC", 1.9);
  t.show_cores = true;
  t.reference = "integrand only (batch in cache)";
  auto lines = evaluate_targets({t}, rows, {2});
  ASSERT_EQ(lines.size(), 1U);
  EXPECT_DOUBLE_EQ(*lines[0].cells[0].reference, 1.6);
  EXPECT_EQ(lines[0].cells[0].m, mark::missed);
  EXPECT_NE(targets_table(lines, {2}).find("1.55× ❌ (2.00 / 1.00 cores; integrand alone 1.60×)"),
            std::string::npos)
      << targets_table(lines, {2});
  rows[3].evaluations = rows[3].rate = 800.0;
  lines = evaluate_targets({t}, rows, {2});
  EXPECT_DOUBLE_EQ(*lines[0].cells[0].reference, 2.0);
  EXPECT_EQ(lines[0].cells[0].m, mark::missed);
  t.reference.clear();
  lines = evaluate_targets({t}, rows, {2});
  EXPECT_FALSE(lines[0].cells[0].reference.has_value());
  EXPECT_EQ(lines[0].cells[0].m, mark::missed);
  EXPECT_NE(targets_table(lines, {2}).find("1.55× ❌ (2.00 / 1.00 cores) |"), std::string::npos)
      << targets_table(lines, {2});
}

TEST(PeersTargetMarks, CellsOutsideTheGoalsScopeAreShownNotCounted) {
  const std::vector<std::size_t> dims{1, 2, 4, 8};
  std::vector<row> rows;
  for (std::size_t s : dims) {
    rows.push_back(throughput("quadmc plain MC", 1, s, 100.0, 1.0));
    rows.push_back(throughput("quadmc tensor Simpson", 1, s, s == 4 ? 120.0 : 160.0, 1.0));
  }
  // Simpson at s = 8: the machine held the core.
  rows.back().cpu_seconds = 0.4;
  target_spec simpson = spec("quadmc tensor Simpson", 1, "quadmc plain MC", 1.5);
  simpson.counted_s = {2, 4, 8};
  const auto lines = evaluate_targets({simpson}, rows, dims);
  ASSERT_EQ(lines.size(), 1U);
  const auto& c = lines[0].cells;
  ASSERT_EQ(c.size(), 4U);
  EXPECT_DOUBLE_EQ(*c[0].ratio, 1.6);
  EXPECT_EQ(c[0].m, mark::not_counted);
  EXPECT_EQ(c[0].note, "s = 1 not in the goal");
  EXPECT_EQ(c[1].m, mark::met);
  EXPECT_EQ(c[2].m, mark::missed);
  EXPECT_EQ(c[3].m, mark::not_measurable);
  const target_tally t = tally(lines);
  EXPECT_EQ(t.met, 1);
  EXPECT_EQ(t.missed, 1);
  EXPECT_EQ(t.not_measurable, 1);
  const std::string table = targets_table(lines, dims);
  EXPECT_NE(table.find("| 1.60× (s = 1 not in the goal) | 1.60× ✅ | 1.20× ❌ | 1.60× ⚠ (0.40 / "
                       "1.00 cores) |"),
            std::string::npos)
      << table;
}

TEST(PeersTargetMarks, ATwoThreadRunBelowTheTargetsNIsShownNotCounted) {
  const std::uint64_t n = std::uint64_t{1} << 22;
  const std::vector<std::size_t> dims{2, 8};
  std::vector<row> rows{
      throughput("quadmc lattice shift", 1, 2, 1 << 20, 1.0),
      throughput("quadmc lattice shift", 2, 2, 1 << 20, 1.98),
      throughput("quadmc sobol owen", 1, 2, static_cast<double>(n), 1.0),
      throughput("quadmc sobol owen", 2, 2, 1.7 * static_cast<double>(n), 1.99),
  };
  // The two-thread run's rate is its evaluations per second: halve its time instead.
  rows[1].seconds = 0.5;
  rows[1].rate = 2.0 * (1 << 20);
  rows[1].cpu_seconds = 0.99;
  rows[3].evaluations = static_cast<double>(n);
  std::vector<target_spec> specs;
  for (const char* m : {"quadmc lattice shift", "quadmc sobol owen"}) {
    target_spec t = spec(m, 2, m, 1.9);
    t.min_evaluations = n;
    t.show_cores = true;
    specs.push_back(t);
  }
  const auto lines = evaluate_targets(specs, rows, dims);
  ASSERT_EQ(lines.size(), 2U);
  EXPECT_DOUBLE_EQ(*lines[0].cells[0].ratio, 2.0);
  EXPECT_EQ(lines[0].cells[0].m, mark::not_counted);
  EXPECT_EQ(lines[0].cells[0].note, "N = 1048576 < 4194304");
  EXPECT_DOUBLE_EQ(*lines[1].cells[0].ratio, 1.7);
  EXPECT_EQ(lines[1].cells[0].m, mark::missed);
  // No row at s = 8: no ratio, no mark, "—" on the page, nothing counted.
  EXPECT_FALSE(lines[0].cells[1].ratio.has_value());
  const target_tally t = tally(lines);
  EXPECT_EQ(t.met + t.missed + t.not_measurable, 1);
  const std::string table = targets_table(lines, dims);
  EXPECT_NE(table.find("| ≥ 1.9× (N ≥ 2^22) | 2.00× (N = 1048576 < 4194304) (1.98 / 1.00 cores) "
                       "| — |"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("1.70× ❌ (1.99 / 1.00 cores) | — |"), std::string::npos) << table;
}

TEST(PeersTargetMarks, PointRowsCompareAcrossFamiliesOnTheirOwnIntegrandName) {
  std::vector<row> rows{throughput("quadmc sobol lms_shift", 1, 2, 600.0, 1.0, "(points only)"),
                        throughput("scipy Sobol scrambled", 1, 2, 100.0, NAN, "(points only)")};
  for (row& r : rows) r.run = "points";
  target_spec t = spec("quadmc sobol lms_shift", 1, "scipy Sobol scrambled", 3.0);
  t.run = "points";
  t.integrands = {"(points only)"};
  const auto lines = evaluate_targets({t}, rows, {2});
  ASSERT_EQ(lines.size(), 1U);
  EXPECT_DOUBLE_EQ(*lines[0].cells[0].ratio, 6.0);
  EXPECT_EQ(lines[0].cells[0].m, mark::met);
  // Starved on quadmc's side: ⚠, and scipy's unknown share printed as "?".
  rows[0].cpu_seconds = 0.5;
  const auto starved_lines = evaluate_targets({t}, rows, {2});
  EXPECT_EQ(starved_lines[0].cells[0].m, mark::not_measurable);
  EXPECT_NE(targets_table(starved_lines, {2}).find("6.00× ⚠ (0.50 / ? cores)"), std::string::npos)
      << targets_table(starved_lines, {2});
  // The same rows under run = "throughput" are not the point rows: nothing to compare.
  t.run = "throughput";
  EXPECT_FALSE(evaluate_targets({t}, rows, {2})[0].cells[0].ratio.has_value());
}

TEST(PeersTargetMarks, EveryTwoThreadTargetIsAtTheGivenNAndEveryLineHasAGoal) {
  const std::uint64_t n = std::uint64_t{1} << 22;
  int two_thread = 0;
  for (const target_spec& t : performance_targets(n)) {
    EXPECT_GT(t.goal, 0.0) << t.label;
    EXPECT_FALSE(t.integrands.empty()) << t.label;
    if (t.numerator_threads == 2) {
      ++two_thread;
      EXPECT_EQ(t.numerator, t.denominator) << t.label;
      EXPECT_EQ(t.min_evaluations, n) << t.label;
      EXPECT_EQ(t.reference, integrand_only_method) << t.label;
    }
  }
  EXPECT_GE(two_thread, 10);  // plain, jittered, LHS, Simpson, trapezoid, 3 Sobol', Halton, lattice
}

TEST(PeersTargetMarks, MemoryIsConstantInNOnlyBelowTheBound) {
  EXPECT_TRUE(memory_constant(rss_row{"m", {1000000, 100000000}, {12000, 12500}}, 4096));
  EXPECT_FALSE(memory_constant(rss_row{"m", {1000000, 100000000}, {12000, 16096}}, 4096));
  EXPECT_FALSE(memory_constant(rss_row{"m", {1000000, 100000000}, {12000, 110000}}, 4096));
  EXPECT_FALSE(memory_constant(rss_row{"m", {1000000}, {12000}}, 4096));  // one size: no claim
}

}  // namespace
}  // namespace quadmc::peers
