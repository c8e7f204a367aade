// Running the `quadmc` command (or Python) from a test with more control than
// quadmc_command.hpp's run_quadmc: in the background (to signal it, or to start a second run
// while the first is busy), with added environment variables, output to chosen files
// (/dev/full included), and as an unprivileged user.
//
// Use it for the end-to-end tests of the results folder's rules, interruption and exit status.
// For a plain run, run_quadmc is simpler.
//
// Unprivileged: root ignores permission bits, so a test of "the folder is read-only" means
// nothing as root. With unprivileged = true a root test process runs the child as user and group
// 65534 (nobody), after give_to_unprivileged_user has handed it the scratch folder; as any other
// user the child runs as that user. permission_tests_possible() says whether either works.
// As nobody, the child cannot be the build tree's binary itself: a clone may sit below a folder
// only root can enter (/root is 0700 on Debian, and so is every mkdtemp folder), and then the
// exec fails. start_quadmc runs instead a copy laid out as an installed quadmc inside the logs
// folder (unprivileged_command), the same binary, which nobody can always reach.
//
// Stand-in matplotlib: write_matplotlib_stand_in puts a package named `matplotlib` in a folder
// that the child's PYTHONPATH puts first. Imported by bench/plot.py (sys.argv[0] ends in
// "plot.py"), it runs the test's Python code, then (if asked) hands over to the real matplotlib,
// so the plot step can be made to wait, fail or change the file system at a known moment without
// any test-only switch in the command. Imported any other way (`python3 -c 'import matplotlib'`,
// the command's check before a run) it is the real matplotlib; with fail_import every import is
// an ImportError.
#pragma once

#include "quadmc_command.hpp"

#include <fcntl.h>
#include <grp.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace quadmc_cli_test {

inline constexpr uid_t unprivileged_id = 65534;

struct process_options {
  fs::path working_directory;
  fs::path stdout_file;                  // required
  fs::path stderr_file;                  // required
  std::vector<std::string> environment;  // "NAME=value", added to (or replacing) the test's own
  bool unprivileged = false;
};

// A child process started at construction; wait() collects it. The destructor kills a child
// that was never waited for, so a failed assertion does not leave it running.
class child_process {
 public:
  child_process(const std::vector<std::string>& argv, const process_options& options)
      : options_(options) {
    if (options.stdout_file.empty() || options.stderr_file.empty()) {
      throw std::invalid_argument("child_process: stdout_file and stderr_file are required");
    }
    // Everything the child needs is built before fork: after it only async-signal-safe calls.
    std::vector<std::string> args = argv;
    std::vector<char*> cargs;
    for (auto& a : args) cargs.push_back(a.data());
    cargs.push_back(nullptr);
    std::vector<std::string> added = options.environment;
    // As nobody, matplotlib cannot write the root user's ~/.config and says so on stderr.
    if (options.unprivileged && ::geteuid() == 0) {
      added.push_back("MPLCONFIGDIR=" +
                      (options.stderr_file.parent_path() / ".matplotlib").string());
    }
    std::vector<std::string> env;
    for (char** e = environ; *e != nullptr; ++e) {
      const std::string entry = *e;
      const std::string name = entry.substr(0, entry.find('=') + 1);
      if (std::none_of(added.begin(), added.end(),
                       [&](const std::string& a) { return a.rfind(name, 0) == 0; })) {
        env.push_back(entry);
      }
    }
    env.insert(env.end(), added.begin(), added.end());
    std::vector<char*> cenv;
    for (auto& e : env) cenv.push_back(e.data());
    cenv.push_back(nullptr);
    const std::string out = options.stdout_file.string();
    const std::string err = options.stderr_file.string();
    const std::string cwd = options.working_directory.string();
    const bool drop = options.unprivileged && ::geteuid() == 0;

    pid_ = ::fork();
    if (pid_ < 0) throw std::system_error(errno, std::generic_category(), "fork");
    if (pid_ == 0) {
      const int in_fd = ::open("/dev/null", O_RDONLY);
      const int out_fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      const int err_fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (in_fd < 0 || out_fd < 0 || err_fd < 0) ::_exit(126);
      ::dup2(in_fd, STDIN_FILENO);
      ::dup2(out_fd, STDOUT_FILENO);
      ::dup2(err_fd, STDERR_FILENO);
      if (!cwd.empty() && ::chdir(cwd.c_str()) != 0) ::_exit(126);
      if (drop) {
        const gid_t group = unprivileged_id;
        if (::setgroups(1, &group) != 0 || ::setgid(unprivileged_id) != 0 ||
            ::setuid(unprivileged_id) != 0) {
          ::_exit(125);
        }
      }
      ::execve(cargs[0], cargs.data(), cenv.data());
      ::_exit(127);
    }
  }
  child_process(const child_process&) = delete;
  child_process& operator=(const child_process&) = delete;
  ~child_process() {
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }

