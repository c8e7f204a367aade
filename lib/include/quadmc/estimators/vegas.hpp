// VEGAS+: adaptive importance sampling on a separable grid plus adaptive stratified sampling
// ([Lepage 2021]; the grid of [Lepage 1978]), iterations combined by inverse-variance weighting,
// with the χ² of that combination and its Q.
//
// Use it for Monte Carlo on integrands that are peaked (along axes, or along a few directions the
// stratification can resolve) or discontinuous, in any s, when σ̂ should shrink much faster than
// plain MC's at equal N. Not for integrands whose peaks lie on a diagonal in high s (a separable
// grid cannot follow them; the estimate stays unbiased, the variance stays large), and not where
// a smooth f in s ≤ 8 makes a deterministic rule cheaper (genz_malik).
//
// One iteration with n evaluations, in y ∈ [0,1)^s (Lepage 2021, §2):
//  - the map: on each axis ninc increments of the x-grid, y·ninc = i + δ ↦ x = x_i + δ·Δx_i, with
//    Jacobian J = Π ninc·Δx_i (times the box volume);
//  - the strata: ns = ⌊(n/8)^(1/s)⌋ per axis (at most 2^20 hypercubes in all), so that a quarter of
//    the points keeps two in every hypercube; hypercube h gets n_h = max(2, ⌊n/(4·ns^s)⌋) +
//    ⌊(n − that·ns^s)·d_h/Σd⌋ points, d_h = σ̂_h^β with σ̂_h² the previous iteration's variance of
//    J·f in h (uniform at first and whenever ns changes), β = 0.75 the damping of the paper;
//  - the estimate: I = Σ_h V_h·mean_h(J f), σ̂² = Σ_h V_h²·var_h(J f)/n_h (V_h = ns^−s);
//  - the grid's training data: on each axis, the mean of (J f)² over the points in each
//    increment; smoothed over neighbours (7,1)/8, (1,6,1)/8, normalised to r_i, damped to
//    ((1 − r_i)/ln(1/r_i))^α, α = 0.5, and the increments redrawn to hold equal shares of it.
// Iterations (Lepage 1978, §3): the first `training_iterations` only adapt; the rest are combined,
// Ī = Σ(I_k/σ̂_k²)/Σ(1/σ̂_k²) and σ̂² = 1/Σ(1/σ̂_k²) (an iteration with σ̂_k = 0, every point of
// each hypercube alike, weighs as the mean of the others: vegas_combination), and
// χ² = Σ(I_k − Ī)²/σ̂_k² on K − 1 degrees of freedom, Q = P(χ²_{K−1} ≥ χ²) (the regularised upper
// incomplete gamma function, Boost.Math). χ²/dof far above 1 (Q tiny) says the iterations disagree
// more than their σ̂ allow: the grid was still moving or σ̂ is too small, so the error estimate is
// not to be trusted.
//
// Budget control: N = max_evaluations split into `iterations` equal iterations. Tolerance control:
// training iterations of evaluations_per_iteration points each, then iterations of growing size
// (the size that would reach the tolerance from the last σ̂, at least the previous size and at most
// 4× it) until at least two are combined, one of them with spread, and σ̂ ≤ tolerance, within the
// budget.
//
// Reproducibility: sample g of a run (counted over all its iterations) draws its s uniforms from
// Philox counters g·s … g·s + s − 1 of the run's stream; the points are cut into chunks of fixed
// size (2^15 or n/64, whichever is larger, so at most 65 chunks hold their training arrays), each
// chunk's statistics (per hypercube, merged by Chan, Golub & LeVeque; per increment, added) are
// folded in chunk order, and every adaptation is serial: a seed gives bitwise the same result on
// any thread count. No allocation per point: buffers per chunk and per iteration.
#pragma once

#include "quadmc/core/batching.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/core/integer_powers.hpp"
#include "quadmc/core/parallel_reduce.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/core/welford.hpp"
#include "quadmc/functions/integrand.hpp"

#include <fmt/format.h>
#include <boost/math/special_functions/gamma.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace quadmc {

