#include "quadmc/report/subprocess.hpp"

#include "quadmc/report/interruption.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

extern char** environ;

namespace quadmc {

namespace {

// posix_spawn's attribute and file-action objects, destroyed on every path.
struct spawn_setup {
  posix_spawnattr_t attributes;
  posix_spawn_file_actions_t actions;
  spawn_setup() {
    posix_spawnattr_init(&attributes);
    posix_spawn_file_actions_init(&actions);
  }
  ~spawn_setup() {
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
  }
  spawn_setup(const spawn_setup&) = delete;
  spawn_setup& operator=(const spawn_setup&) = delete;
};

}  // namespace

int subprocess_status(const std::vector<std::string>& argv, child_output output) {
  std::vector<char*> args;
  args.reserve(argv.size() + 1);
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);

  spawn_setup setup;
  // Its own process group (so that killing the group reaches whatever it starts), an empty
  // signal mask and default actions: what the command blocked or ignored is its own business.
  sigset_t none;
  sigemptyset(&none);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  sigaddset(&defaults, SIGPIPE);
  posix_spawnattr_setflags(&setup.attributes,
                           POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  posix_spawnattr_setpgroup(&setup.attributes, 0);
  posix_spawnattr_setsigmask(&setup.attributes, &none);
  posix_spawnattr_setsigdefault(&setup.attributes, &defaults);
  posix_spawn_file_actions_addopen(&setup.actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&setup.actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  if (output == child_output::none) {
    posix_spawn_file_actions_addopen(&setup.actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  }

  pid_t pid = 0;
  {
    // Registered before a signal can be handled: the waiting thread needs the mutex first.
    const auto held = interruption::hold();
    const int started =
        posix_spawn(&pid, args[0], &setup.actions, &setup.attributes, args.data(), environ);
    if (started != 0) {
      throw std::runtime_error(fmt::format("cannot start `{}`: {} (install it with ./run.sh deps)",
                                           argv[0], std::strerror(started)));
    }
    interruption::set_child_process(pid);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      const int error = errno;
      const auto held = interruption::hold();
      interruption::set_child_process(0);
      throw std::runtime_error(
          fmt::format("waitpid failed for `{}`: {}", argv[0], std::strerror(error)));
    }
  }
  {
    const auto held = interruption::hold();
    interruption::set_child_process(0);
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

void run_subprocess(const std::vector<std::string>& argv) {
  const int status = subprocess_status(argv, child_output::errors_only);
  if (status != 0) {
    throw std::runtime_error(
        fmt::format("`{}` failed (exit status {})", fmt::join(argv, " "), status));
  }
}

}  // namespace quadmc
