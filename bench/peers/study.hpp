// What one run of quadmc_peers measures and what it collects: the configuration (sizes, ladders,
// repetitions), one CSV row per measurement, and the whole study that the report is written
// from.
//
// Use it to pass results from the measurement (measurement.hpp, peak_memory.hpp) to the writing
// (report.hpp). Not the place for how anything is measured or printed.
#pragma once

#include "python_module_speed.hpp"
#include "qmc_point_peers.hpp"

#include "quadmc/report/provenance.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace quadmc::peers {

// Fixed seeds: the Genz parameters (genz_random_parameters) and the base of every run's seed.
inline constexpr std::uint64_t genz_seed = 1;
inline constexpr std::uint64_t base_seed = 0x5eed0007;

// The limit beside every figure: the integrand alone, evaluated again and again on one batch of
// batch_points points already in cache (measurement.cpp), under this method name.
inline constexpr const char* integrand_only_method = "integrand only (batch in cache)";

// quadmc's plain Monte Carlo as "quadmc plain MC" draws Philox4x32-10's uniforms (the library's
// default); under this name, the same estimator on ARS-4x32-7's
// (docs/theory.md#counter-based-generators).
inline constexpr const char* plain_mc_ars_method = "quadmc plain MC (ARS)";

// The uniforms rows' yardstick (measure_uniforms): ordinary stores of doubles, under this name.
inline constexpr const char* ordinary_stores_method = "write doubles (ordinary stores)";

