// End-to-end tests of quadmc_with_peers (bench/peers/CMakeLists.txt): the `quadmc` command with
// the peers as methods runs a scene naming them, while the plain command refuses the same scene
// at plan time naming the method and the command that has it.
#include "quadmc_command.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace quadmc_cli_test {
namespace {

const std::string peer_scene = R"(name = "peers"
[[integrand]]
family = "genz_gaussian"
dimensions = [2]
[[method]]
name = "peer_hcubature"
control = "tolerance"
tolerances = [1e-4, 1e-7]
[[method]]
name = "peer_gsl_vegas"
repetitions = 2
[[method]]
name = "genz_malik"
[budget]
N = [1000, 4000]
[output]
plots = false
)";

TEST(QuadmcWithPeers, RunsASceneNamingPeersBesideTheSuitesMethods) {
  scratch_folder dir;
  write_text(dir / "s.toml", peer_scene);
  const command_result r = run_quadmc(dir, {"run", (dir / "s.toml").string(), "--out", "out"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  const std::vector<std::string> methods =
      csv_column_text(dir / "out" / "convergence.csv", "method");
  const std::vector<std::string> evaluations =
      csv_column_text(dir / "out" / "convergence.csv", "evaluations");
  int hcubature = 0, vegas = 0, genz_malik = 0;
  for (std::size_t i = 0; i < methods.size(); ++i) {
    hcubature += methods[i] == "peer_hcubature";
    vegas += methods[i] == "peer_gsl_vegas";
    genz_malik += methods[i] == "genz_malik";
    EXPECT_NE(evaluations[i], "0") << methods[i];
  }
  EXPECT_EQ(hcubature, 2) << "one cell per tolerance";
  EXPECT_EQ(vegas, 2) << "one cell per N";
  EXPECT_EQ(genz_malik, 2);
}

TEST(QuadmcWithPeers, ThePlainCommandRefusesTheSameSceneAtPlanTime) {
  scratch_folder dir;
  write_text(dir / "s.toml", peer_scene);
  // QUADMC_PLAIN_CLI: bench/quadmc, built without the peers.
  std::vector<std::string> argv{QUADMC_PLAIN_CLI, "plan", (dir / "s.toml").string()};
  const command_result r = run_command(dir, argv);
  EXPECT_EQ(r.exit_status, 1) << describe(r);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << describe(r);
  EXPECT_NE(r.err.find("s.toml:6:"), std::string::npos) << describe(r);
  EXPECT_NE(r.err.find("method 'peer_hcubature' (cubature's hcubature, libcubature-dev) is a peer"),
            std::string::npos)
      << describe(r);
  EXPECT_NE(r.err.find("quadmc_with_peers"), std::string::npos) << describe(r);
}

}  // namespace
}  // namespace quadmc_cli_test
