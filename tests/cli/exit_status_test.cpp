// End-to-end tests of the command's exit status and of what it reports about a run
// (bench/quadmc/main.cpp states the codes): usage errors, --help, a full stdout, the thread
// count and the number of cells that ran.
//
// Use these for the command's contract with scripts and CI. Not for bad scene files
// (bad_input_test.cpp) or the results folder (output_folder_test.cpp).
#include "quadmc/report/markdown_report.hpp"
#include "quadmc/report/results_csv.hpp"
#include "quadmc_process.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <thread>
#include <vector>

namespace quadmc_cli_test {
namespace {

TEST(ExitStatusTest, UsageErrorsExitTwoWithOneLine) {
  // Regression: CLI11's own codes (104–114) and a two-line message, where the command promised 2.
  scratch_folder dir;
  write_text(dir / "s.toml", tiny_scene("s", "", false));
  const std::string scene = (dir / "s.toml").string();
  const std::vector<std::vector<std::string>> usage_errors{
      {},                                     // no subcommand
      {"frobnicate"},                         // unknown subcommand
      {"run"},                                // missing scene
      {"run", scene, "--bogus"},              // unknown flag
      {"run", scene, "--out"},                // flag without its value
      {"run", scene, "--threads", "abc"},     // malformed value
      {"run", scene, "--threads", "100000"},  // out of range
      {"run", scene, "--threads", "-1"},      // out of range
      {"compare", "a"},                       // missing candidate
      {"compare", "a", "b", "--tolerance", "-1"},
      // Regression: NaN passed CLI11's range checks (every comparison with NaN is false) and
      // failed after the plan with exit 1.
      {"compare", "a", "b", "--tolerance", "nan"},
      {"run", scene, "--timing-min-seconds", "nan"},
      {"run", scene, "--timing-min-seconds", "inf"},
      {"run", scene, "--timing-min-seconds", "61"},
  };
  for (const auto& args : usage_errors) {
    std::string shown;
    for (const auto& a : args) shown += " " + a;
    const command_result r = run_quadmc(dir, args);
    EXPECT_EQ(r.exit_status, 2) << "quadmc" << shown << "\n" << describe(r);
    EXPECT_EQ(line_count(r.err), 1u) << "quadmc" << shown << "\n" << describe(r);
    EXPECT_EQ(r.err.rfind("quadmc: ", 0), 0u) << "quadmc" << shown << "\n" << describe(r);
    EXPECT_EQ(r.out, "") << "quadmc" << shown << "\n" << describe(r);
  }
  // The range error names the flag and the range, like the scene key `threads`.
  const command_result big = run_quadmc(dir, {"run", scene, "--threads", "100000"});
  EXPECT_NE(big.err.find("--threads"), std::string::npos) << describe(big);
  EXPECT_NE(big.err.find("4096"), std::string::npos) << describe(big);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"s.toml"});
}

TEST(ExitStatusTest, HelpGoesToStdoutWithExitZeroAndStatesTheExitCodes) {
  scratch_folder dir;
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"--help"}, std::vector<std::string>{"run", "--help"}}) {
    const command_result r = run_quadmc(dir, args);
    EXPECT_EQ(r.exit_status, 0) << describe(r);
    EXPECT_EQ(r.err, "") << describe(r);
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << describe(r);
  }
  const command_result r = run_quadmc(dir, {"--help"});
  EXPECT_NE(r.out.find("Exit status: 0"), std::string::npos) << describe(r);
  EXPECT_NE(r.out.find("3 (compare) incomparable"), std::string::npos) << describe(r);
}

TEST(ExitStatusTest, AMissingSceneFileIsBadInputNotAUsageError) {
  scratch_folder dir;
  const command_result r = run_quadmc(dir, {"run", (dir / "missing.toml").string()});
  EXPECT_EQ(r.exit_status, 1) << describe(r);
  EXPECT_EQ(line_count(r.err), 1u) << describe(r);
  EXPECT_NE(r.err.find("missing.toml"), std::string::npos) << describe(r);
}

TEST(ExitStatusTest, AFullStdoutIsAnErrorAndTheResultsAreStillWritten) {
  // Regression: `quadmc run … > /dev/full` (and plan, compare, list) exited 0.
  scratch_folder dir;
  scratch_folder logs;
  // Plots on: the plot script's own stdout must not make the run fail either.
  write_text(dir / "s.toml", tiny_scene("s", "", true));
  const std::string scene = (dir / "s.toml").string();
  ASSERT_EQ(run_quadmc(dir, {"run", scene, "--out", "seen"}).exit_status, 0);

  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"run", scene, "--out", "full"},
        std::vector<std::string>{"plan", scene},
        std::vector<std::string>{"compare", "seen", "seen"}, std::vector<std::string>{"list"}}) {
    process_options options;
    options.working_directory = dir.path();
    options.stdout_file = "/dev/full";
    options.stderr_file = logs / "err";
    std::vector<std::string> argv{QUADMC_CLI};
    argv.insert(argv.end(), args.begin(), args.end());
    const command_result r = child_process(argv, options).wait();
    EXPECT_EQ(r.exit_status, 1) << args.front() << "\n" << describe(r);
    EXPECT_EQ(line_count(r.err), 1u) << args.front() << "\n" << describe(r);
    EXPECT_NE(r.err.find("cannot write to standard output"), std::string::npos)
        << args.front() << "\n"
        << describe(r);
  }
  // The results of the run whose stdout failed are written all the same, and are the same as
  // those of the run whose stdout worked (same scene and seed; the estimates are bitwise equal).
  ASSERT_TRUE(fs::exists(dir / "full" / "README.md"));
  EXPECT_TRUE(fs::exists(dir / "full" / quadmc::convergence_plot_file("exp", 1)));
  for (const std::string column : {"method", "N", "estimate_mean", "rmse"}) {
    EXPECT_EQ(csv_column_text(dir / "full" / "convergence.csv", column),
              csv_column_text(dir / "seen" / "convergence.csv", column))
        << column;
  }
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"full", "s.toml", "seen"}));
}

