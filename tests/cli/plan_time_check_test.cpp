// End-to-end tests of what `quadmc run` checks before it computes anything: conditions that
// would otherwise make it fail only when writing, after the whole run (bench/quadmc/main.cpp,
// results_staging.hpp). Each must be one line on stderr, exit status 1, nothing computed and
// nothing written.
//
// "Nothing computed" is checked through stdout: the command prints the plan just before it
// starts the first cell, so an empty stdout means the refusal came first.
#include "quadmc/report/markdown_report.hpp"
#include "quadmc_process.hpp"

#include <sys/stat.h>

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace quadmc_cli_test {
namespace {

void expect_refused_before_the_run(const command_result& r, const std::string& says) {
  EXPECT_EQ(r.exit_status, 1) << describe(r);
  EXPECT_EQ(line_count(r.err), 1u) << describe(r);
  EXPECT_NE(r.err.find(says), std::string::npos) << "expected '" << says << "'\n" << describe(r);
  EXPECT_EQ(r.out, "") << "the plan was printed, so the run had started\n" << describe(r);
}

TEST(PlanTimeCheckTest, FolderNamesThatCannotBeCreatedAreRefused) {
  // NAME_MAX is 255 bytes on every file system the tests run on (ext4, tmpfs, btrfs, xfs); the
  // staging folder ".<name>.partial-XXXXXX" is 16 bytes longer than the name, so 239 is the
  // longest name that works. 250 fits the file system but not its staging folder; 256 neither.
  scratch_folder dir;
  write_text(dir / "s.toml", tiny_scene("s", "", false));
  for (const std::size_t length : {std::size_t{250}, std::size_t{256}}) {
    const command_result r =
        run_quadmc(dir, {"run", (dir / "s.toml").string(), "--out", std::string(length, 'n')});
    expect_refused_before_the_run(r, "--out");
    EXPECT_NE(r.err.find("bytes"), std::string::npos) << describe(r);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"s.toml"});
  }
  const command_result fits =
      run_quadmc(dir, {"run", (dir / "s.toml").string(), "--out", std::string(239, 'n')});
  EXPECT_EQ(fits.exit_status, 0) << describe(fits);
}

TEST(PlanTimeCheckTest, PlotNamesThatCannotBeCreatedAreRefused) {
  // The plots are named after the integrand: "work_precision_<name>_s=1.svg" for a name of 240
  // bytes would be 263 bytes, over NAME_MAX. The scene parser bounds integrand names at 128
  // characters (portable ones, so a plot name is at most 15 + 128 + 12 bytes), so such a name is
  // refused when the scene is read, before anything is created.
  const std::string name(240, 'i');
  scratch_folder dir;
  write_text(dir / "s.toml", "name = \"s\"\n[[integrand]]\nname = \"" + name +
                                 "\"\nfamily = \"exp\"\n[[method]]\nname = \"simpson\"\n"
                                 "[budget]\nN = [8, 16, 32]\n");
  const command_result r = run_quadmc(dir, {"run", (dir / "s.toml").string(), "--out", "out"});
  expect_refused_before_the_run(r, "key 'integrand[1].name'");
  EXPECT_NE(r.err.find("at most 128 characters"), std::string::npos) << describe(r);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"s.toml"});
}

TEST(PlanTimeCheckTest, ReadOnlyParentOrFolderIsRefused) {
  if (!permission_tests_possible()) GTEST_SKIP() << "root without CAP_SETUID: no permission test";
  scratch_folder dir;
  scratch_folder logs;
  write_text(logs / "s.toml", tiny_scene("s", "old results", false));
  fs::create_directory(dir / "locked");
  give_to_unprivileged_user(dir.path());
  give_to_unprivileged_user(logs.path());
  const std::vector<std::string> run_into_locked{"run", (logs / "s.toml").string(), "--out",
                                                 "locked/out"};
  ASSERT_EQ(run_quadmc_with(dir.path(), logs.path(), run_into_locked, {}, true).exit_status, 0);
  const auto old_results = snapshot(dir / "locked" / "out");

  // The parent read-only: no staging folder can be made beside the results.
  fs::permissions(dir / "locked", fs::perms::owner_read | fs::perms::owner_exec);
  expect_refused_before_the_run(run_quadmc_with(dir.path(), logs.path(), run_into_locked, {}, true),
                                "Permission denied");
  fs::permissions(dir / "locked", fs::perms::owner_all);

  // The results folder read-only: its old files could not be removed after the swap.
  fs::permissions(dir / "locked" / "out", fs::perms::owner_read | fs::perms::owner_exec);
  expect_refused_before_the_run(run_quadmc_with(dir.path(), logs.path(), run_into_locked, {}, true),
                                "not writable");
  fs::permissions(dir / "locked" / "out", fs::perms::owner_all);

  EXPECT_EQ(snapshot(dir / "locked" / "out"), old_results);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"locked"});
  std::vector<std::string> beside;
  for (const auto& e : fs::directory_iterator(dir / "locked")) {
    beside.push_back(e.path().filename().string());
  }
  EXPECT_EQ(beside, std::vector<std::string>{"out"}) << "no staging folder or lock file left";
}

