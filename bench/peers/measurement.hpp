// The timed part of quadmc_peers: every method (quadmc's and the peers') on every integrand and
// dimension, as a work-precision ladder and as a best-of-rounds throughput run, plus one check
// that quadmc's plain Monte Carlo gives the same bits on 1 and 2 threads and Boost's need not.
//
// Use it from quadmc_peers.cpp only; the README the program writes repeats how it measures:
//  - throughput: each method at N ≥ 2^22 (2^22 points for Monte Carlo and Sobol'; the smallest
//    grid with ≥ 2^22 points for tensor rules; jittered the smallest k^s ≥ 2^22; the lattice and
//    Halton sets at 2^20), run with the same seed in rounds over all methods, at least
//    min_throughput_runs times and until min_throughput_seconds have passed (at most
//    throughput_runs), the best (highest evaluations per second) kept: on a shared 2-core machine
//    the noise only ever slows a run down, so the best run is the closest to the method's own
//    cost; first of all, the limit: the integrand alone on one batch of points in cache;
//  - work-precision ladder: N = 10^2, 10^2.5, …, 10^6 (one thread); random methods are run with
//    `repetitions` independent seeds and the RMS error is kept, with the median of their times;
//    each run is repeated at least twice and until 2 ms have passed (at most 100 times) and its
//    fastest repetition is its time.
// Timer: std::chrono::steady_clock; CPU time: CLOCK_PROCESS_CPUTIME_ID. Nothing is asserted.
// Peak memory is measured apart, in child processes (peak_memory.hpp).
#pragma once

#include "study.hpp"

#include <string>

namespace quadmc::peers {

// Measures every method of the study on Genz oscillatory, Genz Gaussian and the sum of
// coordinates for each s of c.dimensions; appends to out.rows (ladder and throughput rows, with
// ratio_to_scalar_loop on throughput rows), out.skipped (points a peer could not run, with its
// message) and sets out.repro.
void measure_methods(const configuration& c, study& out);

// Uniforms per second of random_stream::fill_uniform under each generator (Philox4x32-10 and
// ARS-4x32-7, docs/theory.md#counter-based-generators) at the active SIMD level, beside the rate
// at which this core writes doubles at all (memory_write.hpp: ordinary vector stores of one value,
// and streaming stores into the large buffer), into a buffer in cache and one in memory
// (configuration::uniform_*): rows with run = "uniforms" (evaluations = doubles written per run,
// rate = doubles per second, kernel = what wrote them), one thread, timed in rounds over the
// writers like the throughput rows, the best run of each kept. A measurement, never a check.
void measure_uniforms(const configuration& c, study& out);

// Points per second of quadmc's quasi-Monte Carlo sets and of Boost.Random's, GSL's and scipy's
// generators (qmc_point_peers.hpp) for each s of c.qmc_dimensions at N = c.qmc_points, one
// thread: rows with run = "points" (evaluations = points, rate = points per second), in rounds
// like the throughput rows (scipy: one subprocess with every run, its best time); first
// out.agreement, the checks that each peer's points are of the kind it is compared with.
void measure_qmc_points(const configuration& c, study& out);

// The Python module against scipy and its own C++ (python_module_speed.hpp), when this build has
// the module: out.python_module, and its contenders as rows with run = "python" (seconds = the
// median of c.python_module_rounds rounds, seconds_min/max their range, rate = n / median).
void measure_python_module(const configuration& c, study& out);

// /proc/loadavg as "1 / 5 / 15 min": how busy the shared machine was.
std::string load_average();

}  // namespace quadmc::peers
