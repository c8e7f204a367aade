// Rounding-floor detection: where a convergence ladder stops measuring the method and starts
// measuring floating-point rounding.
//
// Use it on a ladder sorted by N before fitting a slope (power_law_fit.hpp): floor points would
// flatten the fit. Not a test of statistical noise: Monte Carlo errors never come near the
// rounding level at practical N, and the rule below only fires near it.
//
// Why a floor exists: a rule that adds N terms carries a rounding error of about ε·log₂N·Σ|t_k|
// for pairwise summation and 2ε·Σ|t_k| for compensated summation (Higham, Accuracy and Stability
// of Numerical Algorithms, 2nd ed., §4.2–4.3), with Σ|t_k| ≈ ∫|f| ≥ |I|; naive summation grows
// like ε·N. Once the method's error falls below that, the measured error stops decreasing
// (Gauss–Legendre, Romberg, Simpson at large n) or turns back up (naive sums).
//
// The rule (points k = 0…n−1 in increasing N, errors e_k ≥ 0, scale S = |I| or another magnitude
// of the integrand):
//   rounding level  ℓ(N) = κ·ε·S·max(1, log₂N), κ = 2: the pairwise worst case with ∫|f| = S,
//                   doubled for the rounding of the reference value and of the final scaling.
//   (i)  at the floor: e_k ≤ ℓ(N_k) (this includes e_k = 0, an error below any resolution);
//   (ii) stalled near the floor: e_k ≤ B·ℓ(N_k) with B = 10⁴ (within four decades of the
//        rounding level, where a ladder can plausibly run out of precision) and neither of the
//        next W = 2 points improves on e_k by more than a factor F = 2:
//        min(e_{k+1}, e_{k+2}) > e_k/F. Any algebraic rate ≥ 1/2 on a ladder that doubles N
//        twice improves by ≥ 2, so a converging ladder does not stall. The window is short on
//        purpose: the minimum over *all* later points would, on a long floor of random rounding
//        noise, almost surely find one lucky small value and never see the stall. The last
//        point cannot stall (nothing after it to judge by).
// The floor starts at the first k meeting (i) or (ii); that point and every later one are floor
// points (once rounding dominates, a larger N cannot recover). The attainable accuracy is the
// smallest error before the floor (the whole ladder when no floor was reached; the smallest floor
// error when the floor starts at the first point). With S = 0 (I = 0 and no other magnitude) only
// exact zeros are flagged.
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <vector>

namespace quadmc {

struct rounding_floor_options {
  double kappa = 2.0;            // κ in ℓ(N) = κ·ε·S·max(1, log₂N)
  double band = 1e4;             // B: how far above ℓ a stall still counts as the floor
  double stall_factor = 2.0;     // F: a later point must improve by more than this
  std::size_t stall_window = 2;  // W: how many later points are looked at
};

struct rounding_floor {
  std::vector<bool> flags;           // flags[k]: point k is at the rounding floor
  std::optional<std::size_t> first;  // index of the first floor point, if any
  double attainable_accuracy = std::numeric_limits<double>::quiet_NaN();
  double floor_level = std::numeric_limits<double>::quiet_NaN();  // median error of floor points

  bool reached() const noexcept { return first.has_value(); }
  std::size_t count() const noexcept { return first ? flags.size() - *first : 0; }
};

// ℓ(N) for one point.
double rounding_level(double n, double scale, const rounding_floor_options& options = {});

// Throws invalid_argument when sizes differ, N is not finite, > 0 and strictly increasing, an
// error is negative or not finite, the scale is not finite and ≥ 0, or an option is out of range
// (κ > 0, B ≥ 1, F > 1, W ≥ 1).
rounding_floor detect_rounding_floor(std::span<const double> n, std::span<const double> error,
                                     double scale, const rounding_floor_options& options = {});

// The same with a scale per point, S_k: for a ladder whose rules amplify rounding differently at
// each N (a sparse grid's weights of both signs: S_k = |I|·Σ|w| at point k, since its sum errs by
// ≈ 2ε·Σ|w_i f_i| and an error δ in f by Σ|w|·δ; rules/weighted_point_set.hpp). Throws as above,
// and for scales of another size than n or not finite and ≥ 0.
rounding_floor detect_rounding_floor(std::span<const double> n, std::span<const double> error,
                                     std::span<const double> scales,
                                     const rounding_floor_options& options = {});

}  // namespace quadmc
