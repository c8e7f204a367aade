// Peak memory of quadmc's methods, and one method run alone: `quadmc_peers --one METHOD INTEGRAND
// S N THREADS` runs one of quadmc's methods (or the scalar reference loop, or nothing: "baseline")
// once and prints the process's peak RSS in KiB.
//
// Use measure_peak_memory for the memory table of the report: it re-executes this program with
// `--one` in a fresh child per size (bench/common/peak_rss.hpp says why a child and why VmHWM).
// Use run_one directly under a profiler to isolate one case, e.g.
//   perf record build/release/bench/peers/quadmc_peers --one plain genz_gaussian 2 16777216 1
// Not a timing: nothing here is timed.
#pragma once

#include "study.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace quadmc::peers {

// The METHOD and INTEGRAND names `--one` accepts.
std::span<const std::string_view> one_run_methods() noexcept;
std::span<const std::string_view> one_run_integrands() noexcept;

// Runs `method` once on `integrand` in s dimensions with n points and `threads` threads
// (0 = all cores), prints the peak RSS in KiB on stdout and returns 0; returns 2 with a message
// on stderr for an unknown method or integrand, 1 when the estimate is not finite. Invalid sizes
// throw quadmc::invalid_argument from the library.
int run_one(const std::string& method, const std::string& integrand, std::size_t s, std::uint64_t n,
            unsigned threads);

// The memory case of the report: Genz Gaussian, s = 2, 2 threads, each of quadmc's methods at
// each size of c.rss_sizes, and the baseline; sets out.rss and out.rss_baseline_kib.
void measure_peak_memory(const configuration& c, study& out);

}  // namespace quadmc::peers
