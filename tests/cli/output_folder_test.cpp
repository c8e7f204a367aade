// End-to-end tests of the results folder's rules (lib/include/quadmc/report/results_staging.hpp): a
// run never deletes what it did not create, never reports results that are not there, and keeps the
// old results whole until the new ones are in place.
//
// Use these for what happens on the file system around `quadmc run`; the plot step is made to
// wait or to change the folder at a known moment by a stand-in matplotlib (quadmc_process.hpp),
// so nothing depends on timing. Not for the content of the files (run_test.cpp).
#include "quadmc/report/markdown_report.hpp"
#include "quadmc_process.hpp"

#include <sys/stat.h>

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

namespace quadmc_cli_test {
namespace {

std::string after(const std::string& text, const std::string& marker, const std::string& end) {
  const auto at = text.find(marker);
  if (at == std::string::npos) return {};
  const auto from = at + marker.size();
  return text.substr(from, text.find(end, from) - from);
}

TEST(OutputFolderTest, ConcurrentRunsToOneFolderNeitherShareNorLoseResults) {
  // Regression: both runs staged in "out.partial"; the second deleted the first's staging while
  // it was plotting, and one of them reported "wrote out" for a folder that did not exist.
  scratch_folder dir;
  scratch_folder logs;
  write_text(logs / "old.toml", tiny_scene("shared", "old results", false));
  write_text(logs / "a.toml", tiny_scene("shared", "results of run A", true));
  write_text(logs / "b.toml", tiny_scene("shared", "results of run B", true));
  ASSERT_EQ(run_quadmc(dir, {"run", (logs / "old.toml").string(), "--out", "out"}).exit_status, 0);

  // The first plot step to start waits until the test releases it; any later one goes on.
  const fs::path started = logs / "started";
  write_matplotlib_stand_in(logs / "python",
                            "try:\n"
                            "    os.close(os.open('" +
                                started.string() +
                                "', os.O_CREAT | os.O_EXCL))\n"
                                "    while not os.path.exists('" +
                                (logs / "release").string() +
                                "'):\n"
                                "        time.sleep(0.02)\n"
                                "except FileExistsError:\n"
                                "    pass");
  const std::vector<std::string> env{"PYTHONPATH=" + (logs / "python").string()};
  auto a = start_quadmc(dir.path(), logs.path(), "a",
                        {"run", (logs / "a.toml").string(), "--out", "out"}, env);
  ASSERT_TRUE(wait_for_file(started)) << "run A never reached its plot step";

  const command_result b = run_quadmc_with(
      dir.path(), logs.path(), {"run", (logs / "b.toml").string(), "--out", "out"}, env);
  EXPECT_EQ(b.exit_status, 1) << describe(b);
  EXPECT_EQ(line_count(b.err), 1u) << describe(b);
  EXPECT_NE(b.err.find(".out.lock"), std::string::npos) << "the error names the lock\n"
                                                        << describe(b);
  EXPECT_EQ(b.out, "") << "refused before computing anything\n" << describe(b);

  write_text(logs / "release", "");
  const command_result ra = a->wait();
  EXPECT_EQ(ra.exit_status, 0) << describe(ra);
  EXPECT_NE(ra.out.find("wrote " + (dir / "out").string()), std::string::npos) << describe(ra);
  const std::string readme = read_text(dir / "out" / "README.md");
  EXPECT_NE(readme.find("results of run A"), std::string::npos) << readme;
  EXPECT_TRUE(fs::exists(dir / "out" / "convergence.csv"));
  // No staging folder, lock file or mixture left beside it.
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out"});
}

TEST(OutputFolderTest, FoldersNamedLikeAStagingFolderAreNotDeleted) {
  // Regression: the staging folder was "<out>.partial", removed before the run: `--out mywork`
  // deleted the user's mywork.partial/, and scene `x` the results of a scene named `x.partial`.
  scratch_folder dir;
  fs::create_directory(dir / "mywork.partial");
  write_text(dir / "mywork.partial" / "notes.txt", "mine");
  write_text(dir / "s.toml", tiny_scene("s", "", false));
  const command_result r = run_quadmc(dir, {"run", (dir / "s.toml").string(), "--out", "mywork"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  EXPECT_EQ(read_text(dir / "mywork.partial" / "notes.txt"), "mine");

  write_text(dir / "xp.toml", tiny_scene("x.partial", "scene x.partial", false));
  write_text(dir / "x.toml", tiny_scene("x", "scene x", false));
  ASSERT_EQ(run_quadmc(dir, {"run", (dir / "xp.toml").string()}).exit_status, 0);
  const command_result x = run_quadmc(dir, {"run", (dir / "x.toml").string()});
  ASSERT_EQ(x.exit_status, 0) << describe(x);
  ASSERT_TRUE(fs::exists(dir / "results" / "x.partial" / "README.md"));
  EXPECT_NE(read_text(dir / "results" / "x.partial" / "README.md").find("scene x.partial"),
            std::string::npos);
  EXPECT_EQ(fs::exists(dir / "results" / "x" / "README.md"), true);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"mywork", "mywork.partial", "results",
                                                     "s.toml", "x.toml", "xp.toml"}));
}

TEST(OutputFolderTest, OnlyRegularFilesCountAsResultsFiles) {
  // Regression: a subfolder named "figures.svg" passed the "nothing but results files" check,
  // and `--out docs` deleted docs/figures.svg/thesis.tex.
  scratch_folder dir;
  write_text(dir / "s.toml", tiny_scene("s", "", false));
  fs::create_directories(dir / "docs" / "figures.svg");
  write_text(dir / "docs" / "figures.svg" / "thesis.tex", "chapter 1");
  write_text(dir / "docs" / "README.md", "my notes");
  // A symlink named like a plot is not a results file either (its target is somebody's).
  fs::create_directory(dir / "linked");
  write_text(dir / "elsewhere.svg", "<svg/>");
  fs::create_symlink(dir / "elsewhere.svg", dir / "linked" / "plot.svg");
  for (const auto& [out, entry] : std::vector<std::pair<std::string, std::string>>{
           {"docs", "figures.svg"}, {"linked", "plot.svg"}}) {
    const command_result r = run_quadmc(dir, {"run", (dir / "s.toml").string(), "--out", out});
    EXPECT_EQ(r.exit_status, 1) << describe(r);
    EXPECT_EQ(line_count(r.err), 1u) << describe(r);
    EXPECT_NE(r.err.find("'" + entry + "'"), std::string::npos) << describe(r);
    EXPECT_EQ(r.out, "") << "refused before the run\n" << describe(r);
  }
  EXPECT_EQ(read_text(dir / "docs" / "figures.svg" / "thesis.tex"), "chapter 1");
  EXPECT_EQ(read_text(dir / "docs" / "README.md"), "my notes");
  EXPECT_EQ(read_text(dir / "linked" / "plot.svg"), "<svg/>");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"docs", "elsewhere.svg", "linked", "s.toml"}));
}

