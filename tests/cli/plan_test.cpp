// End-to-end tests of `quadmc plan` and `quadmc list`: what a user reads before running a scene.
//
// Use these to check the command prints the planner's cells and skips (scene/plan.hpp) and the
// whole catalogue (functions/catalogue.hpp, methods/registry.hpp). Not for the planner's N → grid
// arithmetic itself (tests/scene covers it exhaustively).
#include "quadmc/estimators/point_set_catalogue.hpp"
#include "quadmc/functions/catalogue.hpp"
#include "quadmc/methods/registry.hpp"
#include "quadmc_command.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace quadmc_cli_test {
namespace {

TEST(PlanTest, PrintsCellsAndSkipsWithReasons) {
  // Simpson in s = 2 needs (n + 1)² nodes with n ≥ 2 even: N = 4 is below the smallest grid,
  // 3² = 9; N = 16384 gives n = 126, 127² = 16129 > max_evaluations. Plain MC: 1024 × 16
  // repetitions = 16384 > 5000. Neither the plan nor the skips write anything.
  const std::string scene = R"(name = "plan_check"
[[integrand]]
name = "g"
family = "genz_gaussian"
dimension = 2
a = [1.5, 2.5]
u = [0.4, 0.7]
[[method]]
name = "simpson"
[[method]]
name = "plain_mc"
repetitions = 16
[budget]
N = [4, 64, 1024, 16384]
max_evaluations = 5000
)";
  scratch_folder dir;
  write_text(dir / "plan.toml", scene);
  const command_result r = run_quadmc(dir, {"plan", (dir / "plan.toml").string()});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  EXPECT_EQ(r.err, "") << describe(r);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"plan.toml"});  // plan writes nothing
  for (const std::string expected :
       {"plan for scene 'plan_check'", "cells (4,", "skipped (4)",
        "simpson × g, N = 4: N is below the smallest grid, 3^2 = 9 evaluations",
        "simpson × g, N = 16384: 16129 evaluations exceed budget.max_evaluations = 5000",
        "plain_mc × g, N = 1024: 1024 evaluations × 16 repetitions = 16384 exceed "
        "budget.max_evaluations = 5000"}) {
    EXPECT_NE(r.out.find(expected), std::string::npos) << "missing: " << expected << "\n"
                                                       << describe(r);
  }
  // The cells that remain: Simpson N = 64 → n = 6, 7² = 49 nodes; N = 1024 → n = 30, 961.
  for (const std::string cell : {"simpson", "49", "961"}) {
    EXPECT_NE(r.out.find(cell), std::string::npos) << cell << "\n" << describe(r);
  }
}

TEST(ListTest, PrintsEveryMethodIntegrandPointSetAndOption) {
  scratch_folder dir;
  const command_result r = run_quadmc(dir, {"list"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  EXPECT_EQ(r.err, "") << describe(r);
  std::vector<std::string> names;
  for (const quadmc::method_descriptor* m : quadmc::method_registry()) {
    names.emplace_back(m->name);
    for (const quadmc::option_doc& o : m->options) names.emplace_back(std::string(o.key) + " = ");
  }
  for (const auto& e : quadmc::integrand_catalogue()) names.emplace_back(e.name);
  for (const auto& p : quadmc::point_set_catalogue()) names.emplace_back(p.name);
  for (const auto& w : quadmc::importance_warps()) names.emplace_back(w.name);
  ASSERT_GE(names.size(), 16u + 26u);  // the 16 methods of the registry, 26 families
  for (const auto& name : names) {
    EXPECT_NE(r.out.find(name), std::string::npos) << "`quadmc list` misses " << name;
  }
  // Each set's largest s, on the line after its own.
  for (const auto& p : quadmc::point_set_catalogue()) {
    if (p.max_dimension == 0) continue;
    const std::size_t at =
        r.out.find("  " + std::string(p.name) + " ", r.out.find("\npoint sets ("));
    ASSERT_NE(at, std::string::npos) << p.name;
    const std::size_t next = r.out.find('\n', at) + 1;
    EXPECT_EQ(r.out.substr(next, r.out.find('\n', next) - next),
              "      s ≤ " + std::to_string(p.max_dimension))
        << p.name;
  }
}

}  // namespace
}  // namespace quadmc_cli_test
