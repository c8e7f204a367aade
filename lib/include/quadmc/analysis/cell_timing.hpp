// The stable time of one estimate of a cell, measured apart from its error statistics.
//
// Use it for every figure that divides work by time (work-precision, time to error, compare's
// time ratios): one clock reading around one call cannot time a microsecond cell (thread start-up,
// cache state and the clock's own cost dominate). The runner (scene/run.hpp) repeats the cell's
// first estimate, the same work as repetition 1, in batches of k calls until at least a minimum
// time has passed (Google Benchmark's min_time idea, docs/design.md#stable-timing); each batch
// gives one sample, its time / k. Not the cost of the repetitions: `cell_statistics::seconds`
// stays their measured total.
//
//   seconds_per_estimate  the median of the samples
//   spread                (max − min)/median of the samples: every batch's time per estimate lay
//                         within seconds_per_estimate·[1 − spread, 1 + spread]; min–max rather than
//                         interquartile because a work-precision curve is judged monotone within
//                         it (an interquartile range of a few samples says little of the tails).
//                         NaN when the cell was timed once.
//   estimates             calls timed; 1 = timed once: the first call already took at least the
//                         minimum, and its own time is the figure (no repeat).
#pragma once

#include <cstdint>
#include <limits>
#include <span>

namespace quadmc {

struct cell_timing {
  double seconds_per_estimate = std::numeric_limits<double>::quiet_NaN();
  double spread = std::numeric_limits<double>::quiet_NaN();
  std::uint64_t estimates = 0;  // 0: not timed (a cell from before stable timing)

  bool timed() const noexcept { return estimates > 0; }
  bool timed_once() const noexcept { return estimates == 1; }
};

// samples: seconds per estimate of each batch; estimates: calls over all batches. One sample of
// one call is "timed once" (spread NaN). Throws invalid_argument for no samples, a negative or
// non-finite sample, or fewer estimates than samples.
cell_timing summarise_timing(std::span<const double> samples, std::uint64_t estimates);

}  // namespace quadmc
