#include "subprocess.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

extern char** environ;

namespace quadmc_cli {

void run_subprocess(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  args.reserve(argv.size() + 1);
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int started = posix_spawn(&pid, args[0], nullptr, nullptr, args.data(), environ);
  if (started != 0) {
    throw std::runtime_error(fmt::format("cannot start `{}`: {} (install it with ./run.sh deps)",
                                         argv[0], std::strerror(started)));
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("waitpid failed for " + argv[0]);
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw std::runtime_error(fmt::format("`{}` failed (exit status {})", fmt::join(argv, " "),
                                         WIFEXITED(status) ? WEXITSTATUS(status) : -1));
  }
}

}  // namespace quadmc_cli
