// quadmc_peers: quadmc's plain Monte Carlo, jittered and Latin hypercube points and tensor
// Simpson/trapezoid measured in one run beside what a user would otherwise pick — a hand-written
// xoshiro256+ loop, GSL plain/MISER/VEGAS, Boost.Math naive_monte_carlo and its 1D rules,
// cubature's hcubature/pcubature — on the same integrands (Genz oscillatory and Gaussian, the sum
// of coordinates) with the same references, for s ∈ {1, 2, 4, 8} (issue 7, "Fast" is measured).
//
//   quadmc_peers [--out DIR] [--quick]        writes DIR/peers.csv and DIR/README.md
//   /usr/bin/python3 bench/peers/plot_peers.py DIR   then draws DIR/work_precision_*.svg
//
// What is measured, and how (the README written here repeats it for the reader):
//  - throughput: each method at N ≥ 4·10^6 (2^22 points for Monte Carlo; the smallest grid with
//    ≥ 4·10^6 points for tensor rules; jittered k^s nearest 2^22), run 5 times with the same seed
//    in 5 rounds over all methods, the best of the 5 (highest evaluations per second) kept: on a
//    shared 2-core machine the noise only ever slows a run down, so the best run is the closest
//    to the method's own cost;
//  - work-precision ladder: N = 10^2, 10^2.5, …, 10^6 (one thread); random methods are run with 3
//    independent seeds and the RMS error is kept, with the median of their times; each run is
//    repeated at least twice and until 2 ms have passed (at most 100 times) and its fastest
//    repetition is its time;
//  - time to 10^−3 and 10^−5 from the ladder (time_to_accuracy.hpp);
//  - peak RSS of quadmc's methods at N = 10^6 and 10^8 in fresh child processes
//    (bench/common/peak_rss.hpp).
// Timer: std::chrono::steady_clock. Nothing here is asserted: the targets are reported, met or not.
// Not a test and not part of CI: it takes about two minutes on 2 cores.
#include "boost_math_methods.hpp"
#include "cubature_methods.hpp"
#include "gsl_monte_methods.hpp"
#include "peer_method.hpp"
#include "quadmc_methods.hpp"
#include "sum_of_coordinates.hpp"
#include "time_to_accuracy.hpp"

#include "peak_rss.hpp"               // bench/common
#include "scalar_reference_loop.hpp"  // bench/common

#include "quadmc/core/rng.hpp"
#include "quadmc/core/simd_level.hpp"
#include "quadmc/estimators/monte_carlo.hpp"
#include "quadmc/functions/genz.hpp"
#include "quadmc/sampling/independent_points.hpp"

#include <fmt/format.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_version.h>
#include <boost/version.hpp>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#ifndef QUADMC_PEERS_BUILD
#define QUADMC_PEERS_BUILD "unknown"
#endif
#ifndef QUADMC_PEERS_NOTES
#define QUADMC_PEERS_NOTES ""
#endif