  pid_t pid() const noexcept { return pid_; }
  void signal(int signal) const { ::kill(pid_, signal); }

  command_result wait() {
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0) {
      if (errno != EINTR) throw std::system_error(errno, std::generic_category(), "waitpid");
    }
    pid_ = -1;
    command_result r;
    r.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = options_.stdout_file == "/dev/full" ? "" : read_text(options_.stdout_file);
    r.err = read_text(options_.stderr_file);
    return r;
  }

 private:
  process_options options_;
  pid_t pid_ = -1;
};

// A copy of the command for a child run as nobody by a root test (see the header comment):
// `folder`/command/bin/quadmc with the plot scripts where an installed command finds them
// (QUADMC_INSTALLED_PLOT_SCRIPT, relative to the executable: bench/quadmc/plot_script.cpp), made
// once per folder. `folder` is a scratch folder handed to nobody, so nobody can reach the copy
// wherever the clone is; the copy stays root's, readable and executable by all.
inline fs::path unprivileged_command(const fs::path& folder) {
  const fs::path bin = folder / "command" / "bin";
  const fs::path command = bin / fs::path(QUADMC_CLI).filename();
  if (fs::exists(command)) return command;
  const fs::path scripts = (bin / QUADMC_INSTALLED_PLOT_SCRIPT).lexically_normal().parent_path();
  fs::create_directories(bin);
  fs::create_directories(scripts);
  fs::copy_file(QUADMC_CLI, command);
  for (const char* script : {"plot.py", "gallery.py", "render.py"}) {
    fs::copy_file(fs::path(QUADMC_SOURCE_DIR) / "bench" / script, scripts / script);
  }
  const auto everyone = fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                        fs::perms::others_read | fs::perms::others_exec;
  for (fs::path p = scripts; p != folder; p = p.parent_path()) fs::permissions(p, everyone);
  for (fs::path p = bin; p != folder; p = p.parent_path()) fs::permissions(p, everyone);
  fs::permissions(command, everyone);
  return command;
}

// `quadmc args…` in the background, output captured in `logs` (a folder of its own, so that the
// listing of the folder under test shows only what the command made there). As nobody (root
// test, unprivileged = true) the command is unprivileged_command(logs).
inline std::unique_ptr<child_process> start_quadmc(const fs::path& working_directory,
                                                   const fs::path& logs, const std::string& tag,
                                                   const std::vector<std::string>& args,
                                                   std::vector<std::string> environment = {},
                                                   bool unprivileged = false) {
  const bool as_nobody = unprivileged && ::geteuid() == 0;
  std::vector<std::string> argv{as_nobody ? unprivileged_command(logs).string()
                                          : std::string(QUADMC_CLI)};
  argv.insert(argv.end(), args.begin(), args.end());
  process_options options;
  options.working_directory = working_directory;
  options.stdout_file = logs / (tag + ".stdout");
  options.stderr_file = logs / (tag + ".stderr");
  options.environment = std::move(environment);
  options.unprivileged = unprivileged;
  return std::make_unique<child_process>(argv, options);
}

inline command_result run_quadmc_with(const fs::path& working_directory, const fs::path& logs,
                                      const std::vector<std::string>& args,
                                      std::vector<std::string> environment = {},
                                      bool unprivileged = false) {
  return start_quadmc(working_directory, logs, "run", args, std::move(environment), unprivileged)
      ->wait();
}

// Hands `folder` and everything in it to the unprivileged user (root only; otherwise the test
// user owns it already).
inline void give_to_unprivileged_user(const fs::path& folder) {
  if (::geteuid() != 0) return;
  auto give = [](const fs::path& p) {
    if (::lchown(p.c_str(), unprivileged_id, unprivileged_id) != 0) {
      throw std::system_error(errno, std::generic_category(), "lchown " + p.string());
    }
  };
  give(folder);
  for (const auto& e : fs::recursive_directory_iterator(folder)) give(e.path());
}

