// A shell command's whole output, for the peers that run in a Python subprocess (scipy_qmc.py,
// python_module_speed.py): started with popen, its stdout (with stderr joined by the command's
// own "2>&1") read to the end, and its exit status judged once, so that each caller only says
// what a failure means to it (a thrown error, a skipped section).
#pragma once

#include <fmt/format.h>

#include <sys/wait.h>
#include <cstdio>
#include <optional>
#include <string>

namespace quadmc::peers {

struct shell_output {
  std::string text;     // everything the command wrote
  std::string failure;  // "" when it exited 0; else "`command` failed (exit status N): first line"
};

// nullopt when the shell cannot be started at all.
inline std::optional<shell_output> run_shell(const std::string& command) {
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return std::nullopt;
  shell_output out;
  char buffer[1 << 16];
  for (std::size_t got; (got = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) {
    out.text.append(buffer, got);
  }
  const int status = pclose(pipe);
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    out.failure = fmt::format("`{}` failed (exit status {}): {}", command,
                              WIFEXITED(status) ? WEXITSTATUS(status) : -1,
                              out.text.substr(0, out.text.find('\n')));
  }
  return out;
}

}  // namespace quadmc::peers
