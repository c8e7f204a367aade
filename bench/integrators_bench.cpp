// Throughput of every integrator on the six Genz integrands, s ∈ {1, 2, 4, 8}, beside the
// hand-written scalar loop, and the peak memory of each method at N = 10^6 and 10^8
// (docs/design.md#performance-targets).
//
// Use it for cost: evaluations per second (`evals_per_second`, a kIsIterationInvariantRate
// counter over wall time) and the ratio to the scalar reference loop (`ratio_to_scalar_loop`),
// with the error each run reached (`abs_error`, against the closed-form reference) and the
// integrand evaluations of one iteration (`evaluations`, as counted by the estimator or rule,
// never assumed). Not a convergence study: error against N with fitted slopes is `quadmc run`,
// because Google Benchmark's Complexity() fits time, not error (STYLE.md). Not the peers table
// either: GSL, Boost.Math and cubature are measured by bench/peers/quadmc_peers.
//
// Benchmarks (registered in this order, which is the order they run in):
//  - scalar_loop/<integrand>/s:S/threads:1 — bench/common/scalar_reference_loop.hpp: xoshiro256+,
//    s uniforms per point, the integrand through a batch of one, plain sum, one thread;
//  - <method>/<integrand>/s:S/threads:T, method ∈ {plain_mc, jittered, latin_hypercube,
//    padded_jittered, trapezoid, simpson, midpoint, gauss_legendre (m = 3 nodes per panel)},
//    integrand ∈ {genz_oscillatory, genz_gaussian, genz_continuous, genz_product_peak,
//    genz_corner_peak, genz_discontinuous}, T = 1 for every s and T = 2 for s ∈ {1, 8}
//    (T is quadmc's own thread count; Google Benchmark runs each benchmark on one thread);
//  - tensor_vs_plain/<method>/<integrand>/s:S — tensor rules against plain MC at N ≈ 4·10⁶
//    (see its section below);
//  - peak_rss/<method> — see below.
// Sizes per iteration: N = 2^20 for plain, Latin hypercube and padded jittered points; k^s with
// k = round(2^(20/s)) for jittered points (the stratified size nearest 2^20 on a log scale:
// 6^8 = 1 679 616 at s = 8); tensor rules take the largest panel count n whose grid m(n)^s is
// ≤ 2^20 (m(n) = n + 1 for trapezoid and Simpson, n even for Simpson; n for midpoint; 3n for
// Gauss–Legendre), so at s = 8 they run 5^8 = 390 625 points (Gauss–Legendre 3^8 = 6 561: one
// panel is the smallest grid, and its rate then includes the fixed cost of a call). The point set
// is built inside the timed loop (for Latin hypercube and padded jittered points that includes
// their permutations), with a new stream id each iteration. Integrand parameters are fixed, not
// drawn: aᵢ = genz_normalise(family, w = 1) (Σaᵢ = Genz's difficulty b_f), uᵢ = 0.5.
//
// ratio_to_scalar_loop = (this benchmark's evaluations per wall-clock second) ÷ (the scalar
// loop's evaluations per wall-clock second for the same integrand and s). The numerator is
// evaluations × iterations over the steady_clock time of the timed loop (the same figure as
// evals_per_second, which Google Benchmark divides by the loop's real time). The denominator is
// taken from scalar_loop/<integrand>/s:S if that benchmark has run in this process (its last
// run, i.e. the one in the table, so the column is the quotient of two rows), else it is measured
// on demand before the timed loop — best of 3 runs of 2^20 points timed with steady_clock — and
// kept for the rest of the run, so a --benchmark_filter that leaves the scalar loop out still gets
// the column. The scalar loop is single-threaded, so a threads:2 row's ratio includes its
// parallel speed-up. The targets of docs/design.md#performance-targets read off this column:
// plain_mc ≥ 1.0 (one thread), jittered ≥ 0.85 and latin_hypercube ≥ 0.7 × plain_mc, tensor
// Simpson/trapezoid ≥ 1.5 × plain_mc at s ≥ 2.
//
// peak_rss/<method>/iterations:1 (Genz Gaussian, s = 2, 2 threads): peak resident memory of a
// fresh child process (this binary re-executed as `integrators_bench --peak-rss-child METHOD N`,
// handled in main() before Google Benchmark starts; bench/common/peak_rss.hpp says why a child
// and VmHWM rather than getrusage) that integrates with N = 10^6 and N = 10^8 evaluations
// (jittered: k² exactly; tensor rules: the largest grid ≤ N, at 10^8 (10⁴)² points for
// trapezoid and midpoint, 9 999² for Simpson and Gauss–Legendre — evaluations_n1e8 says which):
// counters peak_rss_kib_n1e6, peak_rss_kib_n1e8, peak_rss_kib_baseline (the same child doing no
// integration), evaluations_n1e6 and evaluations_n1e8. Constant memory in N shows as
// n1e8 ≈ n1e6. They take up to a few seconds each (the 10^8 run); skip them with
//   integrators_bench --benchmark_filter=-peak_rss
// and run only them with --benchmark_filter=peak_rss.
//
// Default run: 344 benchmarks in about 2½ minutes on 2 shared cores (MinTime 0.2 s each; the
// peak_rss rows about 6 s of it). Timer: wall clock (UseRealTime), since quadmc's threads run
// outside the calling thread's CPU time. Google Benchmark appends /min_time:0.200/real_time
// (peak_rss: /iterations:1/real_time) to every name.
//   build/release/bench/integrators_bench --benchmark_format=json
#include <benchmark/benchmark.h>

