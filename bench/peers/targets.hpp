// The targets of results/peers: which ratios of rates the page marks met (✅), missed (❌) or not
// measurable in this run (⚠), and the rule that decides the mark.
//
// Use it from report.cpp (the targets table) and from tests/peers/targets_test.cpp (the rule on
// synthetic rows). A target is a ratio of two rows of the study — throughput rows (evaluations
// per second) or QMC point rows (points per second) — on named integrands, for every s of the
// table; a cell can be outside the target's scope (an s the goal does not name, a run smaller
// than the target's N) and is then shown but not counted. Not for measuring: nothing here
// times anything. The goals are those of docs/design.md#performance-targets (the page says which
// first goals they replaced).
#pragma once

#include "study.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace quadmc::peers {

enum class mark {
  met,             // ✅ ratio ≥ goal
  missed,          // ❌ ratio < goal
  not_measurable,  // ⚠ a run got less than 0.75 of a core per thread: the machine's other work
  not_counted,     // shown for information: outside the target's scope (s, N)
};

// The symbol the page prints for a mark ("" for not_counted: its cell says why instead).
const char* symbol(mark m) noexcept;

// How much of the machine one kept run got: process CPU time / wall time, and the threads it
// asked for. cores NaN = unknown (a subprocess, e.g. scipy): never the reason for ⚠.
struct run_share {
  double cores = 0.0;
  unsigned threads = 1;
};

// A run got less than 0.75 of a core per thread: on a shared machine its time measured other
// work too. 0.75 leaves room for the process's own waits (a pool's wake-up, a page fault).
bool starved(run_share r) noexcept;

// The mark of one measured ratio: ⚠ when either run is starved, else ✅ / ❌ against the goal.
mark judge(double ratio, double goal, run_share numerator, run_share denominator) noexcept;

struct target_spec {
  std::string label;  // e.g. "quadmc jittered / plain MC (1 thread each)"
  std::string run;    // the rows compared: "throughput" or "points"
  std::string numerator;
  unsigned numerator_threads = 1;
  std::string denominator;
  unsigned denominator_threads = 1;
  double goal = 1.0;
  std::vector<std::string> integrands;  // one line per integrand ("(points only)")
  std::vector<std::size_t> counted_s;   // the s the goal names; empty: every s
  std::uint64_t min_evaluations = 0;    // smaller kept runs: shown, not counted
  bool show_cores = false;              // print the two runs' cores in every cell
  // A method whose ratio at the same thread counts is printed beside this one, for the reader;
  // it never changes the mark. The two-thread targets name the integrand alone, which shares
  // nothing but a chunk counter: its ratio shows what two threads of this machine gave code with
  // nothing to wait for in the same rounds (a vCPU whose physical core the host gives to other
  // work runs slower while "cores" still reads full). Empty: none.
  std::string reference;
};

// The current targets, then the first ones that still stand (plain MC against the scalar loop, GSL
// and Boost), for quadmc's methods by the names measurement.cpp gives them.
std::vector<target_spec> performance_targets(std::uint64_t two_thread_min_n);

struct target_cell {
  std::size_t s = 0;
  std::optional<double> ratio;  // empty: a row missing (method not run at this s)
  mark m = mark::not_counted;
  run_share numerator, denominator;
  std::optional<double> reference;  // the reference method's ratio, where the spec names one
  std::string note;  // why not counted ("s = 1 not in the goal", "N = 1048576 < 4194304")
};

struct target_line {
  target_spec spec;
  std::string integrand;
  std::vector<target_cell> cells;  // one per s of the table, in order
};

// Every target on every integrand it names, one cell per s in `dimensions`.
std::vector<target_line> evaluate_targets(const std::vector<target_spec>& specs,
                                          const std::vector<row>& rows,
                                          const std::vector<std::size_t>& dimensions);

struct target_tally {
  int met = 0, missed = 0, not_measurable = 0;
};
target_tally tally(const std::vector<target_line>& lines);

// The Markdown table (header, one line per target line); cells "1.23× ✅", "0.80× ⚠ (0.52 /
// 1.00 cores)", "1.61× ❌ (1.99 / 1.00 cores; integrand alone 1.62×)", "0.70× (s = 1 not in the
// goal)", "—".
std::string targets_table(const std::vector<target_line>& lines,
                          const std::vector<std::size_t>& dimensions);

// Memory constant in N: the growth of peak RSS from the smallest to the largest size stays below
// `bound_kib`, far below what storing even one byte per point would add.
bool memory_constant(const rss_row& r, long bound_kib) noexcept;

}  // namespace quadmc::peers
