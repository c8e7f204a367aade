// Ladder, throughput and reproducibility of the methods; what and how: measurement.hpp.
#include "measurement.hpp"

#include "boost_math_methods.hpp"
#include "cubature_methods.hpp"
#include "gsl_monte_methods.hpp"
#include "memory_write.hpp"
#include "peer_method.hpp"
#include "qmc_point_peers.hpp"
#include "quadmc_methods.hpp"
#include "sum_of_coordinates.hpp"

#include "scalar_reference_loop.hpp"  // bench/common

#include "quadmc/core/batching.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/core/simd_level.hpp"
#include "quadmc/estimators/monte_carlo.hpp"
#include "quadmc/functions/genz.hpp"
#include "quadmc/sampling/independent_points.hpp"

#include <fmt/format.h>
#include <gsl/gsl_errno.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <ctime>
#include <exception>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#ifndef QUADMC_PEERS_PYTHON
#define QUADMC_PEERS_PYTHON "/usr/bin/python3"
#endif
#ifndef QUADMC_PEERS_SCIPY_SCRIPT
#define QUADMC_PEERS_SCIPY_SCRIPT "bench/peers/scipy_qmc.py"
#endif
#ifndef QUADMC_PEERS_PYTHON_MODULE_SCRIPT
#define QUADMC_PEERS_PYTHON_MODULE_SCRIPT "bench/peers/python_module_speed.py"
#endif
// The folder of this build's Python module (bench/python/CMakeLists.txt), empty without one.
#ifndef QUADMC_PEERS_PYTHON_MODULE_DIR
#define QUADMC_PEERS_PYTHON_MODULE_DIR ""
#endif

