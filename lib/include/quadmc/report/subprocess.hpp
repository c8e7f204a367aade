// Runs a helper program (the plot script, the matplotlib check) and waits for it.
//
// The child gets a process group of its own and default signal handling (the command blocks
// SIGINT/SIGTERM and ignores SIGPIPE for itself, interruption.hpp), and is registered with
// interruption.hpp so that Ctrl-C kills it with the command instead of leaving it running.
#pragma once

#include <string>
#include <vector>

namespace quadmc {

// Where the child's output goes; its stdin is always /dev/null.
enum class child_output {
  errors_only,  // stdout to /dev/null, stderr shown: the plot script, whose stdout would only
                // repeat what the command says (and fail on a full or closed stdout)
  none,         // both to /dev/null: a check whose exit status is the answer
};

// Runs argv[0] with arguments argv[1…] (no shell, so no quoting issues) and waits. Returns its
// exit status, 128 + the signal number when a signal ended it. Throws std::runtime_error naming
// the program if it cannot start.
int subprocess_status(const std::vector<std::string>& argv, child_output output);

// As subprocess_status with errors_only; throws std::runtime_error naming the command when it
// exits non-zero.
void run_subprocess(const std::vector<std::string>& argv);

}  // namespace quadmc
