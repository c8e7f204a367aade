// Tests of scene/run_scene.hpp: one call from a scene file to analysed results gives what its
// steps give one by one (plan, run, analysis), the options reach the plan, and a plan without a
// cell or a run without one is an error that says why.
#include "quadmc/scene/run_scene.hpp"

#include "quadmc/scene/parse.hpp"
#include "support/temporary_directory.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace quadmc {
namespace {

constexpr std::string_view two_methods = R"(name = "two"
seed = 3
[[integrand]]
family = "genz_oscillatory"
dimension = 2
[[method]]
name = "plain_mc"
repetitions = 4
[[method]]
name = "midpoint"
[budget]
N = [16, 256, 4096]
timing_min_seconds = 0
)";

std::string message_of(const auto& call) {
  try {
    call();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no exception)";
}

TEST(RunScene, OneCallGivesWhatItsStepsGive) {
  test_support::temporary_directory dir("run_scene",
                                        test_support::temporary_directory::start::empty);
  const auto file = dir.path / "two.toml";
  std::ofstream(file) << two_methods;
  run_options options;
  options.threads = 1;
  const scene_results results = run_scene(file, options);

  scene s = parse_scene(two_methods, "two.toml");
  s.threads = 1;
  const run_output steps = run_plan(make_plan(s));
  EXPECT_EQ(results.plan.source.threads, 1u);
  EXPECT_EQ(results.cells_ran(), results.plan.cells.size());
  ASSERT_EQ(results.tables.size(), steps.series.size());
  ASSERT_EQ(results.run.series.size(), steps.series.size());
  for (std::size_t k = 0; k < steps.series.size(); ++k) {
    const convergence_table expected = analyse_convergence(steps.series[k]);
    const convergence_table& got = results.tables[k];
    EXPECT_EQ(got.method, expected.method);
    ASSERT_EQ(got.rows.size(), expected.rows.size());
    for (std::size_t r = 0; r < got.rows.size(); ++r) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(got.rows[r].stats.rmse),
                std::bit_cast<std::uint64_t>(expected.rows[r].stats.rmse))
          << got.method << ", row " << r;
    }
  }
}

// The options' overrides are written into the scene before planning, so the plan's header says
// what the run uses.
TEST(RunScene, OptionsReachThePlan) {
  run_options options;
  options.threads = 3;
  options.timing_min_seconds = 0.25;
  const plan p = plan_scene(parse_scene(two_methods, "two.toml"), options);
  EXPECT_EQ(p.source.threads, 3u);
  EXPECT_EQ(p.source.budget.timing_min_seconds, 0.25);
}

TEST(RunScene, APlanWithoutCellsIsRefusedWithTheReason) {
  // A plan whose every cell was skipped, as make_plan leaves it when no method can take any N.
  scene s = parse_scene(two_methods, "two.toml");
  plan p = make_plan(s);
  p.cells.clear();
  EXPECT_EQ(message_of([&] { require_cells(p, "two.toml"); }),
            "two.toml: no cell to run: the plan skips every cell (reasons in the plan); nothing "
            "written");
  EXPECT_EQ(message_of([&] { (void)run_scene(p); }),
            "scene 'two': no cell to run: the plan skips every cell (reasons in the plan); "
            "nothing written");
}

TEST(RunScene, ABudgetSpentBeforeTheFirstCellIsAnError) {
  scene s = parse_scene(two_methods, "two.toml");
  s.budget.max_seconds = 1e-12;
  const std::string message = message_of([&] { (void)run_scene(make_plan(s)); });
  // The first cell may start within the picosecond on no machine: the run has nothing.
  EXPECT_NE(message.find("no cell ran: budget.max_seconds = 1e-12 s was spent before the first "
                         "cell"),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace quadmc
