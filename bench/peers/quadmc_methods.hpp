// quadmc's own methods as peers: plain Monte Carlo over independent, jittered and Latin hypercube
// points (estimators/monte_carlo.hpp) under either generator (core/rng.hpp), over scrambled
// Sobol', Halton and lattice points, and the tensor-product Simpson and trapezoid rules
// (rules/tensor_product.hpp), with the sizes each one accepts.
//
// Use it from the peers driver only. Sizes: independent and Latin hypercube points take any N;
// jittered points need N = k^s (k = round(N^{1/s}), so the nearest such size is measured);
// tensor rules take panels per axis n with N = (n+1)^s (n even for Simpson). The measured
// evaluations, not the requested N, go into every rate.
#pragma once

#include "peer_method.hpp"

#include "quadmc/core/rng.hpp"
#include "quadmc/estimators/monte_carlo.hpp"
#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "quadmc/rules/trapezoid_rule.hpp"
#include "quadmc/sampling/halton_points.hpp"
#include "quadmc/sampling/independent_points.hpp"
#include "quadmc/sampling/jittered_points.hpp"
#include "quadmc/sampling/latin_hypercube_points.hpp"
#include "quadmc/sampling/rank1_lattice_points.hpp"
#include "quadmc/sampling/sobol_points.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace quadmc::peers {

// k^s with k = max(1, round(N^{1/s})): the jittered size nearest to N on a log scale.
inline std::uint64_t jittered_size(std::uint64_t n, std::size_t s) {
  const auto k = std::max<std::uint64_t>(
      1, static_cast<std::uint64_t>(std::llround(std::pow(static_cast<double>(n), 1.0 / s))));
  return tensor_grid_size(k, s);
}

// The smallest k^s ≥ N: the throughput size of jittered points (the two-thread target is
// stated at N ≥ 2^22; 45^4 < 2^22 ≤ 46^4).
inline std::uint64_t jittered_size_at_least(std::uint64_t n, std::size_t s) {
  auto k = std::max<std::uint64_t>(
      1, static_cast<std::uint64_t>(std::floor(std::pow(static_cast<double>(n), 1.0 / s))));
  while (k > 1 && tensor_grid_size(k - 1, s) >= n) --k;  // pow may round up
  while (tensor_grid_size(k, s) < n) ++k;
  return tensor_grid_size(k, s);
}

// Panels per axis n ≥ minimum (even when `even`) whose grid (n+1)^s is nearest to N on a log
// scale; with at_least, the smallest such grid with (n+1)^s ≥ N.
inline std::uint64_t tensor_panels(std::uint64_t n, std::size_t s, bool even, bool at_least) {
  const std::uint64_t step = even ? 2 : 1;
  std::uint64_t best = step;
  double best_distance = INFINITY;
  for (std::uint64_t panels = step;; panels += step) {
    const double points = std::pow(static_cast<double>(panels + 1), static_cast<double>(s));
    const double distance = std::abs(std::log(points / static_cast<double>(n)));
    if (at_least) {
      if (points >= static_cast<double>(n)) return panels;
    } else if (distance < best_distance) {
      best = panels;
      best_distance = distance;
    } else if (points > static_cast<double>(n)) {
      return best;
    }
  }
}

inline std::vector<std::uint64_t> distinct_sorted(std::vector<std::uint64_t> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

// One run of plain Monte Carlo over point set P with N points: P built from (s, N, seed,
// stream_id({N}), extra...), the call both the point-set and the quasi-Monte Carlo methods time.
// `extra`: the constructor's further arguments, e.g. the generator of a random point set.
template <class P, class F, class... Extra>
auto monte_carlo_run(const F& f, unsigned threads, Extra... extra) {
  return [&f, threads, extra...](std::uint64_t n, std::uint64_t seed) {
    const P points(f.dimension(), n, seed, stream_id({n}), extra...);
    const estimate e = monte_carlo(f, points, threads);
    return run_result{e.value, e.evaluations};
  };
}

// Plain Monte Carlo with point set P (any of the three: same constructor shape). The point set
// is built inside the run (for Latin hypercube points that includes its s permutations), with
// stream id stream_id({N}) under the run's seed, its uniforms drawn by `rng` (Philox, the
// library's default, or ARS: docs/theory.md#counter-based-generators).
template <class P, class F>
peer_method quadmc_monte_carlo(std::string name, const F& f, unsigned threads,
                               const std::vector<std::uint64_t>& ladder, std::uint64_t throughput_n,
                               rng_kind rng = rng_kind::philox4x32_10) {
  const std::size_t s = f.dimension();
  auto size = [s](std::uint64_t n) {
    if constexpr (std::is_same_v<P, jittered_points>) return jittered_size(n, s);
    return n;
  };
  std::vector<std::uint64_t> controls;
  for (std::uint64_t n : ladder) controls.push_back(size(n));
  peer_method m;
  m.name = std::move(name);
  m.family = "quadmc";
  m.threads = threads;
  m.random = true;
  m.kind = control_kind::evaluations;
  m.ladder = distinct_sorted(controls);
  m.throughput_control = throughput_n;
  if constexpr (std::is_same_v<P, jittered_points>) {
    m.throughput_control = jittered_size_at_least(throughput_n, s);
  }
  m.run = monte_carlo_run<P>(f, threads, rng);
  return m;
}

// Plain Monte Carlo over one randomization of a quasi-Monte Carlo set P (sobol_points,
// halton_points, rank1_lattice_points: one constructor shape), built inside the run: the call a
// `sobol`, `halton` or `lattice` method makes for one replicate (the suite's methods repeat it
// for error bars; the rate per evaluation is the same). Throughput only: no ladder (the work-
// precision ladders of these sets are the scenes' business, results/default), so they cost the
// study little time.
template <class P, class F>
peer_method quadmc_quasi_monte_carlo(std::string name, const F& f, unsigned threads,
                                     std::uint64_t throughput_n) {
  peer_method m;
  m.name = std::move(name);
  m.family = "quadmc";
  m.threads = threads;
  m.random = true;
  m.kind = control_kind::evaluations;
  m.throughput_control = throughput_n;
  m.run = monte_carlo_run<P>(f, threads);
  return m;
}

// Tensor-product rule R with n panels per axis. The throughput size is the smallest grid with at
// least throughput_n points, so that the two-thread target (N ≥ 2^22) applies to it.
template <class R, class F>
peer_method quadmc_tensor_rule(std::string name, const F& f, unsigned threads,
                               const std::vector<std::uint64_t>& ladder,
                               std::uint64_t throughput_n) {
  const std::size_t s = f.dimension();
  constexpr bool even = std::is_same_v<R, simpson_rule>;
  std::vector<std::uint64_t> controls;
  for (std::uint64_t n : ladder) controls.push_back(tensor_panels(n, s, even, false));
  peer_method m;
  m.name = std::move(name);
  m.family = "quadmc";
  m.threads = threads;
  m.random = false;
  m.kind = control_kind::panels;
  m.ladder = distinct_sorted(controls);
  m.throughput_control = tensor_panels(throughput_n, s, even, true);
  m.run = [&f, threads](std::uint64_t panels, std::uint64_t) {
    const rule_result r = integrate(f, R{}, panels, threads);
    return run_result{r.value, r.evaluations};
  };
  return m;
}

}  // namespace quadmc::peers