TEST(OutputFolderTest, FilesWithARunsNamesAreNotResultsWithoutARunsMetaCsv) {
  // Regression: a folder holding only names a run writes was taken for old results and replaced:
  // `--out art` deleted art/diagram1.svg, `--out notes` a hand-written README.md and logo.svg.
  // Every run writes meta.csv, so a folder without one that quadmc wrote is somebody's.
  scratch_folder dir;
  write_text(dir / "s.toml", tiny_scene("s", "", false));
  fs::create_directory(dir / "art");
  write_text(dir / "art" / "diagram1.svg", "<svg/>");
  fs::create_directory(dir / "notes");
  write_text(dir / "notes" / "README.md", "my notes");
  write_text(dir / "notes" / "logo.svg", "<svg/>");
  fs::create_directory(dir / "fake");
  write_text(dir / "fake" / "README.md", "mine");
  write_text(dir / "fake" / "meta.csv", "author,year\nme,2026\n");
  std::vector<std::map<std::string, std::string>> before;
  for (const char* folder : {"art", "notes", "fake"}) before.push_back(snapshot(dir / folder));
  for (const auto& [out, reason] : std::vector<std::pair<std::string, std::string>>{
           {"art", "no meta.csv"}, {"notes", "no meta.csv"}, {"fake", "meta.csv is not one"}}) {
    const command_result r = run_quadmc(dir, {"run", (dir / "s.toml").string(), "--out", out});
    EXPECT_EQ(r.exit_status, 1) << describe(r);
    EXPECT_EQ(line_count(r.err), 1u) << describe(r);
    EXPECT_NE(r.err.find(reason), std::string::npos) << describe(r);
    EXPECT_EQ(r.out, "") << "refused before the run\n" << describe(r);
  }
  EXPECT_EQ(snapshot(dir / "art"), before[0]);
  EXPECT_EQ(snapshot(dir / "notes"), before[1]);
  EXPECT_EQ(snapshot(dir / "fake"), before[2]);

  // A run's own folder, markdown only, is still replaced by the next run: meta.csv is written
  // with any output.
  write_text(dir / "md.toml", tiny_scene("md", "first", false) + "csv = false\n");
  ASSERT_EQ(run_quadmc(dir, {"run", (dir / "md.toml").string(), "--out", "md"}).exit_status, 0);
  EXPECT_TRUE(fs::exists(dir / "md" / "meta.csv"));
  const command_result again = run_quadmc(dir, {"run", (dir / "md.toml").string(), "--out", "md"});
  EXPECT_EQ(again.exit_status, 0) << describe(again);
}

