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
  // The page's time-to-error ratios are paired: quadmc's best and the best peer timed again
  // alternately, 5 rounds (budget.paired_timing_rounds' default), every round in the CSV.
  const fs::path pairs = dir / "out" / "time_to_error_pairs.csv";
  ASSERT_TRUE(fs::exists(pairs)) << describe(r);
  const std::vector<std::string> rounds = csv_column_text(pairs, "rounds");
  ASSERT_FALSE(rounds.empty());
  for (const std::string& k : rounds) EXPECT_EQ(k, "5");
  for (const std::string& m : csv_column_text(pairs, "quadmc_method")) EXPECT_EQ(m, "genz_malik");
  for (const std::string& ratios : csv_column_text(pairs, "ratios")) {
    EXPECT_EQ(std::count(ratios.begin(), ratios.end(), ';'), 4) << ratios;
  }
  const std::string page = read_text(dir / "out" / "README.md");
  EXPECT_NE(page.find("over 5 alternating runs) |"), std::string::npos) << page;
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