namespace quadmc::peers {
namespace {

// Fixed seeds: the Genz parameters (genz_random_parameters) and the base of every run's seed.
constexpr std::uint64_t genz_seed = 1;
constexpr std::uint64_t base_seed = 0x5eed0007;

struct configuration {
  std::vector<std::size_t> dimensions{1, 2, 4, 8};
  std::vector<std::uint64_t> ladder{100, 316, 1000, 3162, 10000, 31623, 100000, 316228, 1000000};
  std::vector<std::uint64_t> boost_naive_ladder{100000, 1000000};  // ≥ 0.1 s per run anyway
  std::vector<std::uint64_t> tolerance_exponents{2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  // 2^22: at quadmc's 150–250 M evaluations/s a one-thread run of 2^20 lasts 4–7 ms, so the
  // fixed cost of starting threads blurred the two-thread ratio; 2^22 runs last 15–30 ms.
  std::uint64_t throughput_n = std::uint64_t{1} << 22;
  std::uint64_t tensor_throughput_n = 4000000;
  int repetitions = 3;      // seeds per ladder point of a random method
  int throughput_runs = 5;  // best of
  std::vector<std::uint64_t> rss_sizes{1000000, 100000000};
};

configuration quick_configuration() {
  configuration c;
  c.ladder = {100, 1000, 10000};
  c.boost_naive_ladder = {10000};
  c.tolerance_exponents = {2, 4, 6};
  c.throughput_n = std::uint64_t{1} << 16;
  c.tensor_throughput_n = 1 << 16;
  c.repetitions = 2;
  c.throughput_runs = 2;
  c.rss_sizes = {10000, 1000000};
  return c;
}

// One line of peers.csv.
struct row {
  std::string run;  // "throughput" or "ladder"
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
};

struct timed_run {
  run_result result;
  double seconds = 0.0;
  double cpu_seconds = 0.0;  // CPU time of the whole process (all threads) during the run
};

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Runs fn at least min_runs times and until min_seconds have passed (at most max_runs); keeps the
// run with the most evaluations per second (= the fastest when every run does the same work).
template <class Fn>
timed_run best_of(Fn&& fn, int min_runs, double min_seconds, int max_runs) {
  timed_run best;
  double best_rate = -1.0;
  double total = 0.0;
  for (int k = 0; k < min_runs || (total < min_seconds && k < max_runs); ++k) {
    const double cpu_start = process_cpu_seconds();
    const auto start = std::chrono::steady_clock::now();
    const run_result r = fn();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu = process_cpu_seconds() - cpu_start;
    total += seconds;
    const double rate = static_cast<double>(r.evaluations) / seconds;
    if (rate > best_rate) {
      best_rate = rate;
      best = {r, seconds, cpu};
    }
  }
  return best;
}

std::string control_name(control_kind k) {
  switch (k) {
    case control_kind::evaluations:
      return "N";
    case control_kind::panels:
      return "panels per axis";
    case control_kind::tolerance:
      return "tolerance 10^-k";
    case control_kind::target_calls:
      return "target calls";
  }
  return "?";
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 == 1 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// quadmc's plain MC at 1 and 2 threads must agree bit for bit; Boost's naive_monte_carlo at a
// fixed seed need not. Both observed once and reported.
struct reproducibility {
  std::string integrand;
  std::size_t s = 0;
  double quadmc_one_thread = 0.0, quadmc_two_threads = 0.0;
  std::vector<double> boost_values;
};

struct study {
  std::string load_before, load_after;  // /proc/loadavg: how busy the shared machine was
  std::vector<row> rows;
  std::optional<reproducibility> repro;
  std::vector<std::string> skipped;
};

template <class F>
std::vector<peer_method> methods_for(const F& f, const configuration& c, double variance) {
  const std::size_t s = f.dimension();
  std::vector<peer_method> m;
  peer_method reference;
  reference.name = "scalar reference loop";
  reference.family = "reference";
  reference.ladder = c.ladder;
  reference.throughput_control = c.throughput_n;
  reference.run = [&f](std::uint64_t n, std::uint64_t seed) {
    const bench::scalar_loop_result r = bench::scalar_reference_loop(f, n, seed);
    return run_result{r.value, r.evaluations};
  };
  m.push_back(std::move(reference));
  const std::vector<std::uint64_t> none;
  for (unsigned threads : {1U, 2U}) {
    const auto& ladder = threads == 1 ? c.ladder : none;
    m.push_back(quadmc_monte_carlo<independent_points>("quadmc plain MC", f, threads, ladder,
                                                       c.throughput_n));
    m.push_back(
        quadmc_monte_carlo<jittered_points>("quadmc jittered", f, threads, ladder, c.throughput_n));
    m.push_back(quadmc_monte_carlo<latin_hypercube_points>("quadmc Latin hypercube", f, threads,
                                                           ladder, c.throughput_n));
    m.push_back(quadmc_tensor_rule<simpson_rule>("quadmc tensor Simpson", f, threads, ladder,
                                                 c.tensor_throughput_n));
    m.push_back(quadmc_tensor_rule<trapezoid_rule>("quadmc tensor trapezoid", f, threads, ladder,
                                                   c.tensor_throughput_n));
  }
  for (auto a :
       {gsl_monte_algorithm::plain, gsl_monte_algorithm::miser, gsl_monte_algorithm::vegas}) {
    m.push_back(gsl_monte(a, f, c.ladder, c.throughput_n));
  }
  m.push_back(boost_naive_monte_carlo(f, 1, variance, c.boost_naive_ladder, c.throughput_n));
  m.push_back(boost_naive_monte_carlo(f, 0, variance, none, c.throughput_n));
  m.push_back(cubature(cubature_algorithm::h_adaptive, f, c.ladder, c.throughput_n));
  m.push_back(cubature(cubature_algorithm::p_adaptive, f, c.ladder, c.throughput_n));
  if (s == 1) {
    for (auto r : {boost_quadrature_1d::trapezoidal, boost_quadrature_1d::gauss_kronrod_15,
                   boost_quadrature_1d::tanh_sinh}) {
      m.push_back(boost_quadrature(r, f, c.tolerance_exponents));
    }
  }
  return m;
}

template <class F>
void measure(const F& f, const configuration& c, study& out) {
  const integrand_info info = f.info();
  const std::size_t s = f.dimension();
  const double exact = info.exact;
  // V̂ for Boost's error goal: quadmc plain MC on 2^16 points, a stream of its own.
  const double variance =
      monte_carlo(f, independent_points(s, 1 << 16, base_seed, stream_id({0xba5e})), 1).variance;
  std::cerr << fmt::format("{} s={}: ladder", info.name, s) << std::flush;
  const std::vector<peer_method> methods = methods_for(f, c, variance);
  std::vector<row> bases;
  std::vector<std::vector<row>> ladders(methods.size());
  for (std::size_t k = 0; k < methods.size(); ++k) {
    const peer_method& m = methods[k];
    row base;
    base.method = m.name;
    base.family = m.family;
    base.integrand = info.name;
    base.s = s;
    base.threads = m.threads;
    base.control = control_name(m.kind);
    bases.push_back(base);
    for (std::uint64_t control : m.ladder) {
      const int reps = m.random ? c.repetitions : 1;
      std::vector<double> seconds;
      double squared = 0.0, evaluations = 0.0;
      try {
        for (int r = 0; r < reps; ++r) {
          const std::uint64_t seed = stream_id({base_seed, static_cast<std::uint64_t>(r)});
          // At least 2 runs (one preemption by other work must not make a point), until 2 ms
          // have passed; Boost's naive_monte_carlo runs ≥ 0.1 s by itself, once is enough.
          const int min_runs = m.kind == control_kind::target_calls ? 1 : 2;
          const timed_run t = best_of([&] { return m.run(control, seed); }, min_runs, 2e-3, 100);
          const double e = t.result.value - exact;
          squared += e * e;
          evaluations += static_cast<double>(t.result.evaluations);
          seconds.push_back(t.seconds);
        }
      } catch (const std::exception& e) {
        out.skipped.push_back(fmt::format("{} on {} s={} at {} = {}: {}", m.name, info.name, s,
                                          control_name(m.kind), control, e.what()));
        continue;
      }
      row r = base;
      r.run = "ladder";
      r.n = control;
      r.evaluations = evaluations / reps;
      r.seconds = median(seconds);
      r.rate = r.evaluations / r.seconds;
      r.abs_error = std::sqrt(squared / reps);
      r.repetitions = reps;
      ladders[k].push_back(r);
    }
    std::cerr << "." << std::flush;
  }

  // Throughput in rounds: every method runs once per round, so a burst of load from elsewhere
  // on the shared machine slows one round of all methods rather than every run of one method.
  std::cerr << " throughput" << std::flush;
  std::vector<std::optional<timed_run>> best(methods.size());
  std::vector<bool> failed(methods.size(), false);
  const std::uint64_t seed = stream_id({base_seed, 0xf00d});
  for (int round = 0; round < c.throughput_runs; ++round) {
    for (std::size_t k = 0; k < methods.size(); ++k) {
      const peer_method& m = methods[k];
      if (m.throughput_control == 0 || failed[k]) continue;
      try {
        const timed_run t = best_of([&] { return m.run(m.throughput_control, seed); }, 1, 0.0, 1);
        const auto rate = [](const timed_run& x) {
          return static_cast<double>(x.result.evaluations) / x.seconds;
        };
        if (!best[k] || rate(t) > rate(*best[k])) best[k] = t;
      } catch (const std::exception& e) {
        failed[k] = true;
        out.skipped.push_back(fmt::format(
            "{} on {} s={} at the throughput size {} = {}: {} (its largest ladder run is used)",
            m.name, info.name, s, control_name(m.kind), m.throughput_control, e.what()));
      }
    }
    std::cerr << "." << std::flush;
  }
  for (std::size_t k = 0; k < methods.size(); ++k) {
    out.rows.insert(out.rows.end(), ladders[k].begin(), ladders[k].end());
    row r = bases[k];
    r.run = "throughput";
    if (best[k]) {
      const timed_run& t = *best[k];
      r.n = methods[k].throughput_control;
      r.evaluations = static_cast<double>(t.result.evaluations);
      r.seconds = t.seconds;
      r.cpu_seconds = t.cpu_seconds;
      r.abs_error = std::abs(t.result.value - exact);
      r.repetitions = c.throughput_runs;
    } else {
      // Adaptive 1D rules: their largest ladder run (they converge long before 10^6 points);
      // also a peer that fails at the throughput size.
      if (ladders[k].empty()) continue;
      const auto largest = std::max_element(
          ladders[k].begin(), ladders[k].end(),
          [](const row& a, const row& b) { return a.evaluations < b.evaluations; });
      r.n = largest->n;
      r.evaluations = largest->evaluations;
      r.seconds = largest->seconds;
      r.cpu_seconds = largest->seconds;
      r.abs_error = largest->abs_error;
      r.repetitions = 1;
    }
    r.rate = r.evaluations / r.seconds;
    out.rows.push_back(r);
  }
  std::cerr << "\n";

  if (!out.repro && s == 2) {
    reproducibility rep{info.name, s, 0.0, 0.0, {}};
    const std::uint64_t n = c.throughput_n;
    const independent_points points(s, n, base_seed, stream_id({n}));
    rep.quadmc_one_thread = monte_carlo(f, points, 1).value;
    rep.quadmc_two_threads = monte_carlo(f, points, 2).value;
    const peer_method boost = boost_naive_monte_carlo(f, 0, variance, {}, n);
    for (int k = 0; k < 3; ++k) rep.boost_values.push_back(boost.run(n, base_seed).value);
    out.repro = rep;
  }
}

// ---- one method alone: the peak-RSS children, and a profiler's target ----

// `--one METHOD INTEGRAND S N THREADS` runs one of quadmc's methods (or the reference loop, or
// nothing: "baseline") once and prints the process's peak RSS in KiB. The peak-RSS measurement
// runs it in fresh children; under perf or callgrind it isolates one case, e.g.
//   perf record build/peers/bench/peers/quadmc_peers --one plain genz_gaussian 2 16777216 1
const std::vector<std::string> rss_methods{"plain", "jittered", "latin_hypercube", "simpson",
                                           "trapezoid"};

std::string rss_method_name(const std::string& key) {
  if (key == "plain") return "quadmc plain MC";
  if (key == "jittered") return "quadmc jittered";
  if (key == "latin_hypercube") return "quadmc Latin hypercube";
  if (key == "simpson") return "quadmc tensor Simpson";
  return "quadmc tensor trapezoid";
}

template <class F>
int run_one(const F& f, const std::string& method, std::uint64_t n, unsigned threads) {
  const std::size_t s = f.dimension();
  const std::uint64_t seed = base_seed;
  double value = 0.0;
  if (method == "baseline") {
    value = f.info().exact;
  } else if (method == "reference") {
    value = bench::scalar_reference_loop(f, n, seed).value;
  } else if (method == "plain") {
    value = monte_carlo(f, independent_points(s, n, seed, 1), threads).value;
  } else if (method == "jittered") {
    value = monte_carlo(f, jittered_points(s, jittered_size(n, s), seed, 1), threads).value;
  } else if (method == "latin_hypercube") {
    value = monte_carlo(f, latin_hypercube_points(s, n, seed, 1), threads).value;
  } else if (method == "simpson") {
    value = integrate(f, simpson_rule{}, tensor_panels(n, s, true, false), threads).value;
  } else if (method == "trapezoid") {
    value = integrate(f, trapezoid_rule{}, tensor_panels(n, s, false, false), threads).value;
  } else {
    std::cerr << "--one: unknown method " << method
              << " (baseline, reference, plain, jittered, latin_hypercube, simpson, trapezoid)\n";
    return 2;
  }
  if (!std::isfinite(value)) return 1;
  std::cout << bench::peak_rss_kib() << std::endl;
  return 0;
}

int run_one(const std::string& method, const std::string& integrand, std::size_t s, std::uint64_t n,
            unsigned threads) {
  if (integrand == "genz_oscillatory") {
    auto p = genz_random_parameters(genz_family::oscillatory, s, genz_seed);
    return run_one(genz_oscillatory(std::move(p.a), std::move(p.u)), method, n, threads);
  }
  if (integrand == "genz_gaussian") {
    auto p = genz_random_parameters(genz_family::gaussian, s, genz_seed);
    return run_one(genz_gaussian(std::move(p.a), std::move(p.u)), method, n, threads);
  }
  if (integrand == "sum_of_coordinates") return run_one(sum_of_coordinates(s), method, n, threads);
  std::cerr << "--one: unknown integrand " << integrand
            << " (genz_oscillatory, genz_gaussian, sum_of_coordinates)\n";
  return 2;
}

struct rss_row {
  std::string method;
  std::vector<long> kib;  // per size of configuration::rss_sizes
};

// ---- writing ----

std::string format_seconds(double t) {
  if (t < 1e-3) return fmt::format("{:.3g} µs", t * 1e6);
  if (t < 1.0) return fmt::format("{:.3g} ms", t * 1e3);
  return fmt::format("{:.3g} s", t);
}

// 10^k written 10ᵏ (for the sizes of the memory table); other numbers as they are.
std::string power_of_ten(std::uint64_t n) {
  static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  int k = 0;
  std::uint64_t m = n;
  while (m >= 10 && m % 10 == 0) {
    m /= 10;
    ++k;
  }
  if (m != 1 || k == 0) return std::to_string(n);
  return std::string("10") + (k >= 10 ? std::string(digits[k / 10]) : std::string()) +
         digits[k % 10];
}

std::string format_rate(double r) {
  return fmt::format("{:.3g}", r / 1e6);
}

void write_csv(const std::filesystem::path& path, const std::vector<row>& rows) {
  std::ofstream out(path);
  out << "method,integrand,s,threads,N,evaluations,seconds,evals_per_second,abs_error,"
         "ratio_to_scalar_loop,run,family,control,repetitions,cpu_seconds\n";
  for (const row& r : rows) {
    out << fmt::format(
        "{},{},{},{},{},{:.0f},{:.6g},{:.6g},{:.6g},{},{},{},{},{},{}\n", r.method, r.integrand,
        r.s, r.threads, r.n, r.evaluations, r.seconds, r.rate, r.abs_error,
        r.ratio_to_scalar_loop ? fmt::format("{:.4f}", *r.ratio_to_scalar_loop) : std::string(),
        r.run, r.family, r.control, r.repetitions,
        r.run == "throughput" ? fmt::format("{:.6g}", r.cpu_seconds) : std::string());
  }
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  double one = 0, five = 0, fifteen = 0;
  in >> one >> five >> fifteen;
  return fmt::format("{:.2f} / {:.2f} / {:.2f}", one, five, fifteen);
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  }
  return "unknown CPU";
}

struct key {
  std::string method;
  unsigned threads;
  std::string integrand;
  std::size_t s;
  auto operator<=>(const key&) const = default;
};

class report {
 public:
  report(const configuration& c, const study& st, std::vector<rss_row> rss, long rss_baseline,
         double wall_seconds)
      : c_(c), st_(st), rss_(std::move(rss)), rss_baseline_(rss_baseline), wall_(wall_seconds) {
    for (const row& r : st.rows) {
      if (r.run == "throughput") {
        rate_[{r.method, r.threads, r.integrand, r.s}] = r.rate;
        cores_[{r.method, r.threads, r.integrand, r.s}] = r.cpu_seconds / r.seconds;
        evaluations_[{r.method, r.threads, r.integrand, r.s}] = r.evaluations;
      }
      if (r.run == "ladder") {
        auto& v = ladder_[{r.method, r.threads, r.integrand, r.s}];
        v.push_back({r.evaluations, r.seconds, r.abs_error});
      }
      if (std::find(integrands_.begin(), integrands_.end(), r.integrand) == integrands_.end()) {
        integrands_.push_back(r.integrand);
      }
      const auto m = std::pair{r.method, r.threads};
      if (r.run == "throughput" &&
          std::find(methods_.begin(), methods_.end(), m) == methods_.end()) {
        methods_.push_back(m);
      }
    }
  }

