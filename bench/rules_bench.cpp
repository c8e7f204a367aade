// Throughput of the deterministic rules: integrand evaluations per second of composite Simpson
// in 1D and of the 3D Simpson tensor product, on a cheap integrand (a quadratic), so that what
// is timed is the rule's own overhead — node generation, product weights, batching, summation —
// and not the integrand.
//
// Use it to see what a rule costs per point (a budget against which an expensive integrand can
// be judged), not for accuracy: that is tested in tests/rules/. Counters: evals_per_second
// (Google Benchmark kIsRate over all iterations) and abs_error against the exact integral.
// Source of the kernel: lib/include/quadmc/rules/tensor_product.hpp.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/tensor_product.hpp"

namespace {

// f(x) = Σ_j x_j² + 1 on [0, 1]^s: ∫ = s/3 + 1. A few flops per point.
struct sum_of_squares {
  std::size_t s;
  std::size_t dimension() const { return s; }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    for (std::size_t i = 0; i < y.size(); ++i) {
      double v = 1.0;
      for (std::size_t j = 0; j < s; ++j) v += x[i * s + j] * x[i * s + j];
      y[i] = v;
    }
  }
  quadmc::integrand_info info() const {
    quadmc::integrand_info i;
    i.name = "sum_of_squares";
    i.domain = quadmc::box::unit(s);
    i.exact = static_cast<double>(s) / 3.0 + 1.0;
    return i;
  }
};

// range(0) = dimension s, range(1) = panels per axis n, range(2) = threads.
void BM_simpson_tensor(benchmark::State& state) {
  const sum_of_squares f{static_cast<std::size_t>(state.range(0))};
  const auto n = static_cast<std::uint64_t>(state.range(1));
  const auto threads = static_cast<unsigned>(state.range(2));
  quadmc::rule_result r;
  for (auto _ : state) {
    r = quadmc::integrate(f, quadmc::simpson_rule{}, n, threads);
    benchmark::DoNotOptimize(r.value);
  }
  state.counters["evals_per_second"] = benchmark::Counter(
      static_cast<double>(r.evaluations) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
  state.counters["abs_error"] = std::abs(r.value - f.info().exact);
}
BENCHMARK(BM_simpson_tensor)
    ->Args({1, 1 << 20, 1})
    ->Args({1, 1 << 20, 2})
    ->Args({3, 100, 1})
    ->Args({3, 100, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
