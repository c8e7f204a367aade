// `mpirun -np K quadmc run`: every CSV column but the timing is what one process writes, for
// K = 2 and 3, with the costly cells split across ranks, with every cell split, and with none;
// a rank that fails ends the run with one line on rank 0, a non-zero exit and no results folder.
// Built only with the MPI build (tests/mpi/CMakeLists.txt). Open MPI runs here on loopback:
// shared memory between the ranks (btl self,vader), --oversubscribe for three ranks on two cores,
// and --allow-run-as-root since CI runs as root.
#include "quadmc_command.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace quadmc_cli_test {
namespace {

// Every kind of method: tensor rules (one of them on an accumulator), Romberg in 1D, Monte Carlo
// over every point set, importance sampling, the irradiance estimators, randomized QMC, both
// sparse grids, and the two adaptive methods under budget and tolerance control; random
// integrand parameters (drawn from the seed) and an ensemble.
constexpr const char* every_kind_of_method = R"(name = "mpi"
seed = 7
threads = 1
[[integrand]]
family = "genz_gaussian"
dimension = 2
[[integrand]]
family = "genz_oscillatory"
dimension = 3
ensemble = 2
[[integrand]]
family = "exp"
[[integrand]]
family = "irradiance_area"
occluder = 1
[[method]]
name = "simpson"
integrands = ["genz_gaussian_s2", "genz_oscillatory_s3", "exp"]
[[method]]
name = "gauss_legendre"
accumulator = "neumaier"
integrands = ["genz_gaussian_s2", "exp"]
[[method]]
name = "romberg"
integrands = ["exp"]
[[method]]
name = "plain_mc"
repetitions = 4
[[method]]
name = "jittered"
repetitions = 3
integrands = ["genz_gaussian_s2", "exp"]
[[method]]
name = "latin_hypercube"
repetitions = 3
integrands = ["genz_oscillatory_s3"]
[[method]]
name = "padded_jittered"
repetitions = 2
integrands = ["genz_gaussian_s2"]
[[method]]
name = "importance"
warp = "exponential"
repetitions = 3
integrands = ["exp"]
[[method]]
name = "irradiance_light_area"
repetitions = 3
integrands = ["irradiance_area"]
[[method]]
name = "sobol"
repetitions = 4
integrands = ["genz_gaussian_s2", "genz_oscillatory_s3"]
[[method]]
name = "smolyak"
integrands = ["genz_gaussian_s2", "genz_oscillatory_s3"]
[[method]]
name = "adaptive_sparse_grid"
control = "budget"
integrands = ["genz_gaussian_s2"]
[[method]]
name = "genz_malik"
control = "tolerance"
tolerances = [1e-4, 1e-7]
integrands = ["genz_oscillatory_s3"]
[[method]]
name = "vegas"
control = "budget"
repetitions = 2
integrands = ["genz_gaussian_s2"]
[budget]
N = { from = 64, to = 65536, factor = 4 }
[output]
plots = false
)";

std::vector<std::string> mpirun(unsigned ranks) {
  return {QUADMC_MPIEXEC,
          "-np",
          std::to_string(ranks),
          "--oversubscribe",
          "--allow-run-as-root",
          "--mca",
          "btl",
          "self,vader",
          "--mca",
          "btl_vader_single_copy_mechanism",
          "none",
          QUADMC_CLI};
}

// The lines of stderr that quadmc wrote (they start with "quadmc: ").
std::vector<std::string> quadmc_lines(const std::string& err) {
  std::vector<std::string> lines;
  std::istringstream in(err);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("quadmc: ", 0) == 0) lines.push_back(line);
  }
  return lines;
}

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

command_result run_ranks(const scratch_folder& dir, unsigned ranks,
                         const std::vector<std::string>& args) {
  std::vector<std::string> argv = mpirun(ranks);
  argv.insert(argv.end(), args.begin(), args.end());
  return run_command(dir, argv);
}

TEST(MpiRun, TwoAndThreeRanksWriteWhatOneProcessWrites) {
  scratch_folder dir;
  write_text(dir / "scene.toml", every_kind_of_method);
  const std::string scene = (dir / "scene.toml").string();
  const command_result one = run_quadmc(dir, {"run", scene, "--out", (dir / "one").string()});
  ASSERT_EQ(one.exit_status, 0) << describe(one);
  // The rows are what the test compares: make sure there are many, of every kind.
  ASSERT_GT(csv_column_text(dir / "one" / "convergence.csv", "method").size(), 60u);

  struct variant {
    unsigned ranks;
    std::string split;
  };
  for (const variant& v : {variant{2, "auto"}, variant{3, "auto"}, variant{2, "all"},
                           variant{3, "all"}, variant{2, "none"}}) {
    const std::string name = "ranks" + std::to_string(v.ranks) + "_" + v.split;
    const command_result r = run_ranks(
        dir, v.ranks, {"run", scene, "--out", (dir / name).string(), "--split-cells", v.split});
    ASSERT_EQ(r.exit_status, 0) << name << "\n" << describe(r);
    EXPECT_NE(r.out.find("on " + std::to_string(v.ranks) + " MPI ranks × "), std::string::npos)
        << describe(r);
    // No rank says anything on stderr (mpirun's own notices, should a machine print any, are
    // not quadmc's).
    EXPECT_TRUE(quadmc_lines(r.err).empty()) << describe(r);
    // One plan and one summary: only rank 0 prints.
    EXPECT_EQ(count_of(r.out, "\nran "), 1u) << describe(r);
    expect_same_results(dir / "one", dir / name, name);
    EXPECT_NE(read_text(dir / name / "README.md")
                  .find("- processes: " + std::to_string(v.ranks) + " MPI ranks"),
              std::string::npos);
  }
}