  std::string markdown(const std::string& command) const {
    std::ostringstream o;
    o << "# Peers measured in the same run\n\n";
    o << "quadmc's own methods beside what a user would otherwise pick, on the same integrand "
         "code (quadmc::genz_oscillatory, quadmc::genz_gaussian with "
         "genz_random_parameters(family, "
         "s, 1), and a local sum of coordinates f = Σxⱼ) with the same references "
         "(f.info().exact), measured in one process. Written by `bench/peers/quadmc_peers`; "
         "every number below is in `peers.csv`.\n\n";
    o << "Regenerate (from the repository root; needs libgsl-dev, libcubature-dev, "
         "python3-matplotlib):\n\n```sh\n"
      << command << "\n```\n\n";
    o << fmt::format(
        "Machine: {}, {} hardware threads (shared with other work while measuring); quadmc's "
        "kernels at SIMD level {} (chosen at run time, core/simd_level.hpp). Compiler: "
        "GCC {}; build: {}. GSL {}, Boost {}, cubature (Debian libcubature-dev). Whole run: "
        "{:.0f} s; load average (1/5/15 min) {} before, {} after.\n\n",
        cpu_model(), std::thread::hardware_concurrency(),
        quadmc::to_string(quadmc::active_simd_level()), __VERSION__, QUADMC_PEERS_BUILD,
        GSL_VERSION, BOOST_LIB_VERSION, wall_, st_.load_before, st_.load_after);
    o << "How it is timed: std::chrono::steady_clock around one whole call of each method "
         "(set-up included: point-set construction, GSL state and generator allocation). "
         "**Throughput** rows: N ≥ 4·10⁶ evaluations (2^22 for the Monte Carlo methods; "
         "jittered k^s nearest 2^22; tensor rules the smallest (n+1)^s ≥ 4·10⁶), run "
      << c_.throughput_runs
      << " times with one seed, in rounds (each round runs every method once, so a burst of "
         "load hits all methods alike), the **best** run kept (highest evaluations/s: on a "
         "shared machine noise only slows runs down). **Ladder** rows (work-precision): N = 10², "
         "10^2.5, …, 10⁶ with one thread; random methods with "
      << c_.repetitions
      << " independent seeds, error = RMS over the seeds, time = median over the seeds; each "
         "run repeated at least twice (Boost naive_monte_carlo: once) and until 2 ms have "
         "passed (≤ 100 times), and its fastest repetition kept.\n\n";
    o << "Peers, as called: GSL `gsl_monte_plain/miser/vegas_integrate` with `gsl_rng_mt19937` "
         "(GSL's default), calls = N (VEGAS: N/5 per iteration × its default 5 iterations); "
         "Boost `naive_monte_carlo` with error goal √(V̂/N) (it is goal-driven and polls every "
         "100 ms, so a run lasts ≥ 0.1 s and usually overshoots N; its own `calls()` give the "
         "rate), 1 worker thread and its default (hardware_concurrency); cubature "
         "`hcubature_v`/`pcubature_v` with maxEval = N, tolerances 0 (they get whole batches, "
         "quadmc's layout); Boost `trapezoidal` (max_refinements 20), `gauss_kronrod<double,15>` "
         "(max_depth 15), `tanh_sinh` for s = 1 with tolerances 10⁻² … 10⁻¹²; the scalar "
         "reference loop (xoshiro256+, s uniforms per point, the integrand inlined through a "
         "batch of one, plain sum, `bench/common/scalar_reference_loop.hpp`). Per-point peers call "
         "the suite's integrand through a batch of one (`bench/common/point_adapter.hpp`); "
         "evaluations are counted in every adapter, never assumed.\n\n";
    targets(o);
    throughput(o);
    accuracy(o);
    memory(o);
    determinism(o);
    notes(o);
    o << "## Plots\n\n";
    for (const auto& name : integrands_) {
      o << fmt::format("![work-precision, {0}](work_precision_{0}.svg)\n\n", name);
    }
    if (!st_.skipped.empty()) {
      o << "## Points that could not be run\n\n";
      for (const auto& s : st_.skipped) o << "- " << s << "\n";
      o << "\n";
    }
    return o.str();
  }

