// Time per evaluation of every integrator on the Genz integrands, s ∈ {1, 2, 4, 8}.
//
// Use it for cost (evaluations per second, counter `evals_per_second`, a kIsRate counter) and to
// see the error each run reached (`abs_error`, against the closed-form reference). It is not a
// convergence study: error against N with fitted slopes is `quadmc run` (convergence tables),
// because Google Benchmark's Complexity() fits time, not error (STYLE.md).
// Kernels take the concrete integrand type (static dispatch, inlined) as the runner's templates
// do below their one switch; N = 2^20 evaluations per iteration, one thread unless stated.
//   build/release/bench/integrators_bench --benchmark_format=json
#include <benchmark/benchmark.h>

#include "quadmc/estimators/monte_carlo.hpp"
#include "quadmc/functions/genz.hpp"
#include "quadmc/rules/midpoint_rule.hpp"
#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "quadmc/rules/trapezoid_rule.hpp"
#include "quadmc/sampling/independent_points.hpp"
#include "quadmc/sampling/jittered_points.hpp"
#include "quadmc/sampling/latin_hypercube_points.hpp"

#include <cmath>
#include <cstdint>

namespace {

constexpr std::uint64_t seed = 42;

// Fixed, documented parameters (Genz normalisation of uniform weights; u = 0.5): the benchmark
// must not depend on a random draw.
template <class F>
F make_genz(quadmc::genz_family family, std::size_t s) {
  const std::vector<double> w(s, 1.0);
  return F(quadmc::genz_normalise(family, w), std::vector<double>(s, 0.5));
}

void report(benchmark::State& state, std::uint64_t evaluations, double value, double exact) {
  state.counters["evals_per_second"] = benchmark::Counter(
      static_cast<double>(evaluations), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["abs_error"] = std::abs(value - exact);
  state.counters["evaluations"] = static_cast<double>(evaluations);
}

template <class F, class Points>
void monte_carlo_bench(benchmark::State& state, quadmc::genz_family family) {
  const auto s = static_cast<std::size_t>(state.range(0));
  const auto threads = static_cast<unsigned>(state.range(1));
  const F f = make_genz<F>(family, s);
  // Jittered needs N = k^s: take k = ⌊(2^20)^(1/s)⌋ (exact integer root by search).
  std::uint64_t n = std::uint64_t{1} << 20;
  if constexpr (std::is_same_v<Points, quadmc::jittered_points>) {
    std::uint64_t k = 1;
    auto pow_s = [s](std::uint64_t b) {
      std::uint64_t p = 1;
      for (std::size_t j = 0; j < s; ++j) p *= b;
      return p;
    };
    while (pow_s(k + 1) <= n) ++k;
    n = pow_s(k);
  }
  std::uint64_t stream = 0;
  double value = 0.0;
  for (auto _ : state) {
    const Points points(s, n, seed, ++stream);
    value = quadmc::monte_carlo(f, points, threads).value;
    benchmark::DoNotOptimize(value);
  }
  report(state, n, value, f.info().exact);
}

template <class F, class Rule>
void tensor_bench(benchmark::State& state, quadmc::genz_family family) {
  const auto s = static_cast<std::size_t>(state.range(0));
  const auto threads = static_cast<unsigned>(state.range(1));
  const F f = make_genz<F>(family, s);
  // About 2^20 points: panels n with (n + 1)^s ≤ 2^20, even for Simpson.
  std::uint64_t panels = 2;
  auto points = [s](std::uint64_t p) { return std::pow(static_cast<double>(p), double(s)); };
  while (points(panels + 3) <= double(1 << 20)) panels += 2;
  quadmc::rule_result r;
  for (auto _ : state) {
    r = quadmc::integrate(f, Rule{}, panels, threads);
    benchmark::DoNotOptimize(r.value);
  }
  report(state, r.evaluations, r.value, f.info().exact);
}

void dimensions_and_threads(benchmark::internal::Benchmark* b) {
  for (int s : {1, 2, 4, 8}) b->Args({s, 1});
  for (int s : {1, 8}) b->Args({s, 2});
  b->ArgNames({"s", "threads"})->Unit(benchmark::kMillisecond)->UseRealTime();
}

}  // namespace

int main(int argc, char** argv) {
  using quadmc::genz_family;
  using namespace quadmc;
  // Registered by hand so each benchmark is named method/integrand (s and threads as arguments).
  auto add = [](const char* name, auto fn, genz_family family) {
    benchmark::RegisterBenchmark(name, [=](benchmark::State& state) {
      fn(state, family);
    })->Apply(dimensions_and_threads);
  };
  add("plain_mc/genz_oscillatory", monte_carlo_bench<genz_oscillatory, independent_points>,
      genz_family::oscillatory);
  add("plain_mc/genz_gaussian", monte_carlo_bench<genz_gaussian, independent_points>,
      genz_family::gaussian);
  add("jittered/genz_gaussian", monte_carlo_bench<genz_gaussian, jittered_points>,
      genz_family::gaussian);
  add("latin_hypercube/genz_gaussian", monte_carlo_bench<genz_gaussian, latin_hypercube_points>,
      genz_family::gaussian);
  add("trapezoid/genz_gaussian", tensor_bench<genz_gaussian, trapezoid_rule>,
      genz_family::gaussian);
  add("simpson/genz_gaussian", tensor_bench<genz_gaussian, simpson_rule>, genz_family::gaussian);
  add("simpson/genz_oscillatory", tensor_bench<genz_oscillatory, simpson_rule>,
      genz_family::oscillatory);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("seed", std::to_string(seed));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
