// Throughput of the numeric core: uniform doubles per second from random_stream::fill_uniform
// and terms per second for naive, pairwise and Neumaier summation, and the fixed cost of one
// parallel_reduce call (start-up and join of its threads, no real work).
//
// Use it to see what the hot-path building blocks cost per sample (a budget for point sets and
// estimators), not for accuracy: the accuracy of these is tested in tests/core/. Counters are
// items per second (Google Benchmark's kIsIterationInvariantRate), one item = one uniform or one
// summed term. The generators: Philox4x32-10 and ARS-4x32-7 ([Salmon et al. 2011 (Random123)];
// docs/theory.md#counter-based-generators); `range(1)` picks one (0 Philox, 1 ARS).
#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "quadmc/core/parallel_reduce.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/core/summation.hpp"

namespace {

// fill_uniform over a batch of `range(0)` values; batch 256 is what the estimators use.
void BM_fill_uniform(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto generator = static_cast<quadmc::rng_kind>(state.range(1));
  state.SetLabel(std::string(quadmc::to_string(generator)));
  const quadmc::random_stream rng(1, quadmc::stream_id({1}), generator);
  std::vector<double> out(n);
  std::uint64_t first = 0;
  for (auto _ : state) {
    rng.fill_uniform(first, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
    first += n;
  }
  state.counters["uniforms_per_second"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_fill_uniform)->ArgsProduct({{256, 4096, 1 << 20}, {0, 1}});

// uniform(i) one at a time: what a caller pays for not batching.
void BM_uniform_one_at_a_time(benchmark::State& state) {
  const auto generator = static_cast<quadmc::rng_kind>(state.range(0));
  state.SetLabel(std::string(quadmc::to_string(generator)));
  const quadmc::random_stream rng(1, quadmc::stream_id({2}), generator);
  std::uint64_t i = 0;
  for (auto _ : state) {
    double s = 0;
    for (int k = 0; k < 256; ++k) s += rng.uniform(i++);
    benchmark::DoNotOptimize(s);
  }
  state.counters["uniforms_per_second"] =
      benchmark::Counter(256, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_uniform_one_at_a_time)->Arg(0)->Arg(1);

std::vector<double> terms(std::size_t n) {
  std::vector<double> x(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double d = static_cast<double>(k + 1);
    x[k] = 1.0 / (d * d);
  }
  return x;
}

void BM_naive_sum(benchmark::State& state) {
  const auto x = terms(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(quadmc::naive_sum(x));
  state.counters["terms_per_second"] = benchmark::Counter(
      static_cast<double>(x.size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_naive_sum)->Arg(4096)->Arg(1 << 22);

void BM_pairwise_sum(benchmark::State& state) {
  const auto x = terms(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(quadmc::pairwise_sum(x));
  state.counters["terms_per_second"] = benchmark::Counter(
      static_cast<double>(x.size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_pairwise_sum)->Arg(4096)->Arg(1 << 22);

void BM_neumaier_sum(benchmark::State& state) {
  const auto x = terms(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    quadmc::neumaier_sum s;
    for (const double v : x) s.add(v);
    benchmark::DoNotOptimize(s.value());
  }
  state.counters["terms_per_second"] = benchmark::Counter(
      static_cast<double>(x.size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_neumaier_sum)->Arg(4096)->Arg(1 << 22);

// One parallel_reduce over `range(0)` chunks of trivial work on `range(1)` threads: what a call
// costs before any evaluation (thread start-up or wake-up, hand-out, join, ordered fold). Wall
// time, since the workers run outside the calling thread's CPU time. With 2 chunks and 2 threads
// both threads really run (one chunk each), so the figure is the per-call overhead a small cell
// pays for asking for two threads.
void BM_parallel_reduce_overhead(benchmark::State& state) {
  const auto chunks = static_cast<std::size_t>(state.range(0));
  const auto threads = static_cast<unsigned>(state.range(1));
  for (auto _ : state) {
    const double r = quadmc::parallel_reduce(
        chunks, threads, 0.0, [](std::size_t c) { return static_cast<double>(c); },
        [](double& acc, double x) { acc += x; });
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_parallel_reduce_overhead)
    ->ArgNames({"chunks", "threads"})
    ->Args({2, 1})
    ->Args({2, 2})
    ->Args({64, 2})
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