 private:
  std::optional<double> rate(const std::string& method, unsigned threads,
                             const std::string& integrand, std::size_t s) const {
    const auto it = rate_.find({method, threads, integrand, s});
    if (it == rate_.end()) return std::nullopt;
    return it->second;
  }

  // One target row: numerator/denominator per s, with the goal.
  void target_row(std::ostringstream& o, const std::string& label, const std::string& integrand,
                  const std::string& num, unsigned num_threads, const std::string& den,
                  unsigned den_threads, double goal, int& met, int& total, int& unmeasurable,
                  bool show_cores = false) const {
    o << "| " << label << " | " << integrand << " | ≥ " << goal << "× |";
    for (std::size_t s : c_.dimensions) {
      const auto a = rate(num, num_threads, integrand, s);
      const auto b = rate(den, den_threads, integrand, s);
      if (!a || !b) {
        o << " — |";
        continue;
      }
      const double ratio = *a / *b;
      // A run that got less than 0.75 of a core per thread measured the machine's other work,
      // not the method: the ratio is shown but counted neither as met nor as missed.
      const double cores = cores_.at({num, num_threads, integrand, s});
      const double den_cores = cores_.at({den, den_threads, integrand, s});
      const bool starved = cores < 0.75 * num_threads || den_cores < 0.75 * den_threads;
      const std::string mark = starved ? "⚠" : ratio >= goal ? "✅" : "❌";
      if (starved) {
        ++unmeasurable;
      } else {
        ++total;
        if (ratio >= goal) ++met;
      }
      o << fmt::format(" {:.2f}× {}", ratio, mark);
      if (show_cores || starved) o << fmt::format(" ({:.2f} / {:.2f} cores)", cores, den_cores);
      o << " |";
    }
    o << "\n";
  }

