// A progress bar on stderr for runs longer than a couple of seconds, only on a terminal: logs and
// CI output (not a tty) stay clean, and stdout carries only the summary.
#pragma once

#include "quadmc/scene/run.hpp"

#include <chrono>

namespace quadmc_cli {

class progress_bar {
 public:
  progress_bar();
  // Clears the bar also when a run fails, so the error line starts on a clean line.
  ~progress_bar() { finish(); }
  progress_bar(const progress_bar&) = delete;
  progress_bar& operator=(const progress_bar&) = delete;
  void update(const quadmc::run_progress& progress);
  void finish();

 private:
  using clock = std::chrono::steady_clock;
  bool enabled_;
  bool drawn_ = false;
  clock::time_point start_ = clock::now();
  clock::time_point last_draw_{};
};

}  // namespace quadmc_cli