TEST(OutputFolderTest, RefusalsSayWhatTheEntryIs) {
  // Regression: a FIFO named convergence.csv was "a file a run does not write" (it is a name a
  // run writes, in a form it does not), and a symlink loop "did not exist".
  scratch_folder dir;
  write_text(dir / "s.toml", tiny_scene("s", "", false));
  fs::create_directory(dir / "piped");
  ASSERT_EQ(::mkfifo((dir / "piped" / "convergence.csv").c_str(), 0600), 0);
  fs::create_symlink(dir / "loop", dir / "loop");
  for (const auto& [out, says] : std::vector<std::pair<std::string, std::string>>{
           {"piped", "'convergence.csv', a FIFO where a run writes a regular file"},
           {"loop", "a symlink loop"}}) {
    const command_result r = run_quadmc(dir, {"run", (dir / "s.toml").string(), "--out", out});
    EXPECT_EQ(r.exit_status, 1) << describe(r);
    EXPECT_EQ(line_count(r.err), 1u) << describe(r);
    EXPECT_NE(r.err.find(says), std::string::npos) << "expected '" << says << "'\n" << describe(r);
  }
}

TEST(OutputFolderTest, TheCurrentFolderAndItsParentsAreNeverReplaced) {
  // Regression: `--out .` in a folder holding only a README.md replaced the working directory.
  // Refused even when the folder is a run's results (`cd results/x && quadmc run … --out .`).
  scratch_folder dir;
  write_text(dir / "s.toml", tiny_scene("s", "", false));
  ASSERT_EQ(run_quadmc(dir, {"run", (dir / "s.toml").string(), "--out", "sub"}).exit_status, 0);
  const auto before = snapshot(dir / "sub");
  for (const std::string out : {".", "..", "./"}) {
    const command_result r = run_command(
        dir, {"/bin/sh", "-c",
              "cd sub && exec " + std::string(QUADMC_CLI) + " run ../s.toml --out " + out});
    EXPECT_EQ(r.exit_status, 1) << out << "\n" << describe(r);
    EXPECT_EQ(line_count(r.err), 1u) << describe(r);
    EXPECT_NE(r.err.find("the current folder or one of its parents"), std::string::npos)
        << describe(r);
  }
  EXPECT_EQ(snapshot(dir / "sub"), before);
}