struct vegas_options {
  std::uint64_t max_evaluations = 0;  // the budget; never exceeded
  double absolute_tolerance = 0.0;    // > 0: tolerance control (see above); 0: budget control
  unsigned iterations = 10;           // budget control: the budget in this many equal iterations
  unsigned training_iterations = 3;   // iterations that only adapt (fewer than `iterations`)
  std::uint64_t evaluations_per_iteration = 2000;  // tolerance control: the first iterations' size
  double alpha = 0.5;                 // grid damping; 0 freezes the grid (stratification only)
  double beta = 0.75;                 // stratification damping; 0 keeps n_h uniform
  std::size_t max_increments = 1000;  // grid increments per axis (n/10 if fewer)
  unsigned threads = 1;               // 0 = all cores; the result does not depend on it
};

struct vegas_result {
  double value = 0.0;
  double std_error = 0.0;  // σ̂ of the combined estimate
  std::uint64_t evaluations = 0;
  unsigned iterations = 0;           // all, training included
  unsigned combined_iterations = 0;  // K, the ones in the weighted average
  double chi2_per_dof = std::numeric_limits<double>::quiet_NaN();  // NaN for K < 2
  double q = std::numeric_limits<double>::quiet_NaN();             // NaN for K < 2
  bool converged = false;  // tolerance control: σ̂ ≤ tolerance was reached
};

// The fewest evaluations an iteration may have (two points in one hypercube, and enough for the
// grid to have a few increments).
inline constexpr std::uint64_t vegas_min_iteration_evaluations = 16;

namespace detail {

// The separable map of [0,1)^s onto itself: per axis, ninc increments with edges x_0 = 0 < … <
// x_ninc = 1.
class vegas_grid {
 public:
  vegas_grid(std::size_t s, std::size_t increments) : s_(s) { reset(increments); }

  std::size_t increments() const noexcept { return n_; }
  const double* edges(std::size_t axis) const noexcept { return edges_.data() + axis * (n_ + 1); }

  // y ∈ [0,1) on `axis` ↦ x, multiplying jacobian by ninc·Δx_i; returns the increment i.
  std::size_t map(std::size_t axis, double y, double& x, double& jacobian) const noexcept {
    const double* e = edges(axis);
    const double t = y * static_cast<double>(n_);
    std::size_t i = static_cast<std::size_t>(t);
    if (i >= n_) i = n_ - 1;
    const double width = e[i + 1] - e[i];
    x = e[i] + (t - static_cast<double>(i)) * width;
    jacobian *= static_cast<double>(n_) * width;
    return i;
  }

  // Redraws every axis's increments so that each holds an equal share of weight (one value per
  // old increment, ≥ 0, constant within it), with `increments` new ones; axes whose weights sum
  // to 0 keep their edges (then only resampled onto the new count).
  void redraw(std::span<const double> weight, std::size_t increments) {
    std::vector<double> fresh(s_ * (increments + 1));
    const std::vector<double> uniform(n_, 1.0);
    for (std::size_t d = 0; d < s_; ++d) {
      std::span<const double> w = weight.subspan(d * n_, n_);
      double total = 0.0;
      for (double v : w) total += v;
      if (!(total > 0.0) || !std::isfinite(total)) {
        w = uniform;
        total = static_cast<double>(n_);
      }
      const double* e = edges(d);
      double* out = fresh.data() + d * (increments + 1);
      out[0] = 0.0;
      out[increments] = 1.0;
      const double share = total / static_cast<double>(increments);
      double below = 0.0;  // Σ w over old increments before j
      std::size_t j = 0;
      for (std::size_t k = 1; k < increments; ++k) {
        const double target = share * static_cast<double>(k);
        while (j + 1 < n_ && below + w[j] < target) below += w[j++];
        const double fraction = w[j] > 0.0 ? std::clamp((target - below) / w[j], 0.0, 1.0) : 0.0;
        out[k] = std::max(out[k - 1], e[j] + fraction * (e[j + 1] - e[j]));
      }
    }
    edges_ = std::move(fresh);
    n_ = increments;
  }

