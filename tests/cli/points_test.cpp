// End-to-end tests of `quadmc points` (bench/quadmc/points_command.hpp) and of a scene with the
// quasi-Monte Carlo methods: the CSV of a point set (the unrandomized Sobol' points by value,
// the same seed giving the same bytes, --rng's generator other bytes), the one-line errors for
// what a set refuses, and a run whose convergence.csv carries the replicate and discrepancy
// columns.
#include "quadmc/report/results_csv.hpp"
#include "quadmc_command.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace quadmc_cli_test {
namespace {

TEST(PointsCommand, WritesTheUnrandomizedSobolPointsAsCsv) {
  scratch_folder dir;
  const command_result r = run_quadmc(
      dir, {"points", "sobol", "--n", "4", "--s", "2", "--seed", "1", "--randomization", "none"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  // Points 0 … 3 of the 2D Sobol' sequence in Gray-code order: (0,0), (1/2,1/2), (3/4,1/4),
  // (1/4,3/4) (dimension 2's direction numbers 1/2, 3/4).
  EXPECT_EQ(r.out, "x1,x2\n0,0\n0.5,0.5\n0.75,0.25\n0.25,0.75\n");
}

TEST(PointsCommand, SameSeedSameBytesOtherSeedOtherPointsAndOutFile) {
  scratch_folder dir;
  const std::vector<std::string> args{"points", "halton", "--n", "300", "--s", "5", "--seed", "7"};
  const command_result a = run_quadmc(dir, args);
  const command_result b = run_quadmc(dir, args);
  ASSERT_EQ(a.exit_status, 0) << describe(a);
  EXPECT_EQ(a.out, b.out);
  EXPECT_EQ(std::count(a.out.begin(), a.out.end(), '\n'), 301);
  std::vector<std::string> other = args;
  other[7] = "8";
  EXPECT_NE(run_quadmc(dir, other).out, a.out);
  std::vector<std::string> to_file = args;
  to_file.insert(to_file.end(), {"--out", "points.csv"});
  const command_result f = run_quadmc(dir, to_file);
  ASSERT_EQ(f.exit_status, 0) << describe(f);
  EXPECT_TRUE(f.out.empty());
  EXPECT_EQ(read_text(dir / "points.csv"), a.out);
}

void expect_points_error(const std::vector<std::string>& args, const std::string& names,
                         const std::string& also) {
  scratch_folder dir;
  const command_result r = run_quadmc(dir, args);
  EXPECT_EQ(r.exit_status, 1) << describe(r);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << describe(r);
  EXPECT_NE(r.err.find(names), std::string::npos) << describe(r);
  EXPECT_NE(r.err.find(also), std::string::npos) << describe(r);
  EXPECT_TRUE(r.out.empty()) << describe(r);
}

TEST(PointsCommand, RefusesASeedOrStreamOutsideZeroTo2To64Minus1AsAUsageError) {
  // CLI11 alone reads "-3" into an unsigned as 2^64 − 3, and clamps 2^64 and more to 2^64 − 1
  // (so two different seeds gave the same points).
  for (const char* option : {"--seed", "--stream"}) {
    for (const char* value : {"-3", "18446744073709551616", "99999999999999999999999", "1e3"}) {
      scratch_folder dir;
      std::vector<std::string> args{"points", "sobol", "--n", "4", "--s", "2", "--seed", "1"};
      args.insert(args.end(), {option, value});
      const command_result r = run_quadmc(dir, args);
      EXPECT_EQ(r.exit_status, 2) << describe(r);
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << describe(r);
      EXPECT_NE(r.err.find(std::string(option) +
                           ": expected an integer K with 0 ≤ K ≤ 2^64 − 1 = "
                           "18446744073709551615, got " +
                           value),
                std::string::npos)
          << describe(r);
      EXPECT_TRUE(r.out.empty()) << describe(r);
    }
    // The largest value is a seed (a stream) like any other.
    scratch_folder dir;
    std::vector<std::string> args{"points", "sobol", "--n", "4", "--s", "2"};
    if (std::string(option) == "--stream") args.insert(args.end(), {"--seed", "1"});
    args.insert(args.end(), {option, "18446744073709551615"});
    const command_result largest = run_quadmc(dir, args);
    EXPECT_EQ(largest.exit_status, 0) << describe(largest);
  }
}

TEST(PointsCommand, StopsAtTheFirstFailedWriteAndAnnouncesAHugeOutput) {
  // Regression: `quadmc points … --n 2^40 | head -2` went on computing every point after
  // head had gone (over 60 s). The CPU limit turns a return of that into a failure (SIGXCPU)
  // instead of a hang; the fixed command stops within milliseconds.
  scratch_folder dir;
  const command_result r =
      run_command(dir, {"/bin/sh", "-c",
                        "( ulimit -t 30; " + std::string(QUADMC_CLI) +
                            " points independent --n 1099511627776 --s 1 --seed 1 2> err.txt; "
                            "echo $? > status.txt ) | head -2"});
  EXPECT_EQ(r.exit_status, 0) << describe(r);
  EXPECT_EQ(r.out.rfind("x1\n0.", 0), 0u) << describe(r);
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 2) << describe(r);
  EXPECT_EQ(read_text(dir / "status.txt"), "1\n") << read_text(dir / "err.txt");
  const std::string err = read_text(dir / "err.txt");
  EXPECT_NE(err.find("up to 26.4 TB of text (1099511627776 points × 1 coordinates)"),
            std::string::npos)
      << err;
  EXPECT_NE(err.find("cannot write to standard output"), std::string::npos) << err;
}

TEST(PointsCommand, BlamesTheOptionThatIsWrong) {
  // Regression: `--s 100000` with Sobol' was reported as a bad --n, and `--n 1e3` got CLI11's
  // conversion message instead of what N must be.
  scratch_folder dir;
  const command_result wide =
      run_quadmc(dir, {"points", "sobol", "--n", "2", "--s", "100000", "--seed", "1"});
  EXPECT_EQ(wide.exit_status, 1) << describe(wide);
  EXPECT_NE(wide.err.find("invalid --s = 100000: expected s ≤ "), std::string::npos)
      << describe(wide);
  const command_result scientific =
      run_quadmc(dir, {"points", "sobol", "--n", "1e3", "--s", "2", "--seed", "1"});
  EXPECT_EQ(scientific.exit_status, 2) << describe(scientific);
  EXPECT_NE(scientific.err.find("--n: expected an integer K with 0 ≤ K ≤ 2^64 − 1"),
            std::string::npos)
      << describe(scientific);
}

TEST(PointsCommand, RefusesWhatTheSetCannotGiveInOneLine) {
  expect_points_error({"points", "sobol", "--n", "1000", "--s", "2", "--seed", "1"}, "--n",
                      "nearest valid sizes 512 and 1024");
  expect_points_error({"points", "lattice", "--n", "3000", "--s", "2", "--seed", "1"}, "--n",
                      "2048 and 4096");
  expect_points_error(
      {"points", "halton", "--n", "8", "--s", "2", "--seed", "1", "--randomization", "lms_shift"},
      "--randomization", "owen, permutation, none");
  expect_points_error({"points", "niederreiter", "--n", "8", "--s", "2", "--seed", "1"},
                      "point set", "sobol");
  // The dimension is what is wrong here, so --s is named (it was --n).
  expect_points_error({"points", "sobol", "--n", "8", "--s", "3668", "--seed", "1"}, "--s",
                      "s ≤ 3667");
  expect_points_error(
      {"points", "halton", "--n", "8", "--s", "2", "--seed", "1", "--periodization", "baker"},
      "--periodization", "no periodization for halton (lattice only)");
  // A key the set lacks names the sets that have it, for values and flags alike.
  expect_points_error(
      {"points", "jittered", "--n", "8", "--s", "3", "--seed", "1", "--randomization", "owen"},
      "invalid --randomization = owen",
      "no randomization for jittered (sobol, padded_sobol, halton, lattice only)");
  expect_points_error({"points", "halton", "--n", "8", "--s", "2", "--seed", "1", "--allow-any-n"},
                      "invalid --allow-any-n = true", "no allow_any_n for halton (sobol only)");
  expect_points_error(
      {"points", "lattice", "--n", "8", "--s", "2", "--seed", "1", "--periodization", "tent"},
      "--periodization", "one of none, baker for lattice");
  // c0 … c3sin weight the points by ∏φ' (docs/theory.md#lattice-periodizations): refused, saying
  // why and which values the points take.
  expect_points_error(
      {"points", "lattice", "--n", "8", "--s", "2", "--seed", "1", "--periodization", "c2sin"},
      "--periodization", "one of none, baker for lattice's points: c2sin is a change of variables");
}

// The sets' own flags reach them: --drop-first-point starts the unrandomized Sobol' sequence at
// its point 1, (1/2, 1/2), and --allow-any-n takes N = 3 as it is.
TEST(PointsCommand, PassesEachSetsOwnFlagsToIt) {
  scratch_folder dir;
  const command_result r =
      run_quadmc(dir, {"points", "sobol", "--n", "3", "--s", "2", "--seed", "1", "--randomization",
                       "owen", "--allow-any-n", "--drop-first-point"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 4) << describe(r);
  const command_result plain =
      run_quadmc(dir, {"points", "sobol", "--n", "3", "--s", "2", "--seed", "1", "--randomization",
                       "none", "--drop-first-point"});
  ASSERT_EQ(plain.exit_status, 0) << describe(plain);
  EXPECT_EQ(plain.out, "x1,x2\n0.5,0.5\n0.75,0.25\n0.25,0.75\n");
}

// --rng names the generator of the set's random numbers (docs/theory.md#counter-based-generators):
// ARS-4x32-7 gives other points than the default Philox4x32-10 for the same seed, the same bytes
// every time; philox4x32_10 named is the default; a set that draws nothing is the same under both.
// The command has no --threads: its points are one serial pass over the set.
TEST(PointsCommand, RngNamesTheGeneratorOfTheRandomPoints) {
  scratch_folder dir;
  for (const std::vector<std::string>& set :
       {std::vector<std::string>{"independent"}, std::vector<std::string>{"jittered"},
        std::vector<std::string>{"sobol", "--randomization", "owen"}}) {
    std::vector<std::string> args{"points", set[0], "--n", "64", "--s", "2", "--seed", "3"};
    args.insert(args.end(), set.begin() + 1, set.end());
    const command_result philox = run_quadmc(dir, args);
    ASSERT_EQ(philox.exit_status, 0) << describe(philox);
    std::vector<std::string> named = args;
    named.insert(named.end(), {"--rng", "philox4x32_10"});
    EXPECT_EQ(run_quadmc(dir, named).out, philox.out) << set[0];
    std::vector<std::string> with_ars = args;
    with_ars.insert(with_ars.end(), {"--rng", "ars4x32_7"});
    const command_result ars = run_quadmc(dir, with_ars);
    ASSERT_EQ(ars.exit_status, 0) << describe(ars);
    EXPECT_EQ(std::count(ars.out.begin(), ars.out.end(), '\n'), 65) << set[0];
    EXPECT_EQ(ars.out.rfind("x1,x2\n", 0), 0u) << set[0];
    EXPECT_NE(ars.out, philox.out) << set[0];
    EXPECT_EQ(run_quadmc(dir, with_ars).out, ars.out) << set[0];
  }
  const std::vector<std::string> fixed{
      "points", "sobol", "--n", "8", "--s", "2", "--seed", "3", "--randomization", "none"};
  std::vector<std::string> fixed_ars = fixed;
  fixed_ars.insert(fixed_ars.end(), {"--rng", "ars4x32_7"});
  EXPECT_EQ(run_quadmc(dir, fixed_ars).out, run_quadmc(dir, fixed).out);
  const command_result help = run_quadmc(dir, {"points", "--help"});
  EXPECT_EQ(help.exit_status, 0) << describe(help);
  EXPECT_NE(help.out.find("--rng"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("philox4x32_10, ars4x32_7"), std::string::npos) << help.out;
}

TEST(PointsCommand, RefusesAnRngThatNamesNoGeneratorInOneLine) {
  expect_points_error(
      {"points", "independent", "--n", "8", "--s", "2", "--seed", "1", "--rng", "mt19937"},
      "invalid --rng = \"mt19937\"", "expected one of philox4x32_10, ars4x32_7");
  // Names are exact: no other case, no prefix.
  expect_points_error(
      {"points", "independent", "--n", "8", "--s", "2", "--seed", "1", "--rng", "ARS4x32_7"},
      "--rng", "one of philox4x32_10, ars4x32_7");
  expect_points_error(
      {"points", "independent", "--n", "8", "--s", "2", "--seed", "1", "--rng", "philox"}, "--rng",
      "one of philox4x32_10, ars4x32_7");
  // A missing value is a usage error, as for every option.
  scratch_folder dir;
  const command_result bare =
      run_quadmc(dir, {"points", "independent", "--n", "8", "--s", "2", "--seed", "1", "--rng"});
  EXPECT_EQ(bare.exit_status, 2) << describe(bare);
  EXPECT_NE(bare.err.find("--rng"), std::string::npos) << describe(bare);
}

constexpr const char* qmc_scene = R"(name = "qmc"
seed = 5
[[integrand]]
name = "g"
family = "genz_gaussian"
dimension = 2
[[method]]
name = "sobol"
repetitions = 8
[[method]]
name = "sobol"
randomization = "none"
[[method]]
name = "lattice"
periodization = "baker"
repetitions = 8
[budget]
N = [64, 256, 1000]
[output]
plots = false
)";

TEST(QmcScene, RunsWithReplicateErrorBarsAndDiscrepancies) {
  scratch_folder dir;
  write_text(dir / "scene.toml", qmc_scene);
  const command_result r =
      run_quadmc(dir, {"run", (dir / "scene.toml").string(), "--out", (dir / "out").string()});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  const auto rows = quadmc::read_convergence_csv(dir / "out" / "convergence.csv");
  ASSERT_EQ(rows.size(), 9u);
  for (const auto& row : rows) {
    // N = 1000 maps to the largest 2^m below it, as the tensor rules map N to their grids.
    EXPECT_EQ(row.evaluations, row.n == 1000 ? 512u : row.n) << row.method << " " << row.n;
    EXPECT_FALSE(std::isnan(row.l2_star_discrepancy)) << row.method << " " << row.n;
    if (row.method == "sobol_none") {
      EXPECT_EQ(row.repetitions, 1u);
      EXPECT_TRUE(std::isnan(row.coverage_95));
    } else {
      EXPECT_EQ(row.repetitions, 8u);
      EXPECT_FALSE(std::isnan(row.coverage_95)) << row.method;
      EXPECT_FALSE(std::isnan(row.replicate_std_error)) << row.method;
      EXPECT_FALSE(std::isnan(row.error_estimate)) << row.method;
    }
  }
}

TEST(QmcScene, ExplicitPointsThatAreNoPowerOfTwoFailAtTheKey) {
  scratch_folder dir;
  std::string text = qmc_scene;
  text.replace(text.find("repetitions = 8"), 15, "points = [256, 1000]");
  write_text(dir / "scene.toml", text);
  const command_result r = run_quadmc(dir, {"plan", (dir / "scene.toml").string()});
  EXPECT_EQ(r.exit_status, 1) << describe(r);
  EXPECT_NE(r.err.find("scene.toml:9:"), std::string::npos) << describe(r);
  EXPECT_NE(r.err.find("points"), std::string::npos) << describe(r);
  EXPECT_NE(r.err.find("nearest valid sizes 512 and 1024"), std::string::npos) << describe(r);
}

// The value of `measure` in a --report CSV (measure,value,note), or "?" when it is missing.
std::string reported(const std::string& csv, const std::string& measure) {
  const std::size_t at = csv.find("\n" + measure + ",");
  if (at == std::string::npos) return "?";
  const std::size_t begin = at + measure.size() + 2;
  return csv.substr(begin, csv.find(',', begin) - begin);
}

// --report: pmj02's pairs (0, 1) and (2, 3) are (0, 10, 2)-nets and its cross pairs are not; the
// whole set's t is given at s = 4 and left out, with the reason, where N is not 2^m; a --report
// beyond 2^20 points is refused naming --n.
TEST(PointsCommand, ReportStatesTheNetAndPackingOfTheSet) {
  scratch_folder dir;
  const command_result r =
      run_quadmc(dir, {"points", "pmj02", "--n", "1024", "--s", "4", "--seed", "3", "--report"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  EXPECT_EQ(r.out.rfind("measure,value,note\npoints,1024,\ndimension,4,\n", 0), 0u) << r.out;
  // Three fields on every line: no note may carry a comma.
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 2) << line;
  }
  EXPECT_EQ(reported(r.out, "pair_t_best"), "0") << r.out;
  EXPECT_NE(reported(r.out, "pair_t_worst"), "0") << r.out;
  EXPECT_NE(reported(r.out, "t_value"), "?") << r.out;
  const double ratio = std::stod(reported(r.out, "min_distance_ratio"));
  EXPECT_GT(ratio, 0.0);
  EXPECT_LT(ratio, 1.0);
  const command_result wide = run_quadmc(dir, {"points", "sobol", "--n", "1000", "--s", "6",
                                               "--seed", "3", "--allow-any-n", "--report"});
  ASSERT_EQ(wide.exit_status, 0) << describe(wide);
  EXPECT_NE(wide.out.find("\nt_value,,N is not a power of two\n"), std::string::npos) << wide.out;
  expect_points_error(
      {"points", "independent", "--n", "2000000", "--s", "1", "--seed", "1", "--report"}, "--n",
      "N ≤ 2^20 with --report");
}

}  // namespace
}  // namespace quadmc_cli_test