// Plain Monte Carlo at N = 65536: several chunks of work per cell (chunks are thousands of
// points, estimators/sample_mean.hpp), so a run can use at least two threads.
const std::string threads_scene = R"(name = "t"
threads = 1
[[integrand]]
family = "genz_gaussian"
dimension = 2
a = [1.5, 2.5]
u = [0.4, 0.7]
[[method]]
name = "plain_mc"
repetitions = 2
[budget]
N = [65536]
[output]
plots = false
)";

std::string threads_phrase(const command_result& r) {
  const auto at = r.out.find(" on ");
  return at == std::string::npos ? "" : r.out.substr(at, r.out.find(" threads", at) - at);
}

TEST(ExitStatusTest, ThreadsZeroMeansAllCores) {
  // Regression: `--threads 0` meant "the scene's value" although --help said "all cores".
  // All cores is what --threads <hardware_concurrency> asks for, so both runs must report the
  // same count, and (on a machine with two cores or more) not the scene's one thread.
  const unsigned cores = std::thread::hardware_concurrency();
  if (cores < 2) GTEST_SKIP() << "one core: 0 and the scene's 1 are the same request";
  scratch_folder dir;
  write_text(dir / "t.toml", threads_scene);
  const std::string scene = (dir / "t.toml").string();
  const command_result zero = run_quadmc(dir, {"run", scene, "--out", "a", "--threads", "0"});
  const command_result all =
      run_quadmc(dir, {"run", scene, "--out", "b", "--threads", std::to_string(cores)});
  const command_result default_ = run_quadmc(dir, {"run", scene, "--out", "c"});
  ASSERT_EQ(zero.exit_status, 0) << describe(zero);
  ASSERT_EQ(all.exit_status, 0) << describe(all);
  ASSERT_EQ(default_.exit_status, 0) << describe(default_);
  EXPECT_EQ(threads_phrase(zero), threads_phrase(all)) << describe(zero) << describe(all);
  EXPECT_EQ(threads_phrase(default_), " on 1") << describe(default_);
  EXPECT_NE(threads_phrase(zero), " on 1") << describe(zero);
}

TEST(ExitStatusTest, TheReportedThreadCountIsTheOneUsed) {
  // Regression: "on 64 threads" for cells of 9…33 points, one chunk each, which run on one thread
  // however many are allowed. The summary line and README.md must say 1 used, 64 allowed.
  scratch_folder dir;
  write_text(dir / "s.toml", tiny_scene("s", "", false));
  const command_result r =
      run_quadmc(dir, {"run", (dir / "s.toml").string(), "--out", "out", "--threads", "64"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  EXPECT_NE(r.out.find(" on 1 threads (64 allowed"), std::string::npos) << describe(r);
  const std::string readme = read_text(dir / "out" / "README.md");
  EXPECT_NE(readme.find("- threads: 1 used (64 allowed"), std::string::npos) << readme;
}

TEST(ExitStatusTest, ThePlanShowsTheCommandLinesOverrides) {
  // Regression: the plan's header showed the scene's threads and timing_min_seconds while the
  // run used --threads and --timing-min-seconds.
  scratch_folder dir;
  write_text(dir / "s.toml", tiny_scene("s", "", false));
  const command_result r = run_quadmc(dir, {"run", (dir / "s.toml").string(), "--out", "out",
                                            "--threads", "3", "--timing-min-seconds", "0.25"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  EXPECT_NE(r.out.find("threads 3,"), std::string::npos) << describe(r);
  EXPECT_NE(r.out.find("timing_min_seconds 0.25"), std::string::npos) << describe(r);
}

TEST(ExitStatusTest, TheSummaryCountsTheCellsThatRan) {
  // Regression: "ran 3 cells" when budget.max_seconds had skipped some or all of them. With
  // max_seconds = 1e-300 every cell after the clock has moved at all is skipped; the first cell
  // (midpoint, 2^24 evaluations, milliseconds; cells run method by method) moves any clock, so
  // at most one cell runs. Both outcomes are
  // checked against what was written: never a count of cells that did not run.
  scratch_folder dir;
  write_text(dir / "s.toml",
             "name = \"s\"\n[[integrand]]\nfamily = \"exp\"\n[[method]]\nname = \"midpoint\"\n"
             "panels = [16777216]\n[[method]]\nname = \"trapezoid\"\npanels = [8, 16]\n"
             "[budget]\nN = [8]\nmax_seconds = 1e-300\n[output]\nplots = false\n");
  const command_result r = run_quadmc(dir, {"run", (dir / "s.toml").string(), "--out", "out"});
  if (r.exit_status == 0) {
    const auto rows = quadmc::read_convergence_csv(dir / "out" / "convergence.csv");
    EXPECT_LT(rows.size(), 3u);
    const std::string expected = "ran " + std::to_string(rows.size()) + " of 3 cells";
    EXPECT_NE(r.out.find(expected), std::string::npos) << expected << "\n" << describe(r);
    EXPECT_NE(r.out.find("skipped by budget.max_seconds"), std::string::npos) << describe(r);
  } else {
    EXPECT_EQ(r.exit_status, 1) << describe(r);
    EXPECT_NE(r.err.find("no cell ran"), std::string::npos) << describe(r);
    EXPECT_FALSE(fs::exists(dir / "out")) << "nothing ran, so nothing is written";
  }
}

}  // namespace
}  // namespace quadmc_cli_test
