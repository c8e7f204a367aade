// An integrand whose values overflow, through `quadmc run`: the run must stop with one line
// naming the integrand and the point (functions/integrand.hpp, check_finite_batch) and write
// nothing, rather than fit slopes to inf or NaN.
//
// Use it for the command's handling of a failure in the middle of a run (after the plan
// succeeded). No catalogue member returns NaN from valid parameters that this test could find
// (sin on huge bounds is finite; bounds whose width overflows are refused when the plan is made);
// eˣ on [700, 710] overflows to inf at x > ln(DBL_MAX) ≈ 709.78, and the rules' end node x = 710
// is evaluated in the first cell.
#include "quadmc_command.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace quadmc_cli_test {
namespace {

TEST(NonFiniteTest, OverflowingIntegrandStopsTheRunWithOneLine) {
  const std::string scene = R"(name = "overflow"
[[integrand]]
family = "exp"
lower = 700.0
upper = 710.0
[[method]]
name = "simpson"
[[method]]
name = "plain_mc"
repetitions = 2
[budget]
N = [8, 16]
[output]
plots = false
)";
  scratch_folder dir;
  write_text(dir / "scene.toml", scene);
  const command_result r = run_quadmc(dir, {"run", (dir / "scene.toml").string()});
  EXPECT_EQ(r.exit_status, 1) << describe(r);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << describe(r);
  EXPECT_NE(r.err.find("exp returned inf at x = (710)"), std::string::npos) << describe(r);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.toml"}) << describe(r);
}

}  // namespace
}  // namespace quadmc_cli_test
