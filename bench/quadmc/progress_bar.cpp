#include "progress_bar.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace quadmc_cli {

namespace {
// Below this the run is over before a bar would help, and it would only flicker.
constexpr double quiet_seconds = 2.0;
constexpr double redraw_seconds = 0.1;
constexpr int width = 40;
}  // namespace

progress_bar::progress_bar() : enabled_(isatty(fileno(stderr)) != 0) {}

void progress_bar::update(const quadmc::run_progress& progress) {
  if (!enabled_) return;
  const auto now = clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < quiet_seconds ||
      std::chrono::duration<double>(now - last_draw_).count() < redraw_seconds) {
    return;
  }
  last_draw_ = now;
  // Progress by evaluations, not cells: the last cells of a ladder hold most of the work.
  const double fraction = progress.evaluations_total == 0
                              ? 1.0
                              : std::min(1.0, static_cast<double>(progress.evaluations_done) /
                                                  static_cast<double>(progress.evaluations_total));
  const int filled = static_cast<int>(fraction * width);
  fmt::print(stderr, "\r[{}{}] {:5.1f}%  cell {}/{}  {:.0f} s", std::string(filled, '#'),
             std::string(width - filled, ' '), 100.0 * fraction, progress.cells_done,
             progress.cells_total, elapsed);
  std::fflush(stderr);
  drawn_ = true;
}

void progress_bar::finish() {
  if (drawn_) fmt::print(stderr, "\r{}\r", std::string(width + 40, ' '));
  drawn_ = false;
}

}  // namespace quadmc_cli