namespace quadmc::peers {
namespace {

bool is_limit(const peer_method& m) {
  return m.family == "limit";
}

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

// The limit beside every figure: f alone on one batch of batch_points points (the batch every
// kernel hands it, core/batching.hpp), computed once before the timing so that it sits in cache,
// evaluated ⌈N / batch_points⌉ times through the call every method makes (F::evaluate on the
// concrete type, inlined where the kernels inline it). No point generation, no statistics, no
// finite check: what is left is the integrand's own cost, the ceiling of every method's rate.
//
// With two threads, both take chunks of 48 calls from one counter and evaluate them on the
// shared read-only batch into their own outputs: no shared writes but the chunk's slot, no
// waiting but the join; a thread started late (they start inside the timed run) only misses
// chunks, as a pool thread woken late does. Its two-thread / one-thread ratio is printed beside
// every two-thread target (targets.hpp): what the machine gave code with nothing to wait for,
// in the same rounds.
template <class F>
peer_method integrand_only(const F& f, std::uint64_t throughput_n, unsigned threads) {
  const std::size_t s = f.dimension();
  auto x = std::make_shared<std::vector<double>>(batch_points * s);
  independent_points(s, batch_points, base_seed, stream_id({0x11}))
      .generate(0, std::span<double>(*x));
  peer_method m;
  m.name = integrand_only_method;
  m.family = "limit";
  m.threads = threads;
  m.random = false;
  m.throughput_control = throughput_n;
  m.run = [&f, x, threads](std::uint64_t n, std::uint64_t) {
    constexpr std::uint64_t chunk_calls = sample_chunk_points / batch_points;
    const std::uint64_t batches = (n + batch_points - 1) / batch_points;
    // One slot per chunk, added in chunk order: the same value for any thread count.
    std::vector<double> sums((batches + chunk_calls - 1) / chunk_calls, 0.0);
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
      std::vector<double> y(batch_points);
      for (std::size_t c = next++; c < sums.size(); c = next++) {
        double sum = 0.0;
        const std::uint64_t last = std::min(batches, (c + 1) * chunk_calls);
        for (std::uint64_t b = c * chunk_calls; b < last; ++b) {
          f.evaluate(std::span<const double>(*x), std::span<double>(y));
          sum += y[b % batch_points];  // a use of every call's output, so no call is dropped
        }
        sums[c] = sum;
      }
    };
    std::vector<std::thread> helpers;
    for (unsigned t = 1; t < threads; ++t) helpers.emplace_back(work);
    work();
    for (std::thread& h : helpers) h.join();
    double sum = 0.0;
    for (const double v : sums) sum += v;
    return run_result{sum / static_cast<double>(batches), batches * batch_points};
  };
  return m;
}

// Every method measured on f: the integrand alone at 1 and 2 threads, the scalar loop, quadmc's own
// at 1 and 2 threads (ladders at one thread and for the five classic ones only; plain MC under
// each generator), GSL's three, Boost's naive_monte_carlo at 1 and default threads, cubature's
// two, and for s = 1 Boost's three 1D rules.
template <class F>
std::vector<peer_method> methods_for(const F& f, const configuration& c, double variance) {
  const std::size_t s = f.dimension();
  std::vector<peer_method> m;
  m.push_back(integrand_only(f, c.throughput_n, 1));
  m.push_back(integrand_only(f, c.throughput_n, 2));
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
    // The same estimator and points with ARS's uniforms instead of Philox's: the generator's
    // cost is most of plain MC's beyond the integrand at s = 8 (bench/peers/profile_notes.md),
    // and ARS's is a few AES instructions per block (docs/theory.md#counter-based-generators).
    m.push_back(quadmc_monte_carlo<independent_points>(plain_mc_ars_method, f, threads, ladder,
                                                       c.throughput_n, rng_kind::ars4x32_7));
    m.push_back(
        quadmc_monte_carlo<jittered_points>("quadmc jittered", f, threads, ladder, c.throughput_n));
    m.push_back(quadmc_monte_carlo<latin_hypercube_points>("quadmc Latin hypercube", f, threads,
                                                           ladder, c.throughput_n));
    m.push_back(quadmc_tensor_rule<simpson_rule>("quadmc tensor Simpson", f, threads, ladder,
                                                 c.tensor_throughput_n));
    m.push_back(quadmc_tensor_rule<trapezoid_rule>("quadmc tensor trapezoid", f, threads, ladder,
                                                   c.tensor_throughput_n));
    m.push_back(quadmc_quasi_monte_carlo<sobol_points<linear_matrix_scramble>>(
        "quadmc sobol lms_shift", f, threads, c.throughput_n));
    // The digit-scrambled sets cost 0.1–1 s per run: only on the Genz integrands, where the
    // targets are (about 25 s of the study saved on the sum of coordinates).
    if constexpr (!std::is_same_v<F, sum_of_coordinates>) {
      m.push_back(quadmc_quasi_monte_carlo<sobol_points<fast_owen_scramble>>(
          "quadmc sobol fast_owen", f, threads, c.throughput_n));
      m.push_back(quadmc_quasi_monte_carlo<sobol_points<owen_scramble>>("quadmc sobol owen", f,
                                                                        threads, c.throughput_n));
      // The halton method's default randomization (estimators/point_set_catalogue.cpp).
      m.push_back(quadmc_quasi_monte_carlo<halton_points<nested_digit_scramble>>(
          "quadmc halton owen", f, threads, c.small_throughput_n));
    }
    m.push_back(quadmc_quasi_monte_carlo<rank1_lattice_points<no_periodization>>(
        "quadmc lattice shift", f, threads, std::min(c.small_throughput_n, max_lattice_points)));
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

// The ladder of every method, then its throughput in rounds, then (once, at s = 2) the
// reproducibility check; rows and skipped points go into out.
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
  std::vector<int> runs(methods.size(), 0);
  std::vector<double> spent(methods.size(), 0.0);
  const std::uint64_t seed = stream_id({base_seed, 0xf00d});
  for (int round = 0; round < c.throughput_runs; ++round) {
    for (std::size_t k = 0; k < methods.size(); ++k) {
      const peer_method& m = methods[k];
      if (m.throughput_control == 0 || failed[k]) continue;
      // Enough runs of this method already: at least the minimum, and their time long enough
      // that the best of them is its own cost (configuration::min_throughput_seconds).
      if (runs[k] >= c.min_throughput_runs && spent[k] >= c.min_throughput_seconds) continue;
      try {
        const timed_run t = best_of([&] { return m.run(m.throughput_control, seed); }, 1, 0.0, 1);
        ++runs[k];
        spent[k] += t.seconds;
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
      // The integrand alone computes no estimate: no error to show.
      r.abs_error = is_limit(methods[k]) ? NAN : std::abs(t.result.value - exact);
      r.repetitions = runs[k];
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

}  // namespace

void measure_methods(const configuration& c, study& out) {
  gsl_set_error_handler_off();  // GSL failures come back as status codes (gsl_monte_methods.hpp)
  for (std::size_t s : c.dimensions) {
    auto po = genz_random_parameters(genz_family::oscillatory, s, genz_seed);
    measure(genz_oscillatory(std::move(po.a), std::move(po.u)), c, out);
    auto pg = genz_random_parameters(genz_family::gaussian, s, genz_seed);
    measure(genz_gaussian(std::move(pg.a), std::move(pg.u)), c, out);
    measure(sum_of_coordinates(s), c, out);
  }
  // ratio_to_scalar_loop on throughput rows.
  std::map<std::pair<std::string, std::size_t>, double> reference;
  for (const row& r : out.rows) {
    if (r.run == "throughput" && r.method == "scalar reference loop")
      reference[{r.integrand, r.s}] = r.rate;
  }
  std::map<std::pair<std::string, std::size_t>, double> limit;
  for (const row& r : out.rows) {
    if (r.run == "throughput" && r.method == integrand_only_method && r.threads == 1)
      limit[{r.integrand, r.s}] = r.rate;
  }
  for (row& r : out.rows) {
    if (r.run != "throughput") continue;
    const auto it = reference.find({r.integrand, r.s});
    if (it != reference.end()) r.ratio_to_scalar_loop = r.rate / it->second;
    const auto lim = limit.find({r.integrand, r.s});
    if (lim != limit.end()) r.ratio_to_integrand_only = r.rate / lim->second;
  }
}

void measure_uniforms(const configuration& c, study& out) {
  std::cerr << "uniforms per second" << std::flush;
  struct writer {
    std::string method, family, kernel;
    bool in_cache = true;  // false: only into the large buffer (streaming stores bypass the cache)
    // Writes the buffer as the `fill`-th fill of the run.
    std::function<void(std::span<double>, std::uint64_t fill)> write;
  };
  std::vector<writer> writers;
  // Philox's kernel is the level's pmuludq lanes, Random123's own code at scalar
  // (lib/src/core/philox_blocks.cpp); ARS names its own.
  const simd_level level = active_simd_level();
  const std::string philox_kernel = level == simd_level::scalar
                                        ? std::string("Random123 (scalar)")
                                        : fmt::format("pmuludq ({})", to_string(level));
  for (const rng_kind g : {rng_kind::philox4x32_10, rng_kind::ars4x32_7}) {
    const random_stream stream(base_seed, stream_id({0x0f11}), g);
    writers.push_back(
        {fmt::format("quadmc fill_uniform {}", to_string(g)), "quadmc",
         g == rng_kind::ars4x32_7 ? std::string(quadmc::detail::ars_kernel()) : philox_kernel, true,
         [stream](std::span<double> out, std::uint64_t fill) {
           // Each fill draws the next uniforms of the stream, as consecutive batches of a point
           // set do; the generator's cost does not depend on the index.
           stream.fill_uniform(fill * out.size(), out);
         }});
  }
  for (const store_kind k : {store_kind::ordinary, store_kind::streaming}) {
    writers.push_back(
        {k == store_kind::ordinary ? ordinary_stores_method : "write doubles (streaming stores)",
         "memory", std::string(write_kernel(k)), k == store_kind::ordinary,
         [k](std::span<double> out, std::uint64_t fill) {
           write_doubles(out, 0.25 + static_cast<double>(fill), k);
         }});
  }
  aligned_doubles cache(c.uniform_cache_doubles);
  aligned_doubles memory(c.uniform_memory_doubles);
  struct buffer {
    std::span<double> doubles;
    std::uint64_t fills;  // per run: ≥ throughput_n doubles, so that a run is not timer-bound
  };
  const auto fills = [&c](std::uint64_t n) {
    return std::max<std::uint64_t>(1, (c.throughput_n + n - 1) / n);
  };
  const std::vector<buffer> buffers{{cache.span(), fills(c.uniform_cache_doubles)},
                                    {memory.span(), fills(c.uniform_memory_doubles)}};
  std::vector<std::optional<timed_run>> best(writers.size() * buffers.size());
  for (int round = 0; round < c.uniform_rounds; ++round) {
    for (std::size_t b = 0; b < buffers.size(); ++b) {
      for (std::size_t w = 0; w < writers.size(); ++w) {
        if (b == 0 && !writers[w].in_cache) continue;
        const buffer& buf = buffers[b];
        const timed_run t = best_of(
            [&] {
              for (std::uint64_t fill = 0; fill < buf.fills; ++fill) {
                writers[w].write(buf.doubles, fill);
                // The stores are observed here, so no fill of the run can be dropped as dead.
                asm volatile("" : : "r"(buf.doubles.data()) : "memory");
              }
              return run_result{buf.doubles.front() + buf.doubles.back(),
                                buf.fills * buf.doubles.size()};
            },
            1, 0.0, 1);
        auto& kept = best[b * writers.size() + w];
        if (!kept || t.seconds < kept->seconds) kept = t;
      }
    }
    std::cerr << "." << std::flush;
  }
  for (std::size_t b = 0; b < buffers.size(); ++b) {
    for (std::size_t w = 0; w < writers.size(); ++w) {
      const auto& kept = best[b * writers.size() + w];
      if (!kept) continue;
      row r;
      r.run = "uniforms";
      r.method = writers[w].method;
      r.family = writers[w].family;
      r.integrand = "(uniforms only)";
      r.s = 1;
      r.threads = 1;
      r.n = buffers[b].doubles.size();
      r.control = "doubles per buffer";
      r.evaluations = static_cast<double>(kept->result.evaluations);
      r.seconds = kept->seconds;
      r.cpu_seconds = kept->cpu_seconds;
      r.rate = r.evaluations / r.seconds;
      r.abs_error = NAN;
      r.repetitions = c.uniform_rounds;
      r.kernel = writers[w].kernel;
      out.rows.push_back(r);
    }
  }
  std::cerr << "\n";
}

void measure_qmc_points(const configuration& c, study& out) {
  const std::vector<point_generator> generators =
      qmc_point_generators(QUADMC_PEERS_PYTHON, QUADMC_PEERS_SCIPY_SCRIPT);
  std::cerr << "QMC points: agreement" << std::flush;
  out.agreement = check_point_agreement(generators);
  const std::uint64_t n = c.qmc_points;
  const std::uint64_t seed = stream_id({base_seed, 0x9c});
  for (std::size_t s : c.qmc_dimensions) {
    std::cerr << fmt::format(" s={}", s) << std::flush;
    struct best_run {
      double seconds = INFINITY;
      double cpu_seconds = NAN;  // NaN for scipy: its CPU time is the child's
    };
    std::vector<std::optional<best_run>> best(generators.size());
    std::vector<bool> failed(generators.size(), false);
    auto attempt = [&](std::size_t k, int runs) {
      const point_generator& g = generators[k];
      try {
        const double cpu_start = process_cpu_seconds();
        const generated_points p = g.generate(n, s, seed, runs, false);
        const double cpu = process_cpu_seconds() - cpu_start;
        if (!best[k] || p.seconds < best[k]->seconds) {
          best[k] = best_run{p.seconds, g.in_process ? cpu : NAN};
        }
      } catch (const std::exception& e) {
        failed[k] = true;
        out.skipped.push_back(fmt::format("{} at s = {}, N = {}: {}", g.name, s, n, e.what()));
      }
    };
    for (std::size_t k = 0; k < generators.size(); ++k) {
      if (s > generators[k].max_dimension) {
        failed[k] = true;
        out.skipped.push_back(fmt::format("{} at s = {}: at most {} dimensions", generators[k].name,
                                          s, generators[k].max_dimension));
      } else if (!generators[k].in_process) {
        attempt(k, c.qmc_point_runs);
      }
    }
    for (int round = 0; round < c.qmc_point_runs; ++round) {
      for (std::size_t k = 0; k < generators.size(); ++k) {
        if (generators[k].in_process && !failed[k]) attempt(k, 1);
      }
      std::cerr << "." << std::flush;
    }
    for (std::size_t k = 0; k < generators.size(); ++k) {
      if (!best[k]) continue;
      row r;
      r.run = "points";
      r.method = generators[k].name;
      r.family = generators[k].family;
      r.integrand = "(points only)";
      r.s = s;
      r.threads = 1;
      r.n = n;
      r.control = "N points";
      r.evaluations = static_cast<double>(n);
      r.seconds = best[k]->seconds;
      r.cpu_seconds = best[k]->cpu_seconds;
      r.rate = static_cast<double>(n) / r.seconds;
      r.abs_error = NAN;
      r.repetitions = c.qmc_point_runs;
      out.rows.push_back(r);
    }
  }
  std::cerr << "\n";
}

void measure_python_module(const configuration& c, study& out) {
  std::cerr << "Python module: " << c.python_module_rounds << " rounds" << std::flush;
  out.python_module = quadmc::peers::measure_python_module(
      QUADMC_PEERS_PYTHON, QUADMC_PEERS_PYTHON_MODULE_SCRIPT, QUADMC_PEERS_PYTHON_MODULE_DIR,
      c.python_module_rounds, base_seed);
  if (!out.python_module.skipped.empty()) {
    out.skipped.push_back("the Python module: " + out.python_module.skipped);
  }
  for (const python_timing& t : out.python_module.timings) {
    const python_row_names names = names_of(t);
    row r;
    r.run = "python";
    r.method = names.method;
    r.family = names.family;
    r.integrand = names.integrand;
    r.s = t.s;
    r.threads = 1;
    r.n = t.n;
    r.control = t.group == "points_reused" ? "N points (reused memory)"
                : t.group == "points"      ? "N points (fresh memory)"
                                           : "N evaluations";
    r.evaluations = static_cast<double>(t.n);
    r.seconds = t.median;
    r.seconds_min = t.min;
    r.seconds_max = t.max;
    r.rate = static_cast<double>(t.n) / t.median;
    r.abs_error = NAN;
    r.repetitions = t.rounds;
    out.rows.push_back(r);
  }
  std::cerr << "\n";
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  double one = 0, five = 0, fifteen = 0;
  in >> one >> five >> fifteen;
  return fmt::format("{:.2f} / {:.2f} / {:.2f}", one, five, fifteen);
}

}  // namespace quadmc::peers
