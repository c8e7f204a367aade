// Tests of scene/cell_scheduler.hpp: a scheduler decides where and in which order cells run, never
// the series. A scheduler that runs the cells backwards (as a process of a distributed run may
// receive them) and files them in plan order gives bitwise the series of local_scheduler; the
// session's budget skips name the cell; progress counts what the scheduler says it reports.
#include "quadmc/scene/cell_scheduler.hpp"

#include "quadmc/scene/parse.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstddef>
#include <map>
#include <string_view>
#include <vector>

namespace quadmc {
namespace {

constexpr std::string_view three_methods = R"(name = "three"
seed = 11
threads = 2
[[integrand]]
family = "genz_gaussian"
dimension = 3
[[method]]
name = "plain_mc"
repetitions = 3
[[method]]
name = "sobol"
repetitions = 2
[[method]]
name = "simpson"
[budget]
N = [64, 4096]
timing_min_seconds = 0
)";

// Runs the cells last to first, then files them in plan order: the order of work a scheduler may
// choose freely.
class backwards_scheduler final : public cell_scheduler {
 public:
  void run_cells(run_session& session, run_assembly& assembly) override {
    const std::size_t cells = session.source().cells.size();
    std::map<std::size_t, cell_run> ran;
    for (std::size_t i = cells; i-- > 0;) ran.emplace(i, session.run_cell(i, 0.0));
    for (auto& [index, run] : ran) assembly.add(index, std::move(run));
  }
};

TEST(CellScheduler, AnyOrderOfWorkGivesTheLocalSeries) {
  const plan p = make_plan(parse_scene(three_methods, "three.toml"));
  ASSERT_EQ(p.cells.size(), 6u);
  const run_output here = run_plan(p);
  backwards_scheduler backwards;
  const run_output other = run_plan(p, {}, backwards);
  ASSERT_EQ(other.series.size(), here.series.size());
  for (std::size_t s = 0; s < here.series.size(); ++s) {
    const convergence_series& a = here.series[s];
    const convergence_series& b = other.series[s];
    EXPECT_EQ(a.method, b.method);
    ASSERT_EQ(a.cells.size(), b.cells.size()) << a.method;
    for (std::size_t c = 0; c < a.cells.size(); ++c) {
      ASSERT_EQ(a.cells[c].repetitions.size(), b.cells[c].repetitions.size());
      for (std::size_t r = 0; r < a.cells[c].repetitions.size(); ++r) {
        // Bitwise: the same streams, whatever ran first.
        EXPECT_EQ(std::bit_cast<std::uint64_t>(a.cells[c].repetitions[r].value),
                  std::bit_cast<std::uint64_t>(b.cells[c].repetitions[r].value))
            << a.method << ", cell " << c << ", repetition " << r;
        EXPECT_EQ(a.cells[c].repetitions[r].evaluations, b.cells[c].repetitions[r].evaluations);
      }
    }
  }
  EXPECT_EQ(other.threads_allowed, 2u);
}

// A budget spent before the run: local_scheduler skips every cell, each skip naming its cell and
// the budget, and run_plan still returns (the caller decides that nothing ran is an error).
TEST(CellScheduler, SpentBudgetSkipsEveryCellWithItsName) {
  scene s = parse_scene(three_methods, "three.toml");
  s.budget.max_seconds = 1e-9;
  const plan p = make_plan(s);
  run_session session(p, {});
  EXPECT_FALSE(session.budget_spent(1e-9));
  EXPECT_TRUE(session.budget_spent(2e-9));
  const plan_skip skip = session.budget_skip(1, 2.5);
  EXPECT_EQ(skip.what, "plain_mc × genz_gaussian_s3, N = 4096");
  EXPECT_EQ(skip.reason, "budget.max_seconds = 1e-09 s spent (2.5 s elapsed)");
  local_scheduler here;
  const run_output out = run_plan(p, {}, here);
  // The first cell may start within the nanosecond; every later one is skipped.
  EXPECT_GE(out.skips.size(), p.cells.size() - 1);
  for (const plan_skip& k : out.skips) {
    EXPECT_NE(k.reason.find("budget.max_seconds = 1e-09 s spent"), std::string::npos) << k.reason;
  }
}

// Progress counts what the scheduler reports: by default the whole plan, per repetition and per
// cell; a process that does not speak for the run reports nothing.
TEST(CellScheduler, ProgressCountsWhatTheSchedulerReports) {
  const plan p = make_plan(parse_scene(three_methods, "three.toml"));
  std::vector<run_progress> seen;
  run_options options;
  options.on_progress = [&](const run_progress& progress) { seen.push_back(progress); };
  (void)run_plan(p, options);
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.back().cells_done, p.cells.size());
  EXPECT_EQ(seen.back().cells_total, p.cells.size());
  EXPECT_EQ(seen.back().evaluations_total, p.total_evaluations);
  EXPECT_EQ(seen.back().evaluations_done, p.total_evaluations);

  seen.clear();
  run_session quiet(p, options);
  quiet.count_progress_of(1, p.cells[0].evaluations * p.cells[0].repetitions, false);
  (void)quiet.run_cell(0, 0.0);
  EXPECT_TRUE(seen.empty());
}

}  // namespace
}  // namespace quadmc