 private:
  void reset(std::size_t increments) {
    n_ = increments;
    edges_.assign(s_ * (n_ + 1), 0.0);
    for (std::size_t d = 0; d < s_; ++d) {
      for (std::size_t i = 0; i <= n_; ++i) {
        edges_[d * (n_ + 1) + i] = static_cast<double>(i) / static_cast<double>(n_);
      }
    }
  }

  std::size_t s_;
  std::size_t n_ = 1;
  std::vector<double> edges_;
};

// One hypercube's statistics from one chunk.
struct vegas_cube_part {
  std::uint64_t cube = 0;
  welford stats;
};

// What one chunk of an iteration returns; partial results are folded in chunk order.
struct vegas_chunk {
  std::vector<vegas_cube_part> cubes;  // in increasing cube order
  std::vector<double> square_sum;      // Σ (J f)² per (axis, increment)
  std::vector<double> count;           // points per (axis, increment)
};

struct vegas_iteration {
  double value = 0.0;
  double variance = 0.0;
  std::uint64_t evaluations = 0;
  // Whether J·f varied within some hypercube. An iteration whose every point of a hypercube gave
  // the same value (all zero, where the points missed a small support) has σ̂ = 0: no evidence
  // of its error, not a zero error (see vegas_combination).
  bool spread = true;
};

// x on axis d of the unit cube ↦ the integrand's box; the box volume multiplies the Jacobian.
struct vegas_box_map {
  explicit vegas_box_map(const box& domain)
      : lower(domain.lower), width(domain.lower.size()), volume(domain.volume()) {
    for (std::size_t j = 0; j < lower.size(); ++j) width[j] = domain.upper[j] - domain.lower[j];
  }
  double operator()(std::size_t d, double t) const noexcept { return lower[d] + width[d] * t; }
  std::vector<double> lower;
  std::vector<double> width;
  double volume;
};

// The run's state between iterations: the grid, the strata and their weights d_h, and how many
// points the run has drawn (the base of the next iteration's Philox counters).
class vegas_state {
 public:
  vegas_state(std::size_t s, const vegas_options& options)
      : s_(s), options_(options), grid_(s, 1) {}