TEST(OutputFolderTest, AFileAddedDuringTheRunIsNotDeleted) {
  // Regression: the folder was checked only before the run; a file saved into it meanwhile was
  // deleted with the old results.
  scratch_folder dir;
  scratch_folder logs;
  write_text(logs / "old.toml", tiny_scene("s", "old results", false));
  write_text(logs / "new.toml", tiny_scene("s", "new results", true));
  ASSERT_EQ(run_quadmc(dir, {"run", (logs / "old.toml").string(), "--out", "out"}).exit_status, 0);
  const auto old_results = snapshot(dir / "out");
  // While the run plots, the user saves a file into the folder.
  write_matplotlib_stand_in(
      logs / "python", "open('" + (dir / "out" / "notes.txt").string() + "', 'w').write('mine')");
  const command_result r = run_quadmc_with(dir.path(), logs.path(),
                                           {"run", (logs / "new.toml").string(), "--out", "out"},
                                           {"PYTHONPATH=" + (logs / "python").string()});
  EXPECT_EQ(r.exit_status, 1) << describe(r);
  EXPECT_EQ(line_count(r.err), 1u) << describe(r);
  EXPECT_NE(r.err.find("'notes.txt'"), std::string::npos) << describe(r);
  ASSERT_TRUE(fs::exists(dir / "out" / "notes.txt"));
  EXPECT_EQ(read_text(dir / "out" / "notes.txt"), "mine");
  auto expected = old_results;
  expected["notes.txt"] = "mine";
  EXPECT_EQ(snapshot(dir / "out"), expected) << "the old results are untouched";
  // The new results are kept where the message says.
  const fs::path kept = after(r.err, "the new results are kept in ", "\n");
  ASSERT_FALSE(kept.empty()) << describe(r);
  EXPECT_NE(read_text(kept / "README.md").find("new results"), std::string::npos);
  EXPECT_TRUE(fs::exists(kept / quadmc::convergence_plot_file("exp", 1)));
}

TEST(OutputFolderTest, OldResultsStayWholeWhenTheyCannotBeRemoved) {
  // Regression: the old folder was deleted file by file before the new one was moved in; when
  // one file could not be deleted, part of the old results was gone and the new ones discarded.
  // Here the old folder becomes read-only during the run (so its files cannot be unlinked): the
  // new results must be in place, the old ones whole beside them, and a warning must say where.
  if (!permission_tests_possible()) GTEST_SKIP() << "root without CAP_SETUID: no permission test";
  scratch_folder dir;
  scratch_folder logs;
  write_text(logs / "old.toml", tiny_scene("s", "old results", false));
  write_text(logs / "new.toml", tiny_scene("s", "new results", true));
  write_matplotlib_stand_in(logs / "python", "os.chmod('" + (dir / "out").string() + "', 0o555)");
  give_to_unprivileged_user(dir.path());
  give_to_unprivileged_user(logs.path());
  ASSERT_EQ(run_quadmc_with(dir.path(), logs.path(),
                            {"run", (logs / "old.toml").string(), "--out", "out"}, {}, true)
                .exit_status,
            0);
  const auto old_results = snapshot(dir / "out");

  const command_result r = run_quadmc_with(dir.path(), logs.path(),
                                           {"run", (logs / "new.toml").string(), "--out", "out"},
                                           {"PYTHONPATH=" + (logs / "python").string()}, true);
  EXPECT_EQ(r.exit_status, 0) << describe(r);
  EXPECT_NE(read_text(dir / "out" / "README.md").find("new results"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "out" / quadmc::convergence_plot_file("exp", 1)));
  EXPECT_EQ(line_count(r.err), 1u) << describe(r);
  EXPECT_EQ(r.err.rfind("quadmc: warning: ", 0), 0u) << describe(r);
  const fs::path left = after(r.err, "are left in ", " (");
  ASSERT_FALSE(left.empty()) << describe(r);
  EXPECT_EQ(left.parent_path(), dir.path());
  EXPECT_EQ(snapshot(left), old_results) << "the old results are whole";
  fs::permissions(left, fs::perms::owner_all);  // so that the scratch folder can be removed
}

