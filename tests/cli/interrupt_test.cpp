// End-to-end tests of SIGINT and SIGTERM during `quadmc run`
// (lib/include/quadmc/report/interruption.hpp): the plot process must not outlive the command, this
// run's staging folder and lock must go, the old results must stay as they were, and the exit
// status must be 128 + signal.
//
// Use these for the command's behaviour under a signal. The moment of the signal is fixed by a
// stand-in matplotlib that announces the plot step and then sleeps (quadmc_process.hpp), so the
// signal always arrives while the plot process runs; nothing depends on timing.
#include "quadmc_process.hpp"

#include <signal.h>

#include <gtest/gtest.h>

#include <cerrno>
#include <string>
#include <vector>

namespace quadmc_cli_test {
namespace {

void expect_clean_interrupt(int signal, const std::string& signal_name) {
  scratch_folder dir;
  scratch_folder logs;
  write_text(logs / "old.toml", tiny_scene("s", "old results", false));
  write_text(logs / "new.toml", tiny_scene("s", "new results", true));
  ASSERT_EQ(run_quadmc(dir, {"run", (logs / "old.toml").string(), "--out", "out"}).exit_status, 0);
  const auto old_results = snapshot(dir / "out");

  const fs::path pid_file = logs / "plot.pid";
  write_matplotlib_stand_in(logs / "python",
                            python_write_marker(pid_file, "str(os.getpid())") + "\ntime.sleep(600)",
                            false);
  auto run = start_quadmc(dir.path(), logs.path(), "run",
                          {"run", (logs / "new.toml").string(), "--out", "out"},
                          {"PYTHONPATH=" + (logs / "python").string()});
  ASSERT_TRUE(wait_for_file(pid_file)) << "the run never reached its plot step";
  const pid_t plot = std::stoi(read_text(pid_file));
  run->signal(signal);
  const command_result r = run->wait();

  const bool plot_gone = ::kill(plot, 0) != 0 && errno == ESRCH;
  if (!plot_gone) ::kill(plot, SIGKILL);  // do not leave it sleeping for ten minutes
  EXPECT_TRUE(plot_gone) << "the plot process " << plot << " outlived the command";
  EXPECT_EQ(r.exit_status, 128 + signal) << describe(r);
  EXPECT_EQ(line_count(r.err), 1u) << describe(r);
  EXPECT_EQ(r.err.rfind("quadmc: interrupted by " + signal_name, 0), 0u) << describe(r);
  // No staging folder, no lock file, and the old results as they were.
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out"});
  EXPECT_EQ(snapshot(dir / "out"), old_results);
}

TEST(InterruptTest, SigintDuringPlottingStopsThePlotAndKeepsTheOldResults) {
  expect_clean_interrupt(SIGINT, "SIGINT");
}

TEST(InterruptTest, SigtermDuringPlottingStopsThePlotAndKeepsTheOldResults) {
  expect_clean_interrupt(SIGTERM, "SIGTERM");
}

}  // namespace
}  // namespace quadmc_cli_test
