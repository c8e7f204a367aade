// Instructions per evaluation of the equal-N comparison of bench/rules_bench.cpp (tensor Simpson
// and the Clenshaw–Curtis Smolyak grid on the Genz Gaussian, one thread), for callgrind: each
// sum runs in a function of its own (measured_simpson, measured_smolyak; the grid built inside,
// as the smolyak method builds it per run) after the process's tables are built, so
// --toggle-collect counts exactly the calls. Also prints the best wall time per evaluation.
// Not built by CMake; from the repository root, after `cmake --build build/release`, compile
// it with `g++ -O2 -DNDEBUG -std=c++20 -DFMT_SHARED -Ilib/include` and link
// `-Lbuild/release/lib -lquadmc_rules -lquadmc_functions -lquadmc_core -lfmt -lquadrule` (the
// flags rules_bench is built with), then run
// `valgrind --tool=callgrind --toggle-collect='measured_smolyak*' ./a.out smolyak 4 65536 3`;
// then Ir (callgrind_annotate's PROGRAM TOTALS) / (reps × evals) is the figure; arguments:
// simpson|smolyak, s, N (the largest grid with at most N points), reps.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>
#include "quadmc/functions/genz.hpp"
#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/smolyak_grid.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "quadmc/rules/weighted_sum.hpp"
using namespace quadmc;
static genz_gaussian gaussian(std::size_t s) {
  const std::vector<double> w(s, 1.0);
  return {genz_normalise(genz_family::gaussian, w), std::vector<double>(s, 0.5)};
}
__attribute__((noinline)) double measured_simpson(const genz_gaussian& f, std::uint64_t n,
                                                  std::uint64_t* ev) {
  auto r = integrate(f, simpson_rule{}, n, 1);
  *ev = r.evaluations;
  return r.value;
}
__attribute__((noinline)) double measured_smolyak(const genz_gaussian& f, const nested_rule& rule,
                                                  std::size_t s, unsigned level,
                                                  std::uint64_t* ev) {
  const smolyak_grid grid(rule, s, level);
  auto r = weighted_sum(f, grid, 1);
  *ev = r.evaluations;
  return r.value;
}
int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: %s simpson|smolyak s N reps\n", argv[0]);
    return 2;
  }
  const bool smol = argv[1][1] == 'm';
  const std::size_t s = std::atoi(argv[2]);
  const std::uint64_t target = std::strtoull(argv[3], nullptr, 10);
  const int reps = std::atoi(argv[4]);
  const genz_gaussian f = gaussian(s);
  std::uint64_t ev = 0;
  double v = 0;
  double best = 1e30;
  if (!smol) {
    std::uint64_t n = 2;
    while (tensor_grid_size(n + 3, s) <= target) n += 2;
    for (int i = 0; i < reps; ++i) {
      auto t0 = std::chrono::steady_clock::now();
      v += measured_simpson(f, n, &ev);
      best = std::min(best,
                      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
  } else {
    const nested_rule& rule = nested_rule_table(nested_rule_kind::clenshaw_curtis);
    unsigned level = 0;
    while (level < rule.max_level()) {
      const auto next = smolyak_point_count(rule, s, level + 1);
      if (!next || *next > target) break;
      ++level;
    }
    {
      const smolyak_grid warm(rule, s, level);
      (void)warm;
    }  // the process's tables, once
    for (int i = 0; i < reps; ++i) {
      auto t0 = std::chrono::steady_clock::now();
      v += measured_smolyak(f, rule, s, level, &ev);
      best = std::min(best,
                      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
  }
  std::printf(
      "%s s=%zu evals=%llu reps=%d value=%.17g err=%.3g best_ns_per_eval=%.3f Mevals_per_s=%.1f\n",
      argv[1], s, (unsigned long long)ev, reps, v / reps, v / reps - f.info().exact,
      best * 1e9 / ev, ev / best / 1e6);
}