  void targets(std::ostringstream& o) const {
    o << "## Targets (measured, never asserted)\n\n"
         "Ratios of evaluations per second (throughput rows), on the Genz integrands. "
         "✅ met, ❌ missed, ⚠ not measurable in this run (see below the table).\n\n"
         "| ratio | integrand | goal |";
    for (std::size_t s : c_.dimensions) o << " s = " << s << " |";
    o << "\n|---|---|---|";
    for (std::size_t i = 0; i < c_.dimensions.size(); ++i) o << "---|";
    o << "\n";
    int met = 0, total = 0, unmeasurable = 0;
    const std::vector<std::string> genz{"genz_oscillatory", "genz_gaussian"};
    const std::string mc = "quadmc plain MC";
    for (const auto& g : genz) {
      target_row(o, "plain MC (1 thread) / scalar reference loop", g, mc, 1,
                 "scalar reference loop", 1, 1.0, met, total, unmeasurable);
    }
    for (const auto& g : genz) {
      target_row(o, "plain MC (1 thread) / GSL plain", g, mc, 1, "GSL plain", 1, 2.0, met, total,
                 unmeasurable);
    }
    for (const auto& g : genz) {
      target_row(o, "plain MC (1 thread) / Boost naive_monte_carlo (1 thread)", g, mc, 1,
                 "Boost naive_monte_carlo", 1, 2.0, met, total, unmeasurable);
    }
    for (const auto& name : {"quadmc jittered", "quadmc Latin hypercube"}) {
      for (const auto& g : genz) {
        target_row(o, fmt::format("{} / plain MC (1 thread each)", name), g, name, 1, mc, 1, 0.7,
                   met, total, unmeasurable);
      }
    }
    for (const auto& name : {"quadmc tensor Simpson", "quadmc tensor trapezoid"}) {
      for (const auto& g : genz) {
        target_row(o, fmt::format("{} / plain MC (1 thread each)", name), g, name, 1, mc, 1, 2.0,
                   met, total, unmeasurable);
      }
    }
    for (const auto& name : {"quadmc plain MC", "quadmc jittered", "quadmc Latin hypercube",
                             "quadmc tensor Simpson", "quadmc tensor trapezoid"}) {
      for (const auto& g : genz) {
        target_row(o, fmt::format("{}: 2 threads / 1 thread (N ≥ 10⁶)", name), g, name, 2, name, 1,
                   1.8, met, total, unmeasurable, true);
      }
    }
    o << fmt::format(
        "\n**{} of {} measured ratios met**; {} not measurable (⚠). \"cores\": process CPU "
        "time / wall time of the kept run (CLOCK_PROCESS_CPUTIME_ID), i.e. how much of the "
        "machine the run actually got. A ratio is marked ⚠ instead of ✅/❌ when either of its "
        "two runs got less than 0.75 of a core per thread in the best of its {} rounds: the "
        "machine's other work held a core, so the ratio measures that work, not the method.\n\n",
        met, total, unmeasurable, c_.throughput_runs);
  }