  template <integrand F>
  vegas_iteration iterate(const F& f, const integrand_info& info, const random_stream& rng,
                          std::uint64_t n) {
    const std::size_t s = s_;
    // Increments: n/10 up to the maximum; a finer grid keeps the map (every old increment holds
    // the same probability), so a growing n never throws the adaptation away.
    const auto wanted = static_cast<std::size_t>(
        std::clamp<std::uint64_t>(n / 10, 1, std::max<std::uint64_t>(1, options_.max_increments)));
    if (wanted > grid_.increments()) {
      grid_.redraw(std::vector<double>(s * grid_.increments(), 1.0), wanted);
    }
    const std::size_t ninc = grid_.increments();

    // Strata: ns per axis with ns^s ≤ min(n/8, 2^20).
    const std::uint64_t cap =
        std::max<std::uint64_t>(1, std::min<std::uint64_t>(n / 8, std::uint64_t{1} << 20));
    const std::uint64_t ns = std::max<std::uint64_t>(1, integer_root(cap, s));
    const std::uint64_t cubes = checked_power(ns, s).value_or(1);
    if (ns != strata_) {
      strata_ = ns;
      weight_.assign(static_cast<std::size_t>(cubes), 1.0);
    }
    // Allocation: at least 2 per hypercube (a variance needs two points) and a quarter of n spread
    // evenly; the rest ∝ d_h.
    const std::uint64_t floor_per_cube = std::max<std::uint64_t>(2, n / (4 * cubes));
    const std::uint64_t pool = n - std::min(n, floor_per_cube * cubes);
    neumaier_sum weight_sum;
    for (double w : weight_) weight_sum.add(w);
    const double total_weight = weight_sum.value();
    const bool adaptive = total_weight > 0.0 && options_.beta > 0.0;
    offsets_.assign(static_cast<std::size_t>(cubes) + 1, 0);
    for (std::size_t h = 0; h < cubes; ++h) {
      const std::uint64_t extra =
          adaptive
              ? static_cast<std::uint64_t>(static_cast<double>(pool) * (weight_[h] / total_weight))
              : pool / cubes;
      offsets_[h + 1] = offsets_[h] + floor_per_cube + extra;
    }
    const std::uint64_t points = offsets_.back();

    // Chunks of fixed size (a function of the allocation only), folded in chunk order.
    const std::uint64_t chunk_points =
        std::max<std::uint64_t>(std::uint64_t{1} << 15, ((points + 63) / 64 + batch_points - 1) /
                                                            batch_points * batch_points);
    const chunking layout{points, chunk_points};
    const std::uint64_t base = samples_;
    const double inverse_strata = 1.0 / static_cast<double>(ns);
    const vegas_box_map to_box(info.domain);
    auto chunk = [&](std::size_t c) {
      vegas_chunk out;
      out.square_sum.assign(s * ninc, 0.0);
      out.count.assign(s * ninc, 0.0);
      // Buffers once per chunk, never per point.
      std::vector<double> u(batch_points * s);
      std::vector<double> x(batch_points * s);
      std::vector<double> jacobian(batch_points);
      std::vector<double> y(batch_points);
      std::vector<std::uint32_t> increment(batch_points * s);
      std::vector<std::uint64_t> cube_of(batch_points);
      std::vector<std::uint64_t> corner(s);
      // The generation cursor: the hypercube of the next point and its lower corner (in strata).
      std::uint64_t cube = static_cast<std::uint64_t>(
          std::upper_bound(offsets_.begin(), offsets_.end(), layout.begin(c)) - offsets_.begin() -
          1);
      auto decode = [&](std::uint64_t h) {
        for (std::size_t d = 0; d < s; ++d) {
          corner[d] = h % ns;
          h /= ns;
        }
      };
      decode(cube);
      // The accumulation run: consecutive points of one hypercube, as sums of deviations from its
      // first value (mean and variance without a division per point, and without the cancellation
      // of raw sums of squares).
      std::uint64_t run_cube = cube;
      std::uint64_t run_count = 0;
      double shift = 0.0, sum = 0.0, square = 0.0;
      auto close_run = [&] {
        if (run_count == 0) return;
        const double mean = sum / static_cast<double>(run_count);
        out.cubes.push_back(
            {run_cube, welford(run_count, shift + mean, std::max(0.0, square - sum * mean))});
        run_count = 0;
        sum = square = 0.0;
      };
      for_each_batch(layout, c, [&](std::uint64_t start, std::size_t count) {
        rng.fill_uniform((base + start) * s, std::span<double>(u.data(), count * s));
        for (std::size_t i = 0; i < count; ++i) {
          while (start + i >= offsets_[cube + 1]) decode(++cube);
          cube_of[i] = cube;
          double j = to_box.volume;
          for (std::size_t d = 0; d < s; ++d) {
            const double yd = (static_cast<double>(corner[d]) + u[i * s + d]) * inverse_strata;
            double xd = 0.0;
            increment[i * s + d] = static_cast<std::uint32_t>(grid_.map(d, yd, xd, j));
            x[i * s + d] = to_box(d, xd);
          }
          jacobian[i] = j;
        }
        const std::span<const double> xs(x.data(), count * s);
        const std::span<double> ys(y.data(), count);
        f.evaluate(xs, ys);
        check_finite_batch(info.name, xs, ys, s);
        for (std::size_t i = 0; i < count; ++i) {
          const double value = jacobian[i] * y[i];
          if (cube_of[i] != run_cube) {
            close_run();
            run_cube = cube_of[i];
          }
          if (run_count == 0) shift = value;
          const double deviation = value - shift;
          sum += deviation;
          square += deviation * deviation;
          ++run_count;
          const double squared = value * value;
          for (std::size_t d = 0; d < s; ++d) {
            const std::size_t k = d * ninc + increment[i * s + d];
            out.square_sum[k] += squared;
            out.count[k] += 1.0;
          }
        }
      });
      close_run();
      return out;
    };
    vegas_chunk total;
    total.square_sum.assign(s * ninc, 0.0);
    total.count.assign(s * ninc, 0.0);
    total =
        parallel_reduce(layout.chunks(), options_.threads, std::move(total), chunk,
                        [](vegas_chunk& acc, const vegas_chunk& part) {
                          acc.cubes.insert(acc.cubes.end(), part.cubes.begin(), part.cubes.end());
                          for (std::size_t k = 0; k < acc.square_sum.size(); ++k) {
                            acc.square_sum[k] += part.square_sum[k];
                            acc.count[k] += part.count[k];
                          }
                        });
    samples_ += points;

    // Per hypercube: the parts of a hypercube that straddles chunks are consecutive, merged in
    // order.
    std::vector<welford> per_cube(static_cast<std::size_t>(cubes));
    for (const vegas_cube_part& part : total.cubes) {
      per_cube[static_cast<std::size_t>(part.cube)].merge(part.stats);
    }
    const double volume = 1.0 / static_cast<double>(cubes);
    neumaier_sum value, variance, scale;
    for (std::size_t h = 0; h < cubes; ++h) {
      const welford& w = per_cube[h];
      const double var = w.variance();  // n_h ≥ 2
      value.add(volume * w.mean());
      scale.add(volume * std::abs(w.mean()));
      variance.add(volume * volume * var / static_cast<double>(w.count()));
      // d_h = (V_h σ̂_h)^β for the next iteration's allocation.
      weight_[h] = std::pow(volume * std::sqrt(var), options_.beta);
    }
    adapt_grid(total);
    vegas_iteration out;
    out.value = value.value();
    // Rounding floor: a constant integrand has σ̂ = 0 exactly, which would give its iteration an
    // infinite weight; 4ε·Σ|V_h mean_h| is the rounding of the sum itself.
    const double floor = 4.0 * std::numeric_limits<double>::epsilon() * scale.value();
    out.variance = std::max({variance.value(), floor * floor, std::numeric_limits<double>::min()});
    out.spread = variance.value() > 0.0;
    out.evaluations = points;
    return out;
  }

