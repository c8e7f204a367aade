// A progress bar on stderr for runs longer than a couple of seconds, only on a terminal: logs and
// CI output (not a tty) stay clean, and stdout carries only the summary.
#pragma once

#include "quadmc/scene/run.hpp"

#include <chrono>

namespace quadmc_cli {

class progress_bar {
 public:
  progress_bar();
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