#include "peak_rss.hpp"               // bench/common
#include "scalar_reference_loop.hpp"  // bench/common

#include "quadmc/estimators/monte_carlo.hpp"
#include "quadmc/functions/genz.hpp"
#include "quadmc/rules/gauss_legendre_rule.hpp"
#include "quadmc/rules/midpoint_rule.hpp"
#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "quadmc/rules/trapezoid_rule.hpp"
#include "quadmc/sampling/independent_points.hpp"
#include "quadmc/sampling/jittered_points.hpp"
#include "quadmc/sampling/latin_hypercube_points.hpp"
#include "quadmc/sampling/padded_jittered_points.hpp"
#include "quadmc/sampling/rank1_lattice_points.hpp"
#include "quadmc/sampling/sobol_points.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <exception>
#include <iostream>
#include <map>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace {

using namespace quadmc;

constexpr std::uint64_t seed = 42;
constexpr std::uint64_t timed_n = std::uint64_t{1} << 20;  // evaluations per iteration
constexpr double min_time_seconds = 0.2;
// The memory case (peak RSS at N = 10⁶ and 10⁸, docs/design.md#performance-targets): Genz
// Gaussian, s = 2, 2 threads.
constexpr std::size_t rss_dimension = 2;
constexpr unsigned rss_threads = 2;
constexpr std::uint64_t rss_small_n = 1'000'000;
constexpr std::uint64_t rss_large_n = 100'000'000;