// Whether permission bits bind the command: true for a non-root test user, and for root when it
// can run a child as nobody (a container without CAP_SETUID cannot).
inline bool permission_tests_possible() {
  if (::geteuid() != 0) return true;
  const pid_t pid = ::fork();
  if (pid == 0) {
    const gid_t group = unprivileged_id;
    const bool ok = ::setgroups(1, &group) == 0 && ::setgid(unprivileged_id) == 0 &&
                    ::setuid(unprivileged_id) == 0 && ::geteuid() == unprivileged_id;
    ::_exit(ok ? 0 : 1);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// Waits until `file` exists (the stand-in's signal that the plot step has started). A deadline
// only so that a broken command fails the test instead of hanging it; nothing is asserted about
// how long it took.
inline bool wait_for_file(const fs::path& file,
                          std::chrono::seconds deadline = std::chrono::seconds(120)) {
  const auto until = std::chrono::steady_clock::now() + deadline;
  while (!fs::exists(file)) {
    if (std::chrono::steady_clock::now() > until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

// The stand-in package (see the header comment). `on_plot`: Python statements run when
// bench/plot.py imports matplotlib, with `os`, `sys` and `time` imported; `then_real`: hand over
// to the real matplotlib afterwards (else plot.py fails on its first matplotlib call);
// `fail_import`: every import raises ImportError, as on a machine without matplotlib.
inline void write_matplotlib_stand_in(const fs::path& folder, const std::string& on_plot,
                                      bool then_real = true, bool fail_import = false) {
  fs::create_directories(folder / "matplotlib");
  std::string code =
      "# Stand-in matplotlib of the quadmc end-to-end tests (tests/cli/quadmc_process.hpp).\n"
      "import importlib, os, sys, time\n"
      "_here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))\n"
      "_plot = bool(sys.argv) and sys.argv[0].endswith('plot.py')\n";
  if (fail_import) code += "raise ImportError('No module named matplotlib (test stand-in)')\n";
  code += "if _plot:\n";
  std::string indented;
  std::istringstream lines(on_plot.empty() ? "pass" : on_plot);
  for (std::string line; std::getline(lines, line);) indented += "    " + line + "\n";
  code += indented;
  // A module may replace itself in sys.modules while it is imported; the import then returns the
  // replacement (the Python Language Reference, "The import system", 5.3.1).
  code += std::string("if not _plot or ") + (then_real ? "True" : "False") +
          ":\n"
          "    sys.path[:] = [p for p in sys.path if os.path.abspath(p or '.') != _here]\n"
          "    del sys.modules['matplotlib']\n"
          "    sys.modules['matplotlib'] = importlib.import_module('matplotlib')\n";
  write_text(folder / "matplotlib" / "__init__.py", code);
}

// Writes `text` to `file` atomically (a temporary name, then rename), for the Python side of a
// stand-in to signal with; usable in on_plot as write_marker(path, text).
inline std::string python_write_marker(const fs::path& file, const std::string& text_expr) {
  return "open(" + std::string("'") + file.string() + ".tmp', 'w').write(" + text_expr +
         ")\nos.rename('" + file.string() + ".tmp', '" + file.string() + "')";
}

// A scene of three tiny cells (eˣ under Simpson, N = 8…32): a run takes milliseconds, plus
// 1–2 s for matplotlib when `plots` is on. `description` tells two runs' results apart.
inline std::string tiny_scene(const std::string& name, const std::string& description, bool plots) {
  return "name = \"" + name + "\"\ndescription = \"" + description +
         "\"\n[[integrand]]\nfamily = \"exp\"\n[[method]]\nname = \"simpson\"\n"
         "[budget]\nN = [8, 16, 32]\n[output]\nplots = " +
         (plots ? "true" : "false") + "\n";
}

// Every regular file below `folder` with its content, for "nothing changed" checks.
inline std::map<std::string, std::string> snapshot(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(folder)) {
    if (e.is_regular_file()) files[fs::relative(e.path(), folder).string()] = read_text(e.path());
  }
  return files;
}

inline std::size_t line_count(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

}  // namespace quadmc_cli_test
