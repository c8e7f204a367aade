// Peak resident memory of one run, measured in a fresh child process.
//
// Why a child, and why VmHWM rather than getrusage: ru_maxrss is a high-water mark that never
// goes down, so in this process every reading after the first big run would repeat it; and
// Linux carries ru_maxrss over fork() and execve() (the child starts with the parent's mark:
// fs/exec.c, setmax_mm_hiwater_rss), so even a child's ru_maxrss from wait4() would report the
// parent's peak. VmHWM in /proc/self/status is the high-water mark of the address space itself,
// which execve() creates afresh. So the child exec()s this same program (/proc/self/exe) with the
// arguments of one measurement, runs it, and prints its own VmHWM (peak_rss_kib()) on stdout; the
// parent reads it through a pipe. The child's baseline (libraries, no integration) is measured
// the same way and reported beside, so the memory a method adds is visible. Linux only.
//
// Used by both the peers program (`quadmc_peers --one …`) and the Google Benchmark binary
// (`integrators_bench --peak-rss-child …`); each handles its child arguments in main() before
// anything else runs.
#pragma once

#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace quadmc::bench {

// VmHWM of this process in KiB (peak resident set since its last execve), or −1 if unreadable.
inline long peak_rss_kib() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
  }
  return -1;
}

// Runs /proc/self/exe with `arguments` (argv[1…]); the child must print its peak_rss_kib() and
// nothing before it on stdout, and exit with status 0. Returns that number; throws otherwise.
inline long child_peak_rss_kib(const std::vector<std::string>& arguments) {
  std::vector<std::string> args{"/proc/self/exe"};
  args.insert(args.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  int fd[2];
  if (pipe(fd) != 0) throw std::runtime_error("pipe failed");
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    close(fd[0]);
    dup2(fd[1], STDOUT_FILENO);
    close(fd[1]);
    execv(argv[0], argv.data());
    _exit(127);
  }
  close(fd[1]);
  std::string output;
  char buffer[256];
  for (ssize_t k; (k = read(fd[0], buffer, sizeof buffer)) > 0;)
    output.append(buffer, static_cast<std::size_t>(k));
  close(fd[0]);
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) throw std::runtime_error("waitpid failed");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || output.empty()) {
    std::string command = "/proc/self/exe";
    for (const auto& a : arguments) command += " " + a;
    throw std::runtime_error("peak-RSS child failed: " + command);
  }
  return std::stol(output);
}

}  // namespace quadmc::bench
