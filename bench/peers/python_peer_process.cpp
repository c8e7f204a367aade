#include "python_peer_process.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

extern char** environ;

namespace quadmc::peers {

python_peer_process::python_peer_process(std::vector<std::string> argv, std::string python_path)
    : argv_(std::move(argv)), python_path_(std::move(python_path)) {}

python_peer_process::~python_peer_process() {
  // End of input ends the child; then reap it.
  if (to_child_ >= 0) close(to_child_);
  if (from_child_ >= 0) close(from_child_);
  if (pid_ > 0) {
    int status = 0;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
  }
}

std::string python_peer_process::name() const {
  return argv_.size() > 1 ? argv_[1] : argv_.front();
}

void python_peer_process::start() {
  int in[2], out[2];
  if (pipe2(in, O_CLOEXEC) != 0) {
    throw std::runtime_error(
        fmt::format("cannot start {}: pipe: {}", name(), std::strerror(errno)));
  }
  if (pipe2(out, O_CLOEXEC) != 0) {
    close(in[0]);
    close(in[1]);
    throw std::runtime_error(
        fmt::format("cannot start {}: pipe: {}", name(), std::strerror(errno)));
  }
  posix_spawn_file_actions_t actions;
  posix_spawnattr_t attributes;
  posix_spawn_file_actions_init(&actions);
  posix_spawnattr_init(&attributes);
  posix_spawn_file_actions_adddup2(&actions, in[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  sigaddset(&defaults, SIGPIPE);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setsigdefault(&attributes, &defaults);

  // The environment with PYTHONPATH replaced (bytecode off: nothing written beside the sources).
  std::vector<std::string> environment;
  for (char** e = environ; *e != nullptr; ++e) {
    if (std::strncmp(*e, "PYTHONPATH=", 11) != 0 &&
        std::strncmp(*e, "PYTHONDONTWRITEBYTECODE=", 24) != 0) {
      environment.emplace_back(*e);
    }
  }
  environment.push_back("PYTHONPATH=" + python_path_);
  environment.push_back("PYTHONDONTWRITEBYTECODE=1");
  std::vector<char*> env, args;
  for (std::string& e : environment) env.push_back(e.data());
  env.push_back(nullptr);
  for (std::string& a : argv_) args.push_back(a.data());
  args.push_back(nullptr);

  const int started = posix_spawn(&pid_, args[0], &actions, &attributes, args.data(), env.data());
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  close(in[0]);
  close(out[1]);
  if (started != 0) {
    close(in[1]);
    close(out[0]);
    pid_ = -1;
    throw std::runtime_error(
        fmt::format("cannot start `{}`: {} (install python3 with ./run.sh deps)", argv_.front(),
                    std::strerror(started)));
  }
  to_child_ = in[1];
  from_child_ = out[0];
  const std::string ready = read_line();
  if (ready.rfind("ready", 0) != 0) {
    throw std::runtime_error(fmt::format("{} did not start: {}", name(), ready));
  }
}

std::string python_peer_process::read_line() {
  for (;;) {
    if (const auto end = pending_.find('\n'); end != std::string::npos) {
      std::string line = pending_.substr(0, end);
      pending_.erase(0, end + 1);
      return line;
    }
    char buffer[4096];
    const ssize_t got = read(from_child_, buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) {
      throw std::runtime_error(fmt::format("{} ended without answering{}", name(),
                                           pending_.empty() ? "" : ": " + pending_));
    }
    pending_.append(buffer, static_cast<std::size_t>(got));
  }
}

std::string python_peer_process::request(const std::string& line) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (pid_ < 0) start();
  const std::string text = line + '\n';
  for (std::size_t done = 0; done < text.size();) {
    const ssize_t put = write(to_child_, text.data() + done, text.size() - done);
    if (put < 0 && errno == EINTR) continue;
    if (put <= 0) {
      throw std::runtime_error(fmt::format("{} stopped reading: {}", name(), std::strerror(errno)));
    }
    done += static_cast<std::size_t>(put);
  }
  return read_line();
}

}  // namespace quadmc::peers