TEST(OutputFolderTest, ARunThatWritesNothingLeavesTheFolderAlone) {
  // Regression: with csv, markdown and plots all off, the run still replaced the folder, by an
  // empty one.
  scratch_folder dir;
  write_text(dir / "s.toml", tiny_scene("s", "", false));
  ASSERT_EQ(run_quadmc(dir, {"run", (dir / "s.toml").string(), "--out", "out"}).exit_status, 0);
  const auto before = snapshot(dir / "out");
  write_text(dir / "off.toml",
             "name = \"off\"\n[[integrand]]\nfamily = \"exp\"\n[[method]]\nname = \"simpson\"\n"
             "[budget]\nN = [8, 16, 32]\n[output]\ncsv = false\nmarkdown = false\nplots = false\n");
  const command_result r = run_quadmc(dir, {"run", (dir / "off.toml").string(), "--out", "out"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  EXPECT_NE(r.out.find("wrote nothing"), std::string::npos) << describe(r);
  EXPECT_EQ(r.out.find("wrote " + (dir / "out").string()), std::string::npos) << describe(r);
  EXPECT_EQ(snapshot(dir / "out"), before);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"off.toml", "out", "s.toml"}));
}

TEST(OutputFolderTest, OutThroughASymlinkReplacesTheFolderAndKeepsTheLink) {
  // Regression: the link itself was replaced by a new folder, leaving the folder it pointed to
  // with the old results.
  scratch_folder dir;
  write_text(dir / "old.toml", tiny_scene("s", "old results", false));
  write_text(dir / "new.toml", tiny_scene("s", "new results", false));
  ASSERT_EQ(run_quadmc(dir, {"run", (dir / "old.toml").string(), "--out", "real"}).exit_status, 0);
  fs::create_directory_symlink("real", dir / "link");
  const command_result r = run_quadmc(dir, {"run", (dir / "new.toml").string(), "--out", "link"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  ASSERT_TRUE(fs::is_symlink(dir / "link"));
  EXPECT_EQ(fs::read_symlink(dir / "link"), "real");
  EXPECT_NE(read_text(dir / "real" / "README.md").find("new results"), std::string::npos);
  EXPECT_NE(r.out.find("wrote " + (dir / "real").string() + " (through the link"),
            std::string::npos)
      << describe(r);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"link", "new.toml", "old.toml", "real"}));

  // A link to nothing is refused, not replaced.
  fs::create_directory_symlink("nowhere", dir / "dangling");
  const command_result d =
      run_quadmc(dir, {"run", (dir / "new.toml").string(), "--out", "dangling"});
  EXPECT_EQ(d.exit_status, 1) << describe(d);
  EXPECT_EQ(line_count(d.err), 1u) << describe(d);
  EXPECT_NE(d.err.find("nowhere"), std::string::npos) << describe(d);
  EXPECT_TRUE(fs::is_symlink(dir / "dangling"));
  EXPECT_FALSE(fs::exists(dir / "nowhere"));
}

TEST(OutputFolderTest, AFailedRunRemovesWhatItCreatedAndNothingElse) {
  // eˣ on [700, 710] overflows in the first cell (non_finite_test.cpp): the run fails after the
  // staging folder, the lock file and the results/ parent were created. It removes those, and
  // only those: a folder the user keeps in results/ stays.
  const std::string overflow =
      "name = \"overflow\"\n[[integrand]]\nfamily = \"exp\"\nlower = 700.0\nupper = 710.0\n"
      "[[method]]\nname = \"simpson\"\n[budget]\nN = [8, 16]\n[output]\nplots = false\n";
  scratch_folder dir;
  write_text(dir / "s.toml", overflow);
  const command_result fresh = run_quadmc(dir, {"run", (dir / "s.toml").string()});
  EXPECT_EQ(fresh.exit_status, 1) << describe(fresh);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"s.toml"}) << "results/ was this run's";

  fs::create_directories(dir / "results" / "mine");
  const command_result kept = run_quadmc(dir, {"run", (dir / "s.toml").string()});
  EXPECT_EQ(kept.exit_status, 1) << describe(kept);
  std::vector<std::string> in_results;
  for (const auto& e : fs::directory_iterator(dir / "results")) {
    in_results.push_back(e.path().filename().string());
  }
  EXPECT_EQ(in_results, std::vector<std::string>{"mine"});
}

}  // namespace
}  // namespace quadmc_cli_test
