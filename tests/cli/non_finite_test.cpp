// An integrand whose values overflow, through `quadmc run`: the command must stop with one line
// naming the key and write nothing, rather than fit slopes to inf or NaN.
//
// eˣ on [700, 710] has an integral beyond double (e^710 > DBL_MAX), so `run` refuses it when the
// plan is made, before any work. No catalogue member with valid parameters turns non-finite in
// the middle of a run any more; that path (check_finite_batch naming the point, the runner naming
// the cell) is tested in tests/scene/run_test.cpp.
#include "quadmc_command.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace quadmc_cli_test {
namespace {

TEST(NonFiniteTest, AnIntegralBeyondDoubleIsRefusedByThePlan) {
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
  EXPECT_NE(r.err.find("scene.toml:5:1: key 'integrand[1].upper': invalid upper = 710: expected "
                       "upper ≤ 709.78"),
            std::string::npos)
      << describe(r);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.toml"}) << describe(r);
}

}  // namespace
}  // namespace quadmc_cli_test