 private:
  // The grid's adaptation to the iteration's training data (see the file comment).
  void adapt_grid(const vegas_chunk& total) {
    if (!(options_.alpha > 0.0)) return;
    const std::size_t n = grid_.increments();
    if (n < 2) return;
    std::vector<double> weight(s_ * n, 0.0);
    std::vector<double> mean(n), smooth(n);
    for (std::size_t d = 0; d < s_; ++d) {
      for (std::size_t i = 0; i < n; ++i) {
        const double c = total.count[d * n + i];
        mean[i] = c > 0.0 ? total.square_sum[d * n + i] / c : 0.0;
      }
      smooth[0] = (7.0 * mean[0] + mean[1]) / 8.0;
      smooth[n - 1] = (7.0 * mean[n - 1] + mean[n - 2]) / 8.0;
      for (std::size_t i = 1; i + 1 < n; ++i) {
        smooth[i] = (mean[i - 1] + 6.0 * mean[i] + mean[i + 1]) / 8.0;
      }
      double sum = 0.0;
      for (double v : smooth) sum += v;
      if (!(sum > 0.0) || !std::isfinite(sum)) {
        for (std::size_t i = 0; i < n; ++i) weight[d * n + i] = 1.0;  // nothing learnt: keep it
        continue;
      }
      for (std::size_t i = 0; i < n; ++i) {
        const double r = smooth[i] / sum;
        // ((1 − r)/ln(1/r))^α: 0 at r = 0, 1 − O(1 − r) near r = 1 (then ≈ r^α).
        weight[d * n + i] =
            r <= 0.0 ? 0.0 : (r >= 1.0 ? 1.0 : std::pow((1.0 - r) / -std::log(r), options_.alpha));
      }
    }
    grid_.redraw(weight, n);
  }