  void throughput(std::ostringstream& o) const {
    o << "## Throughput: million evaluations per second\n\n"
         "Per method and thread count; in parentheses the ratio to the scalar reference loop "
         "(same integrand, same s, one thread). Two threads on a 2-core machine: the ideal is "
         "2× the one-thread figure. † fewer than 10⁵ evaluations: the method stopped early "
         "because it had converged (adaptive 1D rules at their tightest tolerance) or its rule "
         "is exact for the integrand (cubature on the sum of coordinates: error estimate 0 "
         "after one rule application), so the figure is mostly set-up cost, not a rate.\n\n";
    for (const auto& integrand : integrands_) {
      o << "### " << integrand << "\n\n| method | threads |";
      for (std::size_t s : c_.dimensions) o << " s = " << s << " |";
      o << "\n|---|---|";
      for (std::size_t i = 0; i < c_.dimensions.size(); ++i) o << "---|";
      o << "\n";
      for (const auto& [method, threads] : methods_) {
        bool any = false;
        std::string line = fmt::format("| {} | {} |", method, threads);
        for (std::size_t s : c_.dimensions) {
          const auto r = rate(method, threads, integrand, s);
          const auto ref = rate("scalar reference loop", 1, integrand, s);
          if (!r) {
            line += " — |";
            continue;
          }
          any = true;
          const bool short_run = evaluations_.at({method, threads, integrand, s}) < 1e5;
          line += fmt::format(" {}{} ({:.2f}×) |", format_rate(*r), short_run ? " †" : "",
                              ref ? *r / *ref : NAN);
        }
        if (any) o << line << "\n";
      }
      o << "\n";
    }
  }