// Fixed, documented parameters (Genz normalisation of uniform weights; u = 0.5): the benchmark
// must not depend on a random draw.
template <class F>
F make_genz(genz_family family, std::size_t s) {
  const std::vector<double> w(s, 1.0);
  return F(genz_normalise(family, w), std::vector<double>(s, 0.5));
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The result of one run. Results are kept with benchmark::DoNotOptimize(whole struct), never on
// the double member alone: Google Benchmark 1.7.1 gives GCC the constraint "+m,r" for an
// 8-byte lvalue, and with GCC 12 -O2 the value read after the loop was then garbage (denormal bit
// patterns) for some methods; a 16-byte struct gets "+m", which kept it intact.
struct sized_run {
  double value = 0.0;
  std::uint64_t evaluations = 0;
};

// b^s in 64 bits (exact; the sizes here stay far below 2^64).
std::uint64_t power(std::uint64_t b, std::size_t s) {
  std::uint64_t p = 1;
  for (std::size_t j = 0; j < s; ++j) p *= b;
  return p;
}

// Plain Monte Carlo over the point set P. control = the number of points.
template <class P>
struct monte_carlo_method {
  // Jittered points need N = k^s: k = round(N^{1/s}) (≥ 1), the size nearest N on a log scale.
  std::uint64_t control(std::size_t s, std::uint64_t n) const {
    if constexpr (std::is_same_v<P, jittered_points>) {
      const double k = std::round(std::pow(static_cast<double>(n), 1.0 / static_cast<double>(s)));
      return power(std::max<std::uint64_t>(1, static_cast<std::uint64_t>(k)), s);
    }
    return n;
  }
  std::uint64_t evaluations(std::size_t, std::uint64_t points) const { return points; }
  template <class F>
  sized_run run(const F& f, std::uint64_t points, unsigned threads, std::uint64_t stream) const {
    const P point_set(f.dimension(), points, seed, stream);
    const estimate e = monte_carlo(f, point_set, threads);
    return {e.value, e.evaluations};
  }
};

// Tensor product of the 1D rule R. control = panels per axis.
template <class R>
struct tensor_method {
  R rule;
  static constexpr std::uint64_t panel_step = std::is_same_v<R, simpson_rule> ? 2 : 1;

  std::uint64_t evaluations(std::size_t s, std::uint64_t panels) const {
    return tensor_grid_size(rule.nodes(panels).size(), s);
  }
  // The largest panel count (even for Simpson) whose grid has at most n points: doubling, then
  // bisection on multiples of panel_step (the grid size grows with the panel count).
  std::uint64_t control(std::size_t s, std::uint64_t n) const {
    std::uint64_t lo = panel_step;
    std::uint64_t hi = panel_step;
    while (evaluations(s, hi) <= n) {
      lo = hi;
      hi *= 2;
    }
    while (hi - lo > panel_step) {
      const std::uint64_t mid = lo + (hi - lo) / (2 * panel_step) * panel_step;
      (evaluations(s, mid) <= n ? lo : hi) = mid;
    }
    return lo;
  }
  template <class F>
  sized_run run(const F& f, std::uint64_t panels, unsigned threads, std::uint64_t) const {
    const rule_result r = integrate(f, rule, panels, threads);
    return {r.value, r.evaluations};
  }
};

// Every method, by name, in the order of the table; visit(name, method) for each.
template <class Visitor>
void for_each_method(Visitor&& visit) {
  visit("plain_mc", monte_carlo_method<independent_points>{});
  visit("jittered", monte_carlo_method<jittered_points>{});
  visit("latin_hypercube", monte_carlo_method<latin_hypercube_points>{});
  visit("padded_jittered", monte_carlo_method<padded_jittered_points>{});
  visit("trapezoid", tensor_method<trapezoid_rule>{trapezoid_rule{}});
  visit("simpson", tensor_method<simpson_rule>{simpson_rule{}});
  visit("midpoint", tensor_method<midpoint_rule>{midpoint_rule{}});
  visit("gauss_legendre", tensor_method<gauss_legendre_rule>{gauss_legendre_rule(3)});
}

// The QMC point sets through the same Monte Carlo kernel (throughput rows only, no peak-RSS row:
// the lattice stops at N = 2^20): Sobol' with each scramble and the shifted rank-1 lattice, so
// their evals_per_second divided by plain_mc's is the per-evaluation ratio of the QMC targets
// (lms_shift, fast_owen ≥ 1×, owen ≥ 0.5×, lattice ≥ 1.5× plain MC).
template <class Visitor>
void for_each_qmc_method(Visitor&& visit) {
  visit("sobol_none", monte_carlo_method<sobol_points<unrandomized_digits>>{});
  visit("sobol_lms_shift", monte_carlo_method<sobol_points<linear_matrix_scramble>>{});
  visit("sobol_fast_owen", monte_carlo_method<sobol_points<fast_owen_scramble>>{});
  visit("sobol_owen", monte_carlo_method<sobol_points<owen_scramble>>{});
  visit("lattice_shift", monte_carlo_method<rank1_lattice_points<no_periodization>>{});
}

// Scalar-loop rates (evaluations per wall second) by (integrand, s): written by the scalar_loop
// benchmark, or measured on demand (scalar_loop_rate). Google Benchmark runs benchmarks one
// after another on this thread, so no lock is needed.
std::map<std::pair<genz_family, std::size_t>, double>& scalar_loop_rates() {
  static std::map<std::pair<genz_family, std::size_t>, double> rates;
  return rates;
}

// Called outside the timed loop. Best of 3: on a shared machine noise only slows a run down.
template <class F>
double scalar_loop_rate(genz_family family, std::size_t s) {
  auto& rates = scalar_loop_rates();
  if (const auto it = rates.find({family, s}); it != rates.end()) return it->second;
  const F f = make_genz<F>(family, s);
  double best = 0.0;
  for (std::uint64_t run = 0; run < 3; ++run) {
    const auto start = std::chrono::steady_clock::now();
    const bench::scalar_loop_result r = bench::scalar_reference_loop(f, timed_n, seed + run);
    benchmark::DoNotOptimize(r);
    best = std::max(best, static_cast<double>(r.evaluations) / seconds_since(start));
  }
  rates[{family, s}] = best;
  return best;
}

// The counters of one throughput row; wall_seconds: steady_clock time of the whole timed loop.
void report(benchmark::State& state, std::uint64_t evaluations, double value, double exact,
            double wall_seconds, double scalar_rate) {
  const double evaluations_all =
      static_cast<double>(evaluations) * static_cast<double>(state.iterations());
  state.counters["evals_per_second"] = benchmark::Counter(
      static_cast<double>(evaluations), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["ratio_to_scalar_loop"] = evaluations_all / wall_seconds / scalar_rate;
  state.counters["abs_error"] = std::abs(value - exact);
  state.counters["evaluations"] = static_cast<double>(evaluations);
}

template <class F>
void scalar_loop_bench(benchmark::State& state, genz_family family) {
  const auto s = static_cast<std::size_t>(state.range(0));
  const F f = make_genz<F>(family, s);
  std::uint64_t run = 0;
  bench::scalar_loop_result r;
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    r = bench::scalar_reference_loop(f, timed_n, seed + run++);
    benchmark::DoNotOptimize(r);
  }
  const double wall = seconds_since(start);
  // The last call is the run Google Benchmark reports: its rate is the one the ratios use.
  const double rate =
      static_cast<double>(r.evaluations) * static_cast<double>(state.iterations()) / wall;
  scalar_loop_rates()[{family, s}] = rate;
  report(state, r.evaluations, r.value, f.info().exact, wall, rate);
}

template <class F, class M>
void method_bench(benchmark::State& state, genz_family family, const M& method) {
  const auto s = static_cast<std::size_t>(state.range(0));
  const auto threads = static_cast<unsigned>(state.range(1));
  const F f = make_genz<F>(family, s);
  const double scalar_rate = scalar_loop_rate<F>(family, s);
  const std::uint64_t control = method.control(s, timed_n);
  std::uint64_t stream = 0;
  sized_run r;
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    r = method.run(f, control, threads, ++stream);
    benchmark::DoNotOptimize(r);
  }
  report(state, r.evaluations, r.value, f.info().exact, seconds_since(start), scalar_rate);
}

