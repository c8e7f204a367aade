// Point generation alone for the QMC point sets: points per second of sobol_points (each
// randomization), rank1_lattice_points and halton_points, s ∈ {1, 2, 4, 8}, N = 2^20 points per
// iteration generated in batches of batch_points into one buffer (as the estimators call
// generate(), core/batching.hpp), the set built inside the timed loop.
//
// Use it for the cost of the kernels behind generate() (sampling/sobol_blocks.hpp,
// sampling/rank1_lattice_blocks.hpp) against their scalar paths: run it once as it is and once
// with QUADMC_SIMD=sse2 (no Sobol'/lattice kernel below avx2, so that run is the scalar walk).
// Not the peers table (bench/peers/qmc_point_peers.cpp times Boost, GSL and scipy) and not the
// per-evaluation cost (integrators_bench's sobol_* and lattice_shift rows). Timer: CPU time of
// this thread (the default), which on a shared machine is steadier than wall time.
#include <benchmark/benchmark.h>

#include "quadmc/core/batching.hpp"
#include "quadmc/sampling/halton_points.hpp"
#include "quadmc/sampling/rank1_lattice_points.hpp"
#include "quadmc/sampling/sobol_points.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace {

using namespace quadmc;

constexpr std::uint64_t points_per_iteration = std::uint64_t{1} << 20;

template <class P>
void generate_points(benchmark::State& state) {
  const auto s = static_cast<std::size_t>(state.range(0));
  std::vector<double> batch(batch_points * s);
  std::uint64_t stream = 0;
  for (auto _ : state) {
    const P points(s, points_per_iteration, 2026, stream++);
    for (std::uint64_t first = 0; first < points_per_iteration; first += batch_points) {
      points.generate(first, batch);
      benchmark::DoNotOptimize(batch.data());
      benchmark::ClobberMemory();
    }
  }
  state.counters["points_per_second"] = benchmark::Counter(
      static_cast<double>(points_per_iteration), benchmark::Counter::kIsIterationInvariantRate);
}

void dimensions(benchmark::internal::Benchmark* b) {
  for (const int s : {1, 2, 4, 8}) b->Arg(s);
  b->ArgName("s");
}

BENCHMARK(generate_points<sobol_points<unrandomized_digits>>)
    ->Name("sobol_none")
    ->Apply(dimensions);
BENCHMARK(generate_points<sobol_points<linear_matrix_scramble>>)
    ->Name("sobol_lms_shift")
    ->Apply(dimensions);
BENCHMARK(generate_points<sobol_points<fast_owen_scramble>>)
    ->Name("sobol_fast_owen")
    ->Apply(dimensions);
BENCHMARK(generate_points<sobol_points<owen_scramble>>)->Name("sobol_owen")->Apply(dimensions);
BENCHMARK(generate_points<rank1_lattice_points<no_periodization>>)
    ->Name("lattice_shift")
    ->Apply(dimensions);
BENCHMARK(generate_points<halton_points<random_digit_permutation>>)
    ->Name("halton_permutation")
    ->Apply(dimensions);

}  // namespace

BENCHMARK_MAIN();
