// SIGINT/SIGTERM handling of a program that writes results (the `quadmc` command); the design is
// in interruption.hpp.
#include "quadmc/report/interruption.hpp"

#include <fmt/format.h>
#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <string>
#include <thread>
#include <utility>

namespace quadmc::interruption {
namespace {

// Allocated once and never freed: the waiting thread may still use it while the process exits.
struct shared_state {
  std::mutex mutex;
  std::function<std::string()> cleanup;  // guarded by mutex
  std::atomic<pid_t> child{0};
};

shared_state& state() {
  static shared_state* s = new shared_state;
  return *s;
}

sigset_t handled_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

void kill_child(pid_t child) {
  if (child <= 0) return;
  ::kill(-child, SIGKILL);  // its process group: the script and anything it started
  ::kill(child, SIGKILL);
}

std::atomic<bool>& quiet() {
  static std::atomic<bool> value{false};
  return value;
}

[[noreturn]] void on_signal(int signal) {
  shared_state& s = state();
  // The mutex before the kill, never after: the main thread, waiting for the child without the
  // mutex, wakes when the child dies and takes the mutex to clear the child, so a child killed
  // first let it win the mutex, report the plot as failed (exit status 137) and exit 1 before
  // this thread could clean up and exit 128 + signal. Holding the mutex first, the kill makes
  // the main thread stop at that step. It is never held while a child runs, so the kill is not
  // delayed past the short step (a write, a progress-bar update) the main thread may be in.
  s.mutex.lock();  // never unlocked: this thread ends the process
  const pid_t child = s.child.load();
  kill_child(child);
  // Reap it, so it is gone before we are; ECHILD when the main thread reaped it first.
  if (child > 0) ::waitpid(child, nullptr, 0);
  std::string done;
  try {
    if (s.cleanup) done = s.cleanup();
  } catch (...) {
    done = "could not remove everything this run created";
  }
  if (!quiet().load()) {
    // A progress bar may be drawn on the terminal without a newline: start on a clean line.
    if (::isatty(STDERR_FILENO) != 0) std::fputs("\r\033[K", stderr);
    fmt::print(stderr, "quadmc: interrupted by {}{}{}\n", signal == SIGINT ? "SIGINT" : "SIGTERM",
               done.empty() ? "" : "; ", done);
    std::fflush(stderr);
  }
  ::_exit(128 + signal);
}

}  // namespace

void install() {
  ::signal(SIGPIPE, SIG_IGN);
  const sigset_t set = handled_signals();
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  std::thread([set] {
    int signal = 0;
    while (sigwait(&set, &signal) != 0) {
    }
    on_signal(signal);
  }).detach();
}

void set_quiet(bool value) {
  quiet().store(value);
}

std::unique_lock<std::mutex> hold() {
  return std::unique_lock<std::mutex>(state().mutex);
}

void set_cleanup(std::function<std::string()> cleanup) {
  state().cleanup = std::move(cleanup);
}

void set_child_process(pid_t pid) {
  state().child.store(pid);
}

}  // namespace quadmc::interruption