void dimensions_and_threads(benchmark::internal::Benchmark* b) {
  for (int s : {1, 2, 4, 8}) b->Args({s, 1});
  for (int s : {1, 8}) b->Args({s, 2});
  b->ArgNames({"s", "threads"})
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->MinTime(min_time_seconds);
}

void dimensions_one_thread(benchmark::internal::Benchmark* b) {
  for (int s : {1, 2, 4, 8}) b->Args({s, 1});
  b->ArgNames({"s", "threads"})
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->MinTime(min_time_seconds);
}

template <class F>
void register_integrand(genz_family family) {
  const std::string integrand(to_string(family));
  benchmark::RegisterBenchmark(("scalar_loop/" + integrand).c_str(), [family](
                                                                         benchmark::State& state) {
    scalar_loop_bench<F>(state, family);
  })->Apply(dimensions_one_thread);
  for_each_method([&](const char* name, auto method) {
    benchmark::RegisterBenchmark(
        (std::string(name) + "/" + integrand).c_str(),
        [family, method](benchmark::State& state) { method_bench<F>(state, family, method); })
        ->Apply(dimensions_and_threads);
  });
  for_each_qmc_method([&](const char* name, auto method) {
    benchmark::RegisterBenchmark(
        (std::string(name) + "/" + integrand).c_str(),
        [family, method](benchmark::State& state) { method_bench<F>(state, family, method); })
        ->Apply(dimensions_and_threads);
  });
}