struct configuration {
  std::vector<std::size_t> dimensions{1, 2, 4, 8};
  std::vector<std::uint64_t> ladder{100, 316, 1000, 3162, 10000, 31623, 100000, 316228, 1000000};
  std::vector<std::uint64_t> boost_naive_ladder{100000, 1000000};  // ≥ 0.1 s per run anyway
  std::vector<std::uint64_t> tolerance_exponents{2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  // 2^22: at quadmc's 150–250 M evaluations/s a one-thread run of 2^20 lasts 4–7 ms, so the
  // fixed cost of starting threads blurred the two-thread ratio; 2^22 runs last 15–30 ms. The
  // two-thread target is stated at N ≥ 2^22, so every method that holds that many points
  // (jittered: the smallest k^s ≥ N; tensor rules: the smallest (n+1)^s ≥ N) is run at least at it.
  std::uint64_t throughput_n = std::uint64_t{1} << 22;
  std::uint64_t tensor_throughput_n = std::uint64_t{1} << 22;
  // The lattice holds at most 2^20 points (sampling/rank1_lattice_points.hpp); the digit-scrambled
  // Halton set generates 2–5 M points/s, so 2^22 points would cost 1–2 s per run and ~30 s of the
  // study: both at 2^20, shown beside the two-thread target but not counted in it.
  std::uint64_t small_throughput_n = std::uint64_t{1} << 20;
  int repetitions = 3;  // seeds per ladder point of a random method
  // Throughput: each method at least min_throughput_runs times and until min_throughput_seconds
  // of its runs have passed, at most throughput_runs times, in rounds; the best run kept. On a
  // shared 2-core virtual machine the same 20 ms run took 19.9–43.9 ms over half a minute, 18 of
  // 60 within 10 % of the fastest (bench/peers/profile_notes.md, "Two threads"). So runs under
  // 40 ms get 15 rounds (none of them near the fastest: 0.7^15 ≈ 0.005 at that rate), and runs
  // of ≥ 0.2 s (Sobol' owen, Halton, the peers at s = 8) 3.
  int throughput_runs = 15;
  int min_throughput_runs = 3;
  double min_throughput_seconds = 0.6;
  std::vector<std::uint64_t> rss_sizes{1000000, 100000000};
  // Quasi-Monte Carlo point generation (qmc_point_peers.hpp): N points in each s, best of
  // qmc_point_runs. 2^18: the slowest generators (digit-scrambled Halton, scipy) then take
  // 1–4 s per run at s = 8 under load, and the fastest still run for ≥ 10 ms.
  std::vector<std::size_t> qmc_dimensions{2, 8};
  std::uint64_t qmc_points = std::uint64_t{1} << 18;
  int qmc_point_runs = 5;
  // The Python module against scipy and C++ (python_module_speed.hpp): rounds of every
  // contender. A round of the three groups takes about 0.3 s on 2 cores, so 15 rounds (and one
  // to warm up) cost ~5 s, and give a median that a burst of load moves little.
  int python_module_rounds = 15;
  // Uniforms per second against the memory write rate (measure_uniforms): each generator's
  // random_stream::fill_uniform and plain stores of doubles, into a buffer of
  // uniform_cache_doubles (32 KiB, which stays in the first-level data cache) filled again and
  // again up to throughput_n doubles per run, and into one of uniform_memory_doubles (64 MiB,
  // meant to go to memory: on the 2-core AMD EPYC with AVX-512, 512-bit stores into 64 MiB ran
  // at 27–35 GB/s, into 256–512 MiB at 24–26, into 16 MiB at 70–74) filled once per run; in
  // rounds over the writers, best of uniform_rounds. The best runs of a round add up to 14 ms
  // there, so the rounds cost about a second.
  std::uint64_t uniform_cache_doubles = 4096;
  std::uint64_t uniform_memory_doubles = std::uint64_t{8} << 20;
  int uniform_rounds = 30;
};

// `--quick`: a smoke run (small N, seconds); its numbers are not for the record.
inline configuration quick_configuration() {
  configuration c;
  c.ladder = {100, 1000, 10000};
  c.boost_naive_ladder = {10000};
  c.tolerance_exponents = {2, 4, 6};
  c.throughput_n = std::uint64_t{1} << 16;
  c.tensor_throughput_n = 1 << 16;
  c.repetitions = 2;
  c.small_throughput_n = 1 << 14;
  c.throughput_runs = 2;
  c.qmc_point_runs = 2;
  c.rss_sizes = {10000, 1000000};
  c.qmc_points = std::uint64_t{1} << 12;
  c.python_module_rounds = 2;
  c.uniform_memory_doubles = std::uint64_t{1} << 20;
  c.uniform_rounds = 3;
  return c;
}

// One line of peers.csv.
struct row {
  // "throughput", "ladder", "points" (QMC point generation, no integrand), "uniforms" (a
  // generator's uniforms or plain stores of doubles into a buffer, no integrand: rate = doubles
  // per second) or "python" (the Python module: seconds is the median of its rounds,
  // seconds_min/max their range)
  std::string run;
  std::string method;
  std::string family;
  std::string integrand;
  std::size_t s = 0;
  unsigned threads = 1;
  std::uint64_t n = 0;       // the control: N, panels per axis, tolerance exponent, target calls
  std::string control;       // what n means
  double evaluations = 0.0;  // mean over repetitions
  double seconds = 0.0;
  double cpu_seconds = 0.0;  // throughput rows: process CPU time of the kept run
  double rate = 0.0;
  double abs_error = 0.0;  // |error|, RMS over repetitions for random methods
  int repetitions = 1;
  std::optional<double> ratio_to_scalar_loop;
  // Throughput rows: rate / the integrand-only rate (same integrand and s, one thread).
  std::optional<double> ratio_to_integrand_only;
  double seconds_min = NAN, seconds_max = NAN;  // python rows: the range of the rounds
  // uniforms rows: the kernel that wrote the doubles at the active SIMD level (Philox: the
  // level; ARS: detail::ars_kernel(); stores: their instruction); empty elsewhere.
  std::string kernel;
};

// quadmc's plain MC at 1 and 2 threads must agree bit for bit; Boost's naive_monte_carlo at a
// fixed seed need not. Both observed once and reported.
struct reproducibility {
  std::string integrand;
  std::size_t s = 0;
  double quadmc_one_thread = 0.0, quadmc_two_threads = 0.0;
  std::vector<double> boost_values;
};

// Peak memory of one of quadmc's methods, per size of configuration::rss_sizes.
struct rss_row {
  std::string method;
  std::vector<std::uint64_t> n;  // the sizes run (the nearest the method holds)
  std::vector<long> kib;
};

struct study {
  std::string load_before, load_after;  // /proc/loadavg: how busy the shared machine was
  std::vector<row> rows;
  std::optional<reproducibility> repro;
  std::vector<std::string> skipped;
  std::vector<rss_row> rss;
  std::vector<point_agreement> agreement;  // QMC peers: same kind of points as quadmc's
  python_module_study python_module;       // the Python module against scipy and C++
  long rss_baseline_kib = 0;               // the same child doing no integration
  double wall_seconds = 0.0;               // the whole run
  std::vector<double> phase_seconds;       // methods, QMC points and the Python module, peak memory
  quadmc::provenance build;  // what made the numbers (meta.csv, the README's machine paragraph)
};

}  // namespace quadmc::peers