  std::size_t s_;
  vegas_options options_;
  vegas_grid grid_;
  std::uint64_t strata_ = 0;
  std::vector<double> weight_;  // d_h per hypercube
  std::vector<std::uint64_t> offsets_;
  std::uint64_t samples_ = 0;  // points drawn so far in the run: the counter base
};

// Inverse-variance combination of iterations (see the file comment). An iteration without spread
// (vegas_iteration::spread: σ̂ = 0, floored to the rounding of its sum) would otherwise take a
// weight near 1/DBL_MIN and decide the combination alone: with its points all in the zero part of
// a small support (Genz discontinuous with u = (0.024, 0.087) at 102 points per iteration) the
// estimate became 0 with σ̂ ≈ 1e-154, and four such weights overflowed to NaN. As GSL's VEGAS
// does, such an iteration takes the mean weight of the iterations with spread; only where none
// has any (an integrand constant on every point drawn) do the floored variances weigh. The
// weights are divided by the largest before they are summed, so that none overflows.
struct vegas_combination {
  std::vector<vegas_iteration> parts;

  void add(const vegas_iteration& it) { parts.push_back(it); }
  bool has_spread() const {
    return std::any_of(parts.begin(), parts.end(),
                       [](const vegas_iteration& it) { return it.spread; });
  }

  // The weight of part k relative to the largest weight; `largest` is that largest weight.
  struct weighting {
    std::vector<double> relative;
    double largest = 0.0;
    double relative_sum = 0.0;
  };
  weighting weights() const {
    weighting w;
    double spread_sum = 0.0;
    std::size_t spread_count = 0;
    double largest_spread = 0.0;
    for (const vegas_iteration& it : parts) {
      if (!it.spread) continue;
      largest_spread = std::max(largest_spread, 1.0 / it.variance);
      ++spread_count;
    }
    for (const vegas_iteration& it : parts) {
      if (it.spread) spread_sum += (1.0 / it.variance) / largest_spread;
    }
    // Without spread anywhere: the floored variances (equal where the floors are).
    w.largest = spread_count > 0 ? largest_spread : 0.0;
    if (spread_count == 0) {
      for (const vegas_iteration& it : parts) w.largest = std::max(w.largest, 1.0 / it.variance);
    }
    const double mean_relative =
        spread_count > 0 ? spread_sum / static_cast<double>(spread_count) : 0.0;
    neumaier_sum sum;
    for (const vegas_iteration& it : parts) {
      const double r =
          spread_count > 0 && !it.spread ? mean_relative : (1.0 / it.variance) / w.largest;
      w.relative.push_back(r);
      sum.add(r);
    }
    w.relative_sum = sum.value();
    return w;
  }
  // Σ 1/σ_k² (inf where it overflows; only compared with 1/tolerance²).
  double total_weight() const {
    const weighting w = weights();
    return w.largest * w.relative_sum;
  }
  double value() const { return value(weights()); }
  // 1/Σw = (1/largest)/Σ(w/largest): no overflow on the way.
  double std_error() const {
    const weighting w = weights();
    return std::sqrt((1.0 / w.largest) / w.relative_sum);
  }
  double chi2() const {
    const weighting w = weights();
    const double mean = value(w);
    neumaier_sum out;
    for (std::size_t k = 0; k < parts.size(); ++k) {
      const double d = parts[k].value - mean;
      out.add(d * d * w.relative[k] * w.largest);
    }
    return out.value();
  }

 private:
  double value(const weighting& w) const {
    neumaier_sum weighted;
    for (std::size_t k = 0; k < parts.size(); ++k) weighted.add(w.relative[k] * parts[k].value);
    return weighted.value() / w.relative_sum;
  }
};

}  // namespace detail