// --- tensor rules against plain Monte Carlo at N ≈ 4·10⁶ -----------------------------------
// tensor_vs_plain/<method>/<integrand>/s:S (method ∈ {plain_mc, trapezoid, simpson}, integrand ∈
// {genz_oscillatory, genz_gaussian}, s ∈ {1, 2, 4, 8}, one thread): the tensor-rule row of
// docs/design.md#performance-targets at the size bench/peers times them (the
// smallest grid (n + 1)^s ≥ 4·10⁶: 2001², 45⁴, 7⁸; plain MC 4·10⁶ points). ratio_to_plain_mc =
// this row's evaluations per wall second ÷ plain_mc's for the same integrand and s (the plain_mc
// rows run first; with a filter that leaves them out, plain MC is timed on demand, best of 3).
//   build/release/bench/integrators_bench --benchmark_filter=tensor_vs_plain
//   --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
constexpr std::uint64_t tensor_vs_plain_n = 4'000'000;

// The smallest panel count (even for Simpson) whose grid has at least n points.
template <class R>
std::uint64_t panels_at_least(const tensor_method<R>& method, std::size_t s, std::uint64_t n) {
  std::uint64_t panels = method.control(s, n);
  while (method.evaluations(s, panels) < n) panels += tensor_method<R>::panel_step;
  return panels;
}

std::map<std::pair<genz_family, std::size_t>, double>& plain_mc_rates() {
  static std::map<std::pair<genz_family, std::size_t>, double> rates;
  return rates;
}

template <class F>
double timed_rate(const F& f, auto&& run) {
  const auto start = std::chrono::steady_clock::now();
  const sized_run r = run(f);
  benchmark::DoNotOptimize(r);
  return static_cast<double>(r.evaluations) / seconds_since(start);
}

template <class F, class M>
void tensor_vs_plain_bench(benchmark::State& state, genz_family family, const M& method,
                           bool is_plain) {
  const auto s = static_cast<std::size_t>(state.range(0));
  const F f = make_genz<F>(family, s);
  const monte_carlo_method<independent_points> plain;
  auto run_plain = [&](const F& g, std::uint64_t stream) {
    return plain.run(g, tensor_vs_plain_n, 1, stream);
  };
  std::uint64_t control = tensor_vs_plain_n;
  if constexpr (!std::is_same_v<M, monte_carlo_method<independent_points>>) {
    control = panels_at_least(method, s, tensor_vs_plain_n);
  }
  auto& rates = plain_mc_rates();
  if (!is_plain && rates.find({family, s}) == rates.end()) {
    double best = 0.0;
    for (std::uint64_t k = 0; k < 3; ++k) {
      best = std::max(best, timed_rate(f, [&](const F& g) { return run_plain(g, 1000 + k); }));
    }
    rates[{family, s}] = best;
  }
  std::uint64_t stream = 0;
  sized_run r;
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    r = method.run(f, control, 1, ++stream);
    benchmark::DoNotOptimize(r);
  }
  const double wall = seconds_since(start);
  const double rate =
      static_cast<double>(r.evaluations) * static_cast<double>(state.iterations()) / wall;
  if (is_plain) rates[{family, s}] = rate;
  state.counters["evals_per_second"] = benchmark::Counter(
      static_cast<double>(r.evaluations), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["ratio_to_plain_mc"] = rate / rates[{family, s}];
  state.counters["abs_error"] = std::abs(r.value - f.info().exact);
  state.counters["evaluations"] = static_cast<double>(r.evaluations);
}

template <class F>
void register_tensor_vs_plain(genz_family family) {
  const std::string integrand(to_string(family));
  auto add = [&](const char* name, auto method, bool is_plain) {
    benchmark::RegisterBenchmark(("tensor_vs_plain/" + std::string(name) + "/" + integrand).c_str(),
                                 [family, method, is_plain](benchmark::State& state) {
                                   tensor_vs_plain_bench<F>(state, family, method, is_plain);
                                 })
        ->Apply(dimensions_one_thread);
  };
  add("plain_mc", monte_carlo_method<independent_points>{}, true);
  add("trapezoid", tensor_method<trapezoid_rule>{trapezoid_rule{}}, false);
  add("simpson", tensor_method<simpson_rule>{simpson_rule{}}, false);
}

