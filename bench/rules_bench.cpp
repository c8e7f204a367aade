// Throughput of the deterministic rules: integrand evaluations per second of composite Simpson
// in 1D and of the 3D Simpson tensor product, on a cheap integrand (a quadratic), so that what
// is timed is the rule's own overhead — node generation, product weights, batching, summation —
// and not the integrand; and the Smolyak sparse grid (Clenshaw–Curtis) beside tensor Simpson at
// about equal N on the Genz Gaussian, s = 4 and 8, both through the one kernel
// (rules/weighted_sum.hpp), so that the ratio of their rates is the cost of the sparse grid's
// walk against the tensor grid's.
//
// Use it to see what a rule costs per point (a budget against which an expensive integrand can
// be judged), not for accuracy: that is tested in tests/rules/. Counters: evals_per_second
// (Google Benchmark kIsRate over all iterations), abs_error against the exact integral, and
// evaluations (the points of one iteration). Run only the equal-N comparison with
//   build/release/bench/rules_bench --benchmark_filter=equal_n
// Source of the kernel: lib/include/quadmc/rules/tensor_product.hpp, smolyak_grid.hpp.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "quadmc/functions/genz.hpp"
#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/smolyak_grid.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "quadmc/rules/weighted_sum.hpp"

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

// The Genz Gaussian with the parameters of integrators_bench (aᵢ = genz_normalise(w = 1), uᵢ =
// 0.5): fixed, so that the benchmark does not depend on a draw.
quadmc::genz_gaussian gaussian(std::size_t s) {
  const std::vector<double> w(s, 1.0);
  return {quadmc::genz_normalise(quadmc::genz_family::gaussian, w), std::vector<double>(s, 0.5)};
}

void report(benchmark::State& state, const quadmc::rule_result& r, double exact) {
  state.counters["evals_per_second"] = benchmark::Counter(
      static_cast<double>(r.evaluations) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
  state.counters["abs_error"] = std::abs(r.value - exact);
  state.counters["evaluations"] = static_cast<double>(r.evaluations);
}

// range(0) = dimension s, range(1) = N: the largest Simpson grid (n even, (n + 1)^s points) with
// at most N points, one thread.
void BM_equal_n_simpson(benchmark::State& state) {
  const auto s = static_cast<std::size_t>(state.range(0));
  const auto target = static_cast<std::uint64_t>(state.range(1));
  const quadmc::genz_gaussian f = gaussian(s);
  std::uint64_t n = 2;
  while (quadmc::tensor_grid_size(n + 3, s) <= target) n += 2;
  quadmc::rule_result r;
  for (auto _ : state) {
    r = quadmc::integrate(f, quadmc::simpson_rule{}, n, 1);
    benchmark::DoNotOptimize(r);
  }
  report(state, r, f.info().exact);
}

// The same with the Clenshaw–Curtis Smolyak grid of the largest level L with at most N nodes
// (what the smolyak method picks), built inside the timed loop as the method does per run (its
// count table, and the box coordinates of its block once per call; the 1D rule's and the
// block's tables are the process's, built in the first iteration: nested_rule.hpp,
// smolyak_block.hpp).
void BM_equal_n_smolyak(benchmark::State& state) {
  const auto s = static_cast<std::size_t>(state.range(0));
  const auto target = static_cast<std::uint64_t>(state.range(1));
  const quadmc::genz_gaussian f = gaussian(s);
  const quadmc::nested_rule& rule =
      quadmc::nested_rule_table(quadmc::nested_rule_kind::clenshaw_curtis);
  unsigned level = 0;
  while (level < rule.max_level()) {
    const auto next = quadmc::smolyak_point_count(rule, s, level + 1);
    if (!next || *next > target) break;
    ++level;
  }
  quadmc::rule_result r;
  for (auto _ : state) {
    const quadmc::smolyak_grid grid(rule, s, level);
    r = quadmc::weighted_sum(f, grid, 1);
    benchmark::DoNotOptimize(r);
  }
  report(state, r, f.info().exact);
  state.counters["level"] = level;
}

// s = 4 at N = 2^16 (Simpson 15^4 = 50 625 points, Smolyak L = 9: 46 721); s = 8 at N = 2^20
// (Simpson 5^8 = 390 625, Smolyak L = 8: 609 025): both large enough that the per-call costs
// (the grid's tables, the kernel's buffers) are a small part of the time. s = 2 and 3 each on
// both sides of the block's cap (smolyak_grid.hpp): s = 2 at N = 2^14 (Simpson 127² = 16 129,
// Smolyak L = 11: 15 361, the whole grid one block) and 2^17 (361² = 130 321; L = 13: 69 633,
// birth groups), s = 3 at 2^14 (25³ = 15 625; L = 9: 13 953, one block) and 2^16 (39³ = 59 319;
// L = 10: 32 001, birth groups). One thread, timed by
// CPU time (not UseRealTime): on a machine shared with other jobs the wall clock also counts the
// time the process waited for a core.
void equal_n_sizes(benchmark::internal::Benchmark* b) {
  b->Args({2, 1 << 14})->Args({2, 1 << 17})->Args({3, 1 << 14})->Args({3, 1 << 16});
  b->Args({4, 1 << 16})->Args({8, 1 << 20})->ArgNames({"s", "N"});
  b->Unit(benchmark::kMillisecond);
}
BENCHMARK(BM_equal_n_simpson)->Apply(equal_n_sizes);
BENCHMARK(BM_equal_n_smolyak)->Apply(equal_n_sizes);

}  // namespace

BENCHMARK_MAIN();