// ∫ f over f.info().domain by VEGAS+ with the random stream (seed, stream) of generator `rng`
// (core/rng.hpp). Throws
// invalid_argument for a budget below one iteration (16 evaluations, × iterations under budget
// control), training_iterations ≥ iterations, a negative or non-finite tolerance, α < 0 or
// β ∉ [0, 1], and a bad domain; non_finite_value if f returns NaN/±inf.
template <integrand F>
vegas_result vegas(const F& f, const vegas_options& options, std::uint64_t seed,
                   std::uint64_t stream, rng_kind rng = rng_kind::philox4x32_10) {
  const auto& info = f.info();
  const std::size_t s = f.dimension();
  require(s >= 1 && info.domain.dimension() == s, "integrand dimension", s,
          "at least 1, equal to its domain's");
  for (std::size_t j = 0; j < s; ++j) {
    require(std::isfinite(info.domain.lower[j]) && std::isfinite(info.domain.upper[j]) &&
                info.domain.lower[j] <= info.domain.upper[j],
            "domain", j, "finite bounds with lower ≤ upper on every axis");
  }
  const double tolerance = options.absolute_tolerance;
  require(std::isfinite(tolerance) && tolerance >= 0.0, "absolute_tolerance", tolerance,
          "a finite tolerance ≥ 0 (0: spend the budget)");
  require(options.alpha >= 0.0 && std::isfinite(options.alpha), "alpha", options.alpha,
          "a damping ≥ 0");
  require(options.beta >= 0.0 && options.beta <= 1.0, "beta", options.beta, "in [0, 1]");
  require(options.training_iterations < options.iterations || tolerance > 0.0,
          "training_iterations", options.training_iterations,
          "fewer than `iterations` under budget control (some must be combined)");
  const random_stream draws(seed, stream, rng);
  detail::vegas_state state(s, options);
  detail::vegas_combination combined;
  vegas_result out;
  std::uint64_t spent = 0;
  auto run = [&](std::uint64_t n) {
    const detail::vegas_iteration it = state.iterate(f, info, draws, n);
    spent += it.evaluations;
    ++out.iterations;
    return it;
  };

  if (tolerance == 0.0) {
    const std::uint64_t n = options.max_evaluations / options.iterations;
    require(n >= vegas_min_iteration_evaluations, "max_evaluations", options.max_evaluations,
            fmt::format("at least {} evaluations per iteration × {} iterations",
                        vegas_min_iteration_evaluations, options.iterations));
    for (unsigned k = 0; k < options.iterations; ++k) {
      const detail::vegas_iteration it = run(n);
      if (k >= options.training_iterations) combined.add(it);
    }
  } else {
    const std::uint64_t first =
        std::max(options.evaluations_per_iteration, vegas_min_iteration_evaluations);
    require(options.max_evaluations >= first, "max_evaluations", options.max_evaluations,
            fmt::format("at least one iteration of {} evaluations", first));
    detail::vegas_iteration last;
    for (unsigned k = 0; k < options.training_iterations; ++k) {
      if (options.max_evaluations - spent < first) break;
      last = run(first);
    }
    std::uint64_t n = first;
    while (options.max_evaluations - spent >= vegas_min_iteration_evaluations) {
      n = std::min(n, options.max_evaluations - spent);
      const detail::vegas_iteration it = run(n);
      combined.add(it);
      // An iteration with spread is the evidence: σ̂ from floored variances alone (every point
      // gave one value, as on a constant f or where every point missed a small support) is not
      // a claim to stop on.
      if (combined.parts.size() >= 2 && combined.has_spread() &&
          combined.std_error() <= tolerance) {
        out.converged = true;
        break;
      }
      // The size whose σ̂ would bring the combination to the tolerance, σ̂² ∝ 1/n, between the
      // last size and 4× it.
      const double missing = 1.0 / (tolerance * tolerance) - combined.total_weight();
      const double needed = missing > 0.0
                                ? static_cast<double>(it.evaluations) * it.variance * missing
                                : static_cast<double>(it.evaluations);
      n = static_cast<std::uint64_t>(std::clamp(needed, static_cast<double>(it.evaluations),
                                                4.0 * static_cast<double>(it.evaluations)));
    }
    // The budget ran out within the training iterations: the last of them is the estimate.
    if (combined.parts.empty()) combined.add(last);
  }
  out.value = combined.value();
  out.std_error = combined.std_error();
  out.evaluations = spent;
  out.combined_iterations = static_cast<unsigned>(combined.parts.size());
  if (combined.parts.size() >= 2) {
    const double dof = static_cast<double>(combined.parts.size() - 1);
    const double chi2 = combined.chi2();
    out.chi2_per_dof = chi2 / dof;
    out.q = boost::math::gamma_q(dof / 2.0, chi2 / 2.0);
  }
  return out;
}

}  // namespace quadmc
