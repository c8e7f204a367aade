// Running the `quadmc` command from a test: a scratch folder per test and one child process per
// command, with its exit status, stdout and stderr.
//
// Use it in the end-to-end tests of tests/cli, which check what a user sees (exit status, the one
// stderr line of an error, the files of a results folder). Not for testing library functions:
// those have their own layer's tests, which are faster and say more when they fail.
// The child is started with posix_spawn (POSIX.1-2008, <spawn.h>), no shell, so paths need no
// quoting; its working directory is the scratch folder (glibc's
// posix_spawn_file_actions_addchdir_np, glibc ≥ 2.29), so a run that ignores --out writes there
// and the test sees it. stdout and stderr are captured in two dot-files of the scratch folder,
// which scratch_folder::entries leaves out so tests can compare the listing with what the
// command should have written.
#pragma once

#include <fcntl.h>
#include <spawn.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

extern char** environ;

namespace quadmc_cli_test {

namespace fs = std::filesystem;

inline constexpr const char* stdout_capture = ".stdout";
inline constexpr const char* stderr_capture = ".stderr";

inline std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void write_text(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

// A fresh folder under the system temp directory (mkdtemp: unique even when several test
// processes run at once, as ctest -j does), removed with everything in it at the end of the test.
class scratch_folder {
 public:
  scratch_folder() {
    std::string pattern = (fs::temp_directory_path() / "quadmc_cli_XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) {
      throw std::system_error(errno, std::generic_category(), "mkdtemp " + pattern);
    }
    path_ = pattern;
  }
  scratch_folder(const scratch_folder&) = delete;
  scratch_folder& operator=(const scratch_folder&) = delete;
  ~scratch_folder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }

  const fs::path& path() const noexcept { return path_; }
  fs::path operator/(const std::string& name) const { return path_ / name; }

  // Names directly inside the folder, sorted, without the stdout/stderr captures.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(path_)) {
      const std::string name = e.path().filename().string();
      if (name != stdout_capture && name != stderr_capture) names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  fs::path path_;
};

struct command_result {
  int exit_status = -1;  // the child's exit code; 128 + signal number when a signal killed it
  std::string out;
  std::string err;
};

// Runs the program argv[0] with its arguments in `folder` and waits.
inline command_result run_command(const scratch_folder& folder, std::vector<std::string> argv) {
  std::vector<char*> cargv;
  for (auto& a : argv) cargv.push_back(a.data());
  cargv.push_back(nullptr);

  const std::string out_file = (folder.path() / stdout_capture).string();
  const std::string err_file = (folder.path() / stderr_capture).string();
  const std::string cwd = folder.path().string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out_file.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err_file.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
  pid_t pid = 0;
  const int started = posix_spawn(&pid, cargv[0], &actions, nullptr, cargv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (started != 0) {
    throw std::system_error(started, std::generic_category(), "spawn " + argv.front());
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::system_error(errno, std::generic_category(), "waitpid");
  }
  command_result r;
  r.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = read_text(out_file);
  r.err = read_text(err_file);
  return r;
}

// Runs `quadmc args…` (the binary built beside these tests, QUADMC_CLI) in `folder` and waits.
inline command_result run_quadmc(const scratch_folder& folder,
                                 const std::vector<std::string>& args) {
  std::vector<std::string> argv{QUADMC_CLI};
  argv.insert(argv.end(), args.begin(), args.end());
  return run_command(folder, std::move(argv));
}

// For assertion messages: everything the command said.
inline std::string describe(const command_result& r) {
  return "exit status " + std::to_string(r.exit_status) + "\n--- stdout ---\n" + r.out +
         "\n--- stderr ---\n" + r.err;
}

inline fs::path scene_path(const std::string& file_name) {
  return fs::path(QUADMC_SOURCE_DIR) / "bench" / "scenes" / file_name;
}

// One column of a CSV file as text, one entry per data row: the bitwise view of a number column
// (the writer prints the shortest text that reads back to the same double, results_csv.hpp, so
// equal text ⇔ equal doubles). Fields of our CSVs hold no commas or quotes in these tests.
inline std::vector<std::string> csv_column_text(const fs::path& file, const std::string& column) {
  std::istringstream in(read_text(file));
  std::string line;
  std::getline(in, line);
  auto split = [](const std::string& l) {
    std::vector<std::string> fields;
    std::string field;
    std::istringstream row(l);
    while (std::getline(row, field, ',')) fields.push_back(field);
    if (!l.empty() && l.back() == ',') fields.emplace_back();
    return fields;
  };
  const std::vector<std::string> header = split(line);
  const auto at = std::find(header.begin(), header.end(), column);
  if (at == header.end()) throw std::runtime_error("no column " + column + " in " + file.string());
  const auto index = static_cast<std::size_t>(at - header.begin());
  std::vector<std::string> values;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::vector<std::string> fields = split(line);
    values.push_back(index < fields.size() ? fields[index] : std::string());
  }
  return values;
}

// Every column of the file but those that hold run time (as bench/same_results.py compares):
// seconds, evals_per_second, and the stable timing's columns.
inline bool is_timing(const std::string& column) {
  return column.find("second") != std::string::npos || column.rfind("timed_", 0) == 0;
}

inline std::vector<std::vector<std::string>> columns_but_timing(const fs::path& file) {
  const std::string text = read_text(file);
  std::istringstream header_line(text.substr(0, text.find('\n')));
  std::vector<std::vector<std::string>> columns;
  std::string name;
  while (std::getline(header_line, name, ',')) {
    if (is_timing(name)) continue;
    columns.push_back(csv_column_text(file, name));
    columns.back().insert(columns.back().begin(), name);
  }
  return columns;
}

inline void expect_same_results(const fs::path& a, const fs::path& b, const std::string& what) {
  for (const char* file : {"convergence.csv", "slopes.csv"}) {
    const auto ca = columns_but_timing(a / file);
    const auto cb = columns_but_timing(b / file);
    ASSERT_EQ(ca.size(), cb.size()) << what << ": " << file;
    for (std::size_t k = 0; k < ca.size(); ++k) {
      EXPECT_EQ(ca[k], cb[k]) << what << ": " << file << ", column " << ca[k].front();
    }
  }
}

}  // namespace quadmc_cli_test
