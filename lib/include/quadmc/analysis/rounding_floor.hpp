// Rounding-floor detection: where a convergence ladder stops measuring the method and starts
// measuring floating-point rounding.
//
// Use it on a ladder sorted by N before fitting a slope (power_law_fit.hpp): floor points would
// flatten the fit. Not a test of statistical noise: Monte Carlo errors never come near the
// rounding level at practical N, and the rule below only fires near it.
//
// Why a floor exists: a rule that adds N terms t_k = w_k·f(x_k) carries, besides its own
// discretisation error, the rounding of each value f(x_k) (relative ε_f of the format f is
// evaluated in: float's 2⁻²³ for the float twins of the stress scene, double's 2⁻⁵² otherwise) and
// the rounding of the sum: ⌈log₂N⌉u·Σ|t_k| for pairwise summation, 2u·Σ|t_k| for compensated
// summation (Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., §4.2–4.3), and
// (N − 1)u·Σ|t_k| in the worst case for a recursive (naive) sum, whose realistic size is ≈ u·√N
// (Higham §2.8 and §4.2: round-to-nearest errors behave like a random walk; the stress scene
// measures ε·√N·I for naive sums to 10⁹ terms, far below ε·N·I), with Σ|t_k| ≈ ∫|f| ≥ |I|. Once
// the method's error falls below that, the measured error stops decreasing (Gauss–Legendre,
// Romberg, Simpson at large n) or turns back up (naive sums).
//
// The rule (points k = 0…n−1 in increasing N, errors e_k ≥ 0, scale S = |I| or another magnitude
// of the integrand):
//   rounding level  ℓ(N) = κ·S·max(ε_f, σ(N)), κ = 2, with σ(N) the accumulator's term:
//                   ε·max(1, log₂N) pairwise (the default), ε Neumaier, ε·max(1, √N) naive,
//                   ε_x·max(1, √N) for an x87 long double sum (ε = 2⁻⁵², ε_x = 2⁻⁶³). The
//                   larger of the two sources is the level; κ = 2 allows for the smaller one and
//                   for the rounding of the reference value and of the final scaling. For double
//                   evaluation and the pairwise sum this is κ·ε·S·max(1, log₂N): every level of the
//                   suite before the model knew the precision.
#pragma once

#include "quadmc/core/evaluation_precision.hpp"
#include "quadmc/core/summation.hpp"

#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace quadmc {

struct rounding_floor_options {
  double kappa = 2.0;            // κ in ℓ(N) = κ·ε·S·max(1, log₂N)
  double band = 1e4;             // B: how far above ℓ a stall still counts as the floor
  double stall_factor = 2.0;     // F: a later point must improve by more than this
  std::size_t stall_window = 2;  // W: how many later points are looked at
  // An error below this many times the reference's uncertainty measures the reference, not the
  // method (add_reference_floor).
  double reference_factor = 10.0;
};

struct rounding_floor {
  std::vector<bool> flags;           // flags[k]: point k is at the rounding floor
  std::optional<std::size_t> first;  // index of the first floor point, if any
  double attainable_accuracy = std::numeric_limits<double>::quiet_NaN();
  double floor_level = std::numeric_limits<double>::quiet_NaN();  // median error of floor points
  // The first point below the reference's floor (add_reference_floor), if any: it starts the floor
  // when it comes before `first` would have without it.
  std::optional<std::size_t> reference_first;

  bool reached() const noexcept { return first.has_value(); }
  std::size_t count() const noexcept { return first ? flags.size() - *first : 0; }
};

// What sets the rounding of one series: the format of f's values and how the method adds them.
struct rounding_model {
  evaluation_precision precision = evaluation_precision::double_precision;
  summation accumulator = summation::pairwise;

  // σ(N)/ε_f combined: max(ε_f, σ(N)), the relative level before κ and S.
  double relative_level(double n) const noexcept;
  // "float evaluation, pairwise sum", for notes and the slopes table.
  std::string describe() const;
};

// ℓ(N) for one point: double evaluation, pairwise sum (the default model).
double rounding_level(double n, double scale, const rounding_floor_options& options = {});
// ℓ(N) = κ·S·max(ε_f, σ(N)) for one point of a series with this model.
double rounding_level(double n, double scale, const rounding_model& model,
                      const rounding_floor_options& options = {});

// Throws invalid_argument when sizes differ, N is not finite, > 0 and strictly increasing, an
// error is negative or not finite, the scale is not finite and ≥ 0, or an option is out of range
// (κ > 0, B ≥ 1, F > 1, W ≥ 1).
rounding_floor detect_rounding_floor(std::span<const double> n, std::span<const double> error,
                                     double scale, const rounding_floor_options& options = {});
// The same rule with the level of `model`.
rounding_floor detect_rounding_floor(std::span<const double> n, std::span<const double> error,
                                     double scale, const rounding_model& model,
                                     const rounding_floor_options& options = {});

// The same with a scale per point, S_k: for a ladder whose rules amplify rounding differently at
// each N (a sparse grid's weights of both signs: S_k = |I|·Σ|w| at point k, since its sum errs by
// ≈ 2ε·Σ|w_i f_i| and an error δ in f by Σ|w|·δ; rules/weighted_point_set.hpp). Throws as above,
// and for scales of another size than n or not finite and ≥ 0.
rounding_floor detect_rounding_floor(std::span<const double> n, std::span<const double> error,
                                     std::span<const double> scales,
                                     const rounding_floor_options& options = {});
// Per-point scales with the level of `model`.
rounding_floor detect_rounding_floor(std::span<const double> n, std::span<const double> error,
                                     std::span<const double> scales, const rounding_model& model,
                                     const rounding_floor_options& options = {});

// The reference's floor (docs/theory.md#references-without-a-closed-form): a reference known
// only to ± u (given with its uncertainty, or computed) cannot tell an error below ≈ u from 0,
// and one below factor·u (10u) is at least 10% its own uncertainty. Such a point, and every
// later one (the floor is a tail, as the rounding floor is: a longer ladder does not climb back
// out of it), joins the floor and is not fitted; floor_level and attainable_accuracy are
// recomputed over the joined floor. Nothing changes for u = 0 (an exact reference). Throws
// invalid_argument when u is negative or not finite, the factor not finite and > 0, or the
// errors are not floor.flags.size().
void add_reference_floor(rounding_floor& floor, std::span<const double> error, double uncertainty,
                         double factor);

}  // namespace quadmc
