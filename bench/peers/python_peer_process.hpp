// A Python peer that answers requests one line at a time (scipy_qmc_quad.py): started once, on the
// first request, and kept for the run, since starting the interpreter and importing scipy takes
// about half a second, far longer than most cells.
//
// The child is started without a shell (posix_spawn of argv[0]) with PYTHONPATH set to the given
// folder, its stdin and stdout on pipes, stderr shown, and default signal handling (the command
// blocks SIGINT/SIGTERM and ignores SIGPIPE for itself, report/interruption.hpp): Ctrl-C reaches
// it through the terminal's process group, and when the command ends for any reason the child
// reads end of input and exits. Its first line must start with "ready"; anything else (an import
// failure) is thrown with that line. request() sends one line and returns the one line answered,
// under a mutex: requests from the threads of a run take turns (one per cell, never per point).
// A child that dies or closes its output is reported with the program's name, not retried.
#pragma once

#include <sys/types.h>

#include <mutex>
#include <string>
#include <vector>

namespace quadmc::peers {

class python_peer_process {
 public:
  // argv: the interpreter and its arguments; python_path: PYTHONPATH for the child.
  python_peer_process(std::vector<std::string> argv, std::string python_path);
  ~python_peer_process();
  python_peer_process(const python_peer_process&) = delete;
  python_peer_process& operator=(const python_peer_process&) = delete;

  // Sends `line` (without its '\n') and returns the answer's line (without '\n'). Starts the
  // child first when it is not running. Throws std::runtime_error naming the script when it
  // cannot start, is not ready, or ends before answering.
  std::string request(const std::string& line);

 private:
  void start();  // with mutex_ held
  std::string read_line();
  std::string name() const;

  std::vector<std::string> argv_;
  std::string python_path_;
  std::mutex mutex_;
  pid_t pid_ = -1;
  int to_child_ = -1;
  int from_child_ = -1;
  std::string pending_;  // read past the last line answered
};

}  // namespace quadmc::peers
