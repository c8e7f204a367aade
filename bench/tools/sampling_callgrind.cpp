// Instructions per evaluation of plain Monte Carlo, jittered and Latin hypercube points on the
// Genz oscillatory and Gaussian integrands (one thread), for callgrind: the whole estimate (point
// set built, placed, integrand, statistics) runs in measured_estimate(), so --toggle-collect
// counts exactly the calls; `generate` mode runs only the point set's generate() over all N
// points in batches of 256 (measured_generate). Also prints the best wall time per evaluation.
// Not built by CMake; from the repository root, after `cmake --build build/release`, compile it
// with
//   g++ -O2 -DNDEBUG -std=c++20 -DFMT_SHARED -Ilib/include bench/tools/sampling_callgrind.cpp \
//     -Lbuild/release/lib -lquadmc_sampling -lquadmc_functions -lquadmc_core -lfmt -lmvec \
//     -o /tmp/sampling_callgrind
// then run
//   valgrind --tool=callgrind --toggle-collect='measured_*' /tmp/sampling_callgrind \
//     jittered oscillatory 4 1048576 1 estimate
// and Ir (callgrind_annotate's PROGRAM TOTALS) / (reps × evals) is the figure. Arguments:
// plain|jittered|lhs, oscillatory|gaussian, s, N (jittered: k^s with k = round(N^(1/s)), the
// size integrators_bench uses), reps, estimate|generate.
#include "quadmc/core/batching.hpp"
#include "quadmc/estimators/monte_carlo.hpp"
#include "quadmc/functions/genz.hpp"
#include "quadmc/sampling/independent_points.hpp"
#include "quadmc/sampling/jittered_points.hpp"
#include "quadmc/sampling/latin_hypercube_points.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

using namespace quadmc;

template <class F>
static F make(std::size_t s) {
  const std::vector<double> w(s, 1.0);
  const genz_family family =
      std::is_same_v<F, genz_gaussian> ? genz_family::gaussian : genz_family::oscillatory;
  return F(genz_normalise(family, w), std::vector<double>(s, 0.5));
}

template <class P, class F>
__attribute__((noinline)) double measured_estimate(const F& f, std::uint64_t n,
                                                   std::uint64_t stream) {
  const P points(f.dimension(), n, 42, stream);
  return monte_carlo(f, points, 1).value;
}

template <class P>
__attribute__((noinline)) double measured_generate(std::size_t s, std::uint64_t n,
                                                   std::uint64_t stream) {
  const P points(s, n, 42, stream);
  std::vector<double> u(batch_points * s);
  double sum = 0.0;
  for (std::uint64_t first = 0; first < n; first += batch_points) {
    const std::size_t count =
        static_cast<std::size_t>(std::min<std::uint64_t>(batch_points, n - first));
    points.generate(first, std::span<double>(u.data(), count * s));
    sum += u[0];
  }
  return sum;
}

template <class P, class F>
static void run(const char* name, std::size_t s, std::uint64_t n, int reps, bool generate_only) {
  const F f = make<F>(s);
  double v = 0.0;
  double best = 1e30;
  for (int i = 0; i < reps; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    v += generate_only ? measured_generate<P>(s, n, i) : measured_estimate<P>(f, n, i);
    best = std::min(best,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::printf("%s s=%zu evals=%llu reps=%d mean=%.17g best_ns_per_eval=%.3f Mevals_per_s=%.1f\n",
              name, s, static_cast<unsigned long long>(n), reps, v / reps, best * 1e9 / n,
              n / best / 1e6);
}

template <class F>
static void dispatch(const char* method, std::size_t s, std::uint64_t n, int reps, bool gen) {
  if (std::strcmp(method, "plain") == 0) return run<independent_points, F>(method, s, n, reps, gen);
  if (std::strcmp(method, "lhs") == 0)
    return run<latin_hypercube_points, F>(method, s, n, reps, gen);
  const double k = std::round(std::pow(static_cast<double>(n), 1.0 / static_cast<double>(s)));
  std::uint64_t kn = 1;
  for (std::size_t j = 0; j < s; ++j) kn *= static_cast<std::uint64_t>(k);
  run<jittered_points, F>(method, s, kn, reps, gen);
}

int main(int argc, char** argv) {
  if (argc != 7) {
    std::fprintf(stderr,
                 "usage: %s plain|jittered|lhs oscillatory|gaussian s N reps estimate|generate\n",
                 argv[0]);
    return 2;
  }
  const std::size_t s = std::strtoul(argv[3], nullptr, 10);
  const std::uint64_t n = std::strtoull(argv[4], nullptr, 10);
  const int reps = std::atoi(argv[5]);
  const bool gen = std::strcmp(argv[6], "generate") == 0;
  if (argv[2][0] == 'g') {
    dispatch<genz_gaussian>(argv[1], s, n, reps, gen);
  } else {
    dispatch<genz_oscillatory>(argv[1], s, n, reps, gen);
  }
}
