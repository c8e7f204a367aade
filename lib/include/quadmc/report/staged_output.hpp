// The one lifecycle of every command that writes a results folder (`quadmc run`, `gallery`,
// `render`, and write_results for library users): stage the folder before any work, write into
// the staging folder, draw the pictures in a child process, commit, and on Ctrl-C or SIGTERM at
// any point kill the child and remove only what this run created.
//
// It joins the three services below it, each of which keeps its own rules:
//  - results_staging.hpp: which folder, the lock, the checks before the run, the atomic replace,
//    never deleting what the run did not create;
//  - interruption.hpp: the signal thread's cleanup, kept in step with the stage reached (before
//    commit it removes the staging folder; after, it says the results were already written);
//  - subprocess.hpp: the plot script, registered so that a signal kills it with the command.
// The signal handling is active only in a program that called interruption::install() (the
// quadmc command does, first thing); without it a staged_output still stages, locks, commits and
// cleans up on exceptions.
//
// Use one per folder-writing run, constructed before the run (every refusal then costs nothing)
// and destroyed at its end, whatever ends it. Not for runs that write nothing (all outputs off),
// nor for reading results (results_csv.hpp).
#pragma once

#include "quadmc/report/results_folder.hpp"
#include "quadmc/report/results_staging.hpp"

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace quadmc {

class staged_output {
 public:
  // `kind` names the run in the interruption messages ("run", "gallery", "render"). The other
  // arguments are results_staging's: `parameter` and `given` name the folder in messages
  // ("--out", "mine/"), `folder` is results_folder_path's, `files` the names the run will write.
  // Throws quadmc::invalid_argument on any refusal, having removed whatever it created.
  staged_output(std::string kind, std::string parameter, std::string given,
                const std::filesystem::path& folder, const std::vector<std::string>& files,
                results_file_predicate is_results_file = &is_results_file_name);
  staged_output(const staged_output&) = delete;
  staged_output& operator=(const staged_output&) = delete;
  // Removes the staging folder unless committed, and releases the lock, under the interruption
  // mutex: whatever ends the run, the signal thread and this one never both clean up.
  ~staged_output();

  // Where this run writes until commit().
  const std::filesystem::path& staging() const noexcept;

  // Calls write(staging()) as one step a signal does not cut in half (interruption::hold).
  void write(const std::function<void(const std::filesystem::path&)>& write);

  // Runs argv (e.g. plot_command_line(script, staging())) and waits; a signal kills it with the
  // command. Throws std::runtime_error when it fails.
  void run_child(const std::vector<std::string>& argv);

  struct committed {
    std::string written;  // "wrote /abs/folder" (and " (through the link L)")
    std::string warning;  // results_staging::commit's, empty when the old results went cleanly
  };
  // Moves the staged results into place. Throws as results_staging::commit does.
  committed commit();

 private:
  std::string kind_;
  std::unique_ptr<results_staging> staging_;
};

}  // namespace quadmc