  void accuracy(std::ostringstream& o) const {
    o << "## Time to reach an absolute error of 10⁻³ and 10⁻⁵\n\n"
         "Interpolated on the work-precision ladder (one thread; log time against log error "
         "between the last point above ε and the first of the tail that stays below); "
         "\"≤ t\": already below ε at the smallest ladder point; \"not reached\": not within "
         "the ladder (N ≤ 10⁶, or the peer's own limit). Random methods: RMS error over the "
         "seeds, so one lucky seed does not count.\n\n";
    for (const auto& integrand : integrands_) {
      o << "### " << integrand << "\n\n| method |";
      for (std::size_t s : c_.dimensions) o << " s = " << s << ": 10⁻³ | 10⁻⁵ |";
      o << "\n|---|";
      for (std::size_t i = 0; i < c_.dimensions.size(); ++i) o << "---|---|";
      o << "\n";
      for (const auto& [method, threads] : methods_) {
        bool any = false;
        std::string line = "| " + method + " |";
        for (std::size_t s : c_.dimensions) {
          const auto it = ladder_.find({method, threads, integrand, s});
          if (it == ladder_.end()) {
            line += " — | — |";
            continue;
          }
          any = true;
          for (double eps : {1e-3, 1e-5}) {
            const time_to_accuracy t = time_to_reach(it->second, eps);
            switch (t.outcome) {
              case time_to_accuracy::status::reached:
                line += " " + format_seconds(t.seconds) + " |";
                break;
              case time_to_accuracy::status::at_most:
                line += " ≤ " + format_seconds(t.seconds) + " |";
                break;
              case time_to_accuracy::status::not_reached:
                line += " not reached |";
                break;
            }
          }
        }
        if (any) o << line << "\n";
      }
      o << "\n";
    }
  }

  void memory(std::ostringstream& o) const {
    o << "## Peak memory of quadmc's methods\n\n"
         "Peak RSS (VmHWM of /proc/self/status, read by the child at its end) of a fresh child "
         "process — this program re-executed as `quadmc_peers --one METHOD genz_gaussian 2 N 2` "
         "— that integrates Genz Gaussian, s = 2, with 2 threads. Not getrusage's ru_maxrss: "
         "Linux carries it over fork and exec, so a child would report the parent's peak "
         "(bench/common/peak_rss.hpp). Jittered and tensor sizes are the nearest valid ones "
         "(k² and (n+1)²). Baseline: the same child doing no integration (libraries, one "
         "integrand). What "
         "grows with N is bounded: parallel_reduce folds at most 4096 chunk results at a "
         "time (core/parallel_reduce.hpp), so the slots stop growing at 4096 chunks — "
         "4096 × 128-byte sample_statistics = 512 KiB for Monte Carlo (reached at 5·10⁷ "
         "points), 4096 × 16-byte Neumaier sums for tensor rules — whatever N; nothing "
         "is stored per point.\n\n"
         "| method |";
    for (std::uint64_t n : c_.rss_sizes) o << " N = " << power_of_ten(n) << " |";
    o << " growth |\n|---|";
    for (std::size_t i = 0; i <= c_.rss_sizes.size(); ++i) o << "---|";
    o << "\n";
    o << fmt::format("| baseline (no integration) | {} KiB |", rss_baseline_);
    for (std::size_t i = 1; i < c_.rss_sizes.size(); ++i) o << " |";
    o << " |\n";
    for (const auto& r : rss_) {
      o << "| " << r.method << " |";
      for (long k : r.kib) o << " " << k << " KiB |";
      o << fmt::format(" {:+} KiB |\n", r.kib.back() - r.kib.front());
    }
    o << "\n";
  }