// --- peak RSS -------------------------------------------------------------------------------

// The child: integrate the memory case with `method` at size n, print VmHWM, exit. "baseline"
// builds the integrand and integrates nothing.
int peak_rss_child(std::string_view method, std::string_view n_text) {
  std::uint64_t n = 0;
  try {
    n = std::stoull(std::string(n_text));
  } catch (const std::exception&) {
    std::cerr << "--peak-rss-child: N must be a positive integer, got '" << n_text << "'\n";
    return 2;
  }
  const auto f = make_genz<genz_gaussian>(genz_family::gaussian, rss_dimension);
  double value = f.info().exact;
  bool known = method == "baseline";
  for_each_method([&](std::string_view name, const auto& m) {
    if (name != method) return;
    known = true;
    value = m.run(f, m.control(rss_dimension, n), rss_threads, 1).value;
  });
  if (!known) {
    std::cerr << "--peak-rss-child: unknown method '" << method << "'\n";
    return 2;
  }
  if (!std::isfinite(value)) return 1;
  std::cout << bench::peak_rss_kib() << std::endl;
  return 0;
}

template <class M>
void peak_rss_bench(benchmark::State& state, const std::string& name, const M& method) {
  long baseline = 0, small = 0, large = 0;
  for (auto _ : state) {
    try {
      baseline = bench::child_peak_rss_kib({"--peak-rss-child", "baseline", "1"});
      small = bench::child_peak_rss_kib({"--peak-rss-child", name, std::to_string(rss_small_n)});
      large = bench::child_peak_rss_kib({"--peak-rss-child", name, std::to_string(rss_large_n)});
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      break;
    }
  }
  auto evaluations = [&](std::uint64_t n) {
    return static_cast<double>(method.evaluations(rss_dimension, method.control(rss_dimension, n)));
  };
  state.counters["peak_rss_kib_n1e6"] = static_cast<double>(small);
  state.counters["peak_rss_kib_n1e8"] = static_cast<double>(large);
  state.counters["peak_rss_kib_baseline"] = static_cast<double>(baseline);
  state.counters["evaluations_n1e6"] = evaluations(rss_small_n);
  state.counters["evaluations_n1e8"] = evaluations(rss_large_n);
}

void register_peak_rss() {
  for_each_method([](const char* name, auto method) {
    const std::string method_name(name);
    benchmark::RegisterBenchmark(("peak_rss/" + method_name).c_str(),
                                 [method_name, method](benchmark::State& state) {
                                   peak_rss_bench(state, method_name, method);
                                 })
        ->Iterations(1)
        ->UseRealTime()
        ->Unit(benchmark::kSecond);
  });
}

}  // namespace

int main(int argc, char** argv) {
  // The peak-RSS child runs before Google Benchmark allocates anything, so its VmHWM is the
  // integration's plus the process's own baseline.
  if (argc >= 2 && std::string_view(argv[1]) == "--peak-rss-child") {
    if (argc != 4) {
      std::cerr << "usage: " << argv[0] << " --peak-rss-child METHOD N\n";
      return 2;
    }
    try {
      return peak_rss_child(argv[2], argv[3]);
    } catch (const std::exception& e) {
      std::cerr << "--peak-rss-child: " << e.what() << "\n";
      return 1;
    }
  }
  register_integrand<genz_oscillatory>(genz_family::oscillatory);
  register_integrand<genz_gaussian>(genz_family::gaussian);
  register_integrand<genz_continuous>(genz_family::continuous);
  register_integrand<genz_product_peak>(genz_family::product_peak);
  register_integrand<genz_corner_peak>(genz_family::corner_peak);
  register_integrand<genz_discontinuous>(genz_family::discontinuous);
  register_tensor_vs_plain<genz_oscillatory>(genz_family::oscillatory);
  register_tensor_vs_plain<genz_gaussian>(genz_family::gaussian);
  register_peak_rss();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("seed", std::to_string(seed));
  benchmark::AddCustomContext("evaluations_per_iteration", std::to_string(timed_n));
  benchmark::AddCustomContext(
      "ratio_to_scalar_loop",
      "evaluations per wall second / scalar_loop's for the same integrand and s (one thread)");
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