TEST(PlanTimeCheckTest, AnUnwritableCellsCsvIsRefusedBeforeTheRun) {
  // Regression: --cells-csv was opened after every cell had run, so a folder or a missing
  // folder in its path cost the whole run.
  scratch_folder dir;
  write_text(dir / "s.toml", tiny_scene("s", "", false));
  fs::create_directory(dir / "a_folder");
  write_text(dir / "mine.csv", "keep me");
  for (const auto& [file, says] : std::vector<std::pair<std::string, std::string>>{
           {"a_folder", "a file (this is a folder"},
           {"missing/cells.csv", "a file in an existing folder"}}) {
    const command_result r =
        run_quadmc(dir, {"run", (dir / "s.toml").string(), "--out", "out", "--cells-csv", file});
    expect_refused_before_the_run(r, "--cells-csv");
    EXPECT_NE(r.err.find(says), std::string::npos) << describe(r);
    EXPECT_FALSE(fs::exists(dir / "out"));
  }
  // A file that exists is checked, not emptied, until the run has something to write.
  EXPECT_EQ(read_text(dir / "mine.csv"), "keep me");
  const command_result ok = run_quadmc(
      dir, {"run", (dir / "s.toml").string(), "--out", "out", "--cells-csv", "mine.csv"});
  EXPECT_EQ(ok.exit_status, 0) << describe(ok);
  EXPECT_NE(read_text(dir / "mine.csv").find("shares_chunks,placement"), std::string::npos);
}

TEST(PlanTimeCheckTest, MissingMatplotlibIsReportedBeforeTheRun) {
  // A stand-in matplotlib on PYTHONPATH that cannot be imported: what a machine without
  // python3-matplotlib looks like to /usr/bin/python3.
  scratch_folder dir;
  scratch_folder logs;
  write_text(logs / "s.toml", tiny_scene("s", "", true));
  write_matplotlib_stand_in(logs / "python", "", false, true);
  const command_result r =
      run_quadmc_with(dir.path(), logs.path(), {"run", (logs / "s.toml").string(), "--out", "out"},
                      {"PYTHONPATH=" + (logs / "python").string()});
  expect_refused_before_the_run(r, "python3-matplotlib");
  EXPECT_TRUE(dir.entries().empty()) << describe(r);
}

TEST(PlanTimeCheckTest, APlanWithoutCellsRunsNothingAndWritesNothing) {
  // Every cell above max_evaluations: there is nothing to run, and an earlier results folder
  // must not be replaced by an empty one.
  scratch_folder dir;
  write_text(dir / "s.toml", tiny_scene("s", "old results", false));
  ASSERT_EQ(run_quadmc(dir, {"run", (dir / "s.toml").string(), "--out", "out"}).exit_status, 0);
  const auto old_results = snapshot(dir / "out");
  write_text(dir / "none.toml",
             "name = \"none\"\n[[integrand]]\nfamily = \"exp\"\n[[method]]\nname = \"simpson\"\n"
             "[budget]\nN = [8, 16, 32]\nmax_evaluations = 2\n[output]\nplots = false\n");
  const command_result r = run_quadmc(dir, {"run", (dir / "none.toml").string(), "--out", "out"});
  EXPECT_EQ(r.exit_status, 1) << describe(r);
  EXPECT_EQ(line_count(r.err), 1u) << describe(r);
  EXPECT_NE(r.err.find("no cell to run"), std::string::npos) << describe(r);
  EXPECT_NE(r.out.find("exceed budget.max_evaluations"), std::string::npos)
      << "the plan with its skip reasons is printed\n"
      << describe(r);
  EXPECT_EQ(snapshot(dir / "out"), old_results);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"none.toml", "out", "s.toml"}));
}

}  // namespace
}  // namespace quadmc_cli_test