  void determinism(std::ostringstream& o) const {
    if (!st_.repro) return;
    const auto& r = *st_.repro;
    o << "## Same seed, same answer?\n\n";
    o << fmt::format(
        "{}, s = {}, N = {}: quadmc plain MC with 1 thread gives {:.17g}, with 2 threads {:.17g} "
        "({}). Boost naive_monte_carlo (default threads) run {} times with the same seed and "
        "error goal:",
        r.integrand, r.s, c_.throughput_n, r.quadmc_one_thread, r.quadmc_two_threads,
        std::bit_cast<std::uint64_t>(r.quadmc_one_thread) ==
                std::bit_cast<std::uint64_t>(r.quadmc_two_threads)
            ? "bitwise identical"
            : "**different bits**",
        r.boost_values.size());
    for (double v : r.boost_values) o << fmt::format(" {:.17g}", v);
    bool same = true;
    for (double v : r.boost_values) same &= v == r.boost_values.front();
    o << (same ? " (identical this time).\n\n"
               : " — it changes from run to run: its threads race to the goal and the master "
                 "stops them at a time-dependent point.\n\n");
  }

  void notes(std::ostringstream& o) const {
    std::ifstream in(QUADMC_PEERS_NOTES);
    // Read into a string first: streaming an empty rdbuf() would set failbit on `o`.
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!text.empty()) o << text << "\n";
  }

  const configuration& c_;
  const study& st_;
  std::vector<rss_row> rss_;
  long rss_baseline_;
  double wall_;
  std::map<key, double> rate_;
  std::map<key, double> cores_;        // process CPU time / wall time of the kept throughput run
  std::map<key, double> evaluations_;  // evaluations of the kept throughput run
  std::map<key, std::vector<ladder_point>> ladder_;
  std::vector<std::string> integrands_;
  std::vector<std::pair<std::string, unsigned>> methods_;
};

int run(int argc, char** argv) {
  std::filesystem::path out = "results/peers";
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--one" && i + 5 < argc) {
      return run_one(argv[i + 1], argv[i + 2], std::stoul(argv[i + 3]), std::stoull(argv[i + 4]),
                     static_cast<unsigned>(std::stoul(argv[i + 5])));
    }
    if (a == "--out" && i + 1 < argc) {
      out = argv[++i];
    } else if (a == "--quick") {
      quick = true;
    } else {
      std::cerr << "usage: quadmc_peers [--out DIR] [--quick]\n"
                   "       quadmc_peers --one METHOD INTEGRAND S N THREADS\n"
                   "  --quick  a smoke run (small N, seconds): numbers not for the record\n"
                   "  --one    run one method once, print its peak RSS in KiB (for profilers)\n";
      return 2;
    }
  }
  gsl_set_error_handler_off();  // GSL failures come back as status codes (gsl_monte_methods.hpp)
  const auto start = std::chrono::steady_clock::now();
  const configuration c = quick ? quick_configuration() : configuration{};
  study st;
  st.load_before = load_average();
  for (std::size_t s : c.dimensions) {
    auto po = genz_random_parameters(genz_family::oscillatory, s, genz_seed);
    measure(genz_oscillatory(std::move(po.a), std::move(po.u)), c, st);
    auto pg = genz_random_parameters(genz_family::gaussian, s, genz_seed);
    measure(genz_gaussian(std::move(pg.a), std::move(pg.u)), c, st);
    measure(sum_of_coordinates(s), c, st);
  }
  // ratio_to_scalar_loop on throughput rows.
  std::map<std::pair<std::string, std::size_t>, double> reference;
  for (const row& r : st.rows) {
    if (r.run == "throughput" && r.method == "scalar reference loop")
      reference[{r.integrand, r.s}] = r.rate;
  }
  for (row& r : st.rows) {
    const auto it = reference.find({r.integrand, r.s});
    if (r.run == "throughput" && it != reference.end())
      r.ratio_to_scalar_loop = r.rate / it->second;
  }

  std::cerr << "peak RSS:" << std::flush;
  // The memory case: Genz Gaussian, s = 2, 2 threads.
  auto one = [](const std::string& method, std::uint64_t n) {
    return bench::child_peak_rss_kib(
        {"--one", method, "genz_gaussian", "2", std::to_string(n), "2"});
  };
  const long baseline = one("baseline", 1);
  std::vector<rss_row> rss;
  for (const auto& m : rss_methods) {
    std::cerr << " " << m << std::flush;
    rss_row r{rss_method_name(m), {}};
    for (std::uint64_t n : c.rss_sizes) {
      r.kib.push_back(one(m, n));
    }
    rss.push_back(r);
  }
  std::cerr << "\n";
  st.load_after = load_average();
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::filesystem::create_directories(out);
  write_csv(out / "peers.csv", st.rows);
  const std::string command =
      "cmake -S . -B build/peers -G Ninja -DCMAKE_BUILD_TYPE=Release \\\n"
      "  -DCMAKE_CXX_FLAGS_RELEASE='-O2 -DNDEBUG' -DQUADMC_BUILD_TESTS=OFF\n"
      "cmake --build build/peers --target quadmc_peers\n"
      "build/peers/bench/peers/quadmc_peers --out results/peers\n"
      "/usr/bin/python3 bench/peers/plot_peers.py results/peers";
  std::ofstream(out / "README.md") << report(c, st, rss, baseline, wall).markdown(command);
  std::cerr << fmt::format("wrote {}/peers.csv and README.md in {:.0f} s\n", out.string(), wall);
  return 0;
}

}  // namespace
}  // namespace quadmc::peers

int main(int argc, char** argv) {
  try {
    return quadmc::peers::run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "quadmc_peers: " << e.what() << "\n";
    return 1;
  }
}