// A time-to-error scene under mpirun: rank 0 times the winners' pairs after the cells (the other
// ranks wait for it), so the folder has time_to_error_pairs.csv with every round, and the page
// says where they were timed. The "peer" is genz_malik under a `peer_` label, which makes it one
// by name (the plain command has no real peers).
TEST(MpiRun, RankZeroTimesTheTimeToErrorPairs) {
  scratch_folder dir;
  write_text(dir / "scene.toml", R"(name = "pairs"
threads = 1
[[integrand]]
family = "genz_gaussian"
dimensions = [2, 3]
[[method]]
name = "genz_malik"
control = "tolerance"
tolerance_kind = "relative"
tolerances = [1e-3, 1e-6]
[[method]]
name = "genz_malik"
label = "peer_twin"
control = "tolerance"
tolerance_kind = "relative"
tolerances = [1e-3, 1e-6]
[budget]
N = [64]
timing_min_seconds = 0.001
[output]
plots = false
)");
  const command_result r =
      run_ranks(dir, 2, {"run", (dir / "scene.toml").string(), "--out", (dir / "out").string()});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  EXPECT_TRUE(quadmc_lines(r.err).empty()) << describe(r);
  const std::vector<std::string> rounds =
      csv_column_text(dir / "out" / "time_to_error_pairs.csv", "rounds");
  ASSERT_FALSE(rounds.empty()) << describe(r);
  for (const std::string& k : rounds) EXPECT_EQ(k, "5");
  const std::vector<std::string> peers =
      csv_column_text(dir / "out" / "time_to_error_pairs.csv", "peer_method");
  for (const std::string& p : peers) EXPECT_EQ(p, "peer_twin");
  const std::string page = read_text(dir / "out" / "README.md");
  EXPECT_NE(page.find("over 5 alternating runs)"), std::string::npos) << page;
  EXPECT_NE(page.find("on MPI rank 0 while the other ranks waited idle"), std::string::npos);
}

// A rank killed in the middle of the run (rank 1 here, by a shell that starts it and sends
// SIGKILL two seconds later): mpirun ends the others, rank 0 removes its staging folder, the run
// exits non-zero and no results folder is written. (A cell that throws on one rank is tested in
// mpi_runner_test.cpp, where the plan can hold an integrand that fails.)
TEST(MpiRun, AKilledRankEndsTheRunWithoutResults) {
  scratch_folder dir;
  write_text(dir / "scene.toml", R"(name = "killed"
threads = 1
[[integrand]]
family = "genz_gaussian"
dimension = 4
[[method]]
name = "plain_mc"
repetitions = 64
[budget]
N = { from = 1024, to = 16777216, factor = 2 }
[output]
plots = false
)");
  std::vector<std::string> argv = mpirun(2);
  argv.pop_back();  // the shell starts quadmc, not mpirun
  const std::string script =
      "if [ \"$OMPI_COMM_WORLD_RANK\" = 1 ]; then \"$0\" \"$@\" & p=$!; sleep 2; kill -9 $p; "
      "wait $p; exit 137; else exec \"$0\" \"$@\"; fi";
  argv.insert(argv.end(), {"/bin/sh", "-c", script, QUADMC_CLI, "run",
                           (dir / "scene.toml").string(), "--out", (dir / "out").string()});
  const command_result r = run_command(dir, argv);
  EXPECT_NE(r.exit_status, 0) << describe(r);
  EXPECT_EQ(r.out.find("wrote "), std::string::npos) << describe(r);
  EXPECT_FALSE(fs::exists(dir / "out")) << describe(r);
}

// Bad input is found by every rank alike (the plan is deterministic): one line, exit 1.
TEST(MpiRun, BadInputIsOneLineFromRankZero) {
  scratch_folder dir;
  write_text(dir / "scene.toml",
             "name = \"bad\"\n[[integrand]]\nfamily = \"nope\"\n[[method]]\nname = "
             "\"simpson\"\n[budget]\nN = [8]\n");
  const command_result r = run_ranks(dir, 2, {"run", (dir / "scene.toml").string()});
  EXPECT_NE(r.exit_status, 0) << describe(r);
  // quadmc's own words (mpirun adds its report of the non-zero exit after them).
  const std::vector<std::string> said = quadmc_lines(r.err);
  ASSERT_EQ(said.size(), 1u) << describe(r);
  EXPECT_EQ(said[0].rfind("quadmc: " + (dir / "scene.toml").string() +
                              ":3:1: key 'integrand[1].family': unknown family \"nope\"",
                          0),
            0u)
      << describe(r);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.toml"}) << describe(r);
}

TEST(MpiRun, EveryOtherSubcommandRefusesMpirunInOneLine) {
  // Regression: `mpirun -np 2 quadmc render` and `… gallery` ran whole on both ranks, wrote one
  // folder from both and exited 1; `points`, `list` and the others printed once per rank.
  scratch_folder dir;
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"render", (fs::path(QUADMC_SOURCE_DIR) / "bench/scenes/render.toml").string(), "--out",
            "r"},
           {"gallery", "--out", "g"},
           {"points", "sobol", "--n", "4", "--s", "2", "--seed", "1"},
           {"list"}}) {
    const command_result r = run_ranks(dir, 2, args);
    EXPECT_NE(r.exit_status, 0) << describe(r);
    const std::vector<std::string> said = quadmc_lines(r.err);
    ASSERT_EQ(said.size(), 1u) << describe(r);
    EXPECT_NE(said[0].find("`quadmc " + args[0] +
                           "` runs in one process, not under mpirun (2 "
                           "ranks)"),
              std::string::npos)
        << describe(r);
    EXPECT_EQ(r.out, "") << describe(r);
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{}) << "nothing written";
}

}  // namespace
}  // namespace quadmc_cli_test
