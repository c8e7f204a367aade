// One estimate from k independent randomizations of a quasi-Monte Carlo set: their mean or their
// median, each with its own error bar (docs/theory.md#replicate-estimators).
//
//   mean    x̄ = Σx_r/k, std_error = error_estimate = s_k/√k (s_k with divisor k − 1): the
//           standard error of a mean of k independent unbiased estimates.
//   median  the middle value x_((k+1)/2) of an odd k (Pan & Owen's median of means, [Pan & Owen
//           2023]): under random linear scrambling of a net its error falls faster than any power
//           of n for analytic f in one dimension, where the mean's is n^(−3/2); under nested
//           (Owen) scrambling it does not ([Goda & Suzuki 2025]). Its error bar is distribution
//           free: the order statistics x_(l) ≤ x_(k+1−l) cover the median of the estimator's law
//           with probability 1 − 2·P(Bin(k, 1/2) ≤ l − 1); the claim is the larger distance from
//           x_((k+1)/2) to the ends of the narrowest such interval of probability ≥ 68.27 % (the
//           probability of ±1σ, so that it reads like the mean's one-σ claim). It claims an
//           error of the integral only as far as that median is I, which is what the median's
//           theory proves for smooth f and what the reliability scene audits. No std_error (NaN):
//           no normal law stands behind it.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

namespace quadmc {

enum class replicate_estimator { mean, median };

std::string_view to_string(replicate_estimator e) noexcept;

// The mean and the standard deviation (divisor k − 1) of k ≥ 2 independent estimates, in two
// passes (the mean pairwise, core/summation.hpp, then the squared deviations from it): the
// spread of randomizations that the mean's error bar here and the replicate stopping rule
// (stopping_rules.hpp) both stand on. Throws invalid_argument for k < 2.
struct mean_and_deviation {
  double mean = 0.0;
  double sd = 0.0;
};
mean_and_deviation replicate_mean_and_sd(std::span<const double> values);

struct combined_replicates {
  double value = 0.0;
  double std_error = 0.0;       // NaN for the median
  double error_estimate = 0.0;  // the error bar above
};

// The probability 1 − 2·P(Bin(k, 1/2) ≤ l − 1) that x_(l) ≤ m ≤ x_(k+1−l) for the median m of
// the law of k independent draws. Throws invalid_argument unless 1 ≤ l ≤ (k + 1)/2.
double median_interval_coverage(std::size_t k, std::size_t l);

// The largest l (the narrowest interval) whose coverage is at least `level`; k ≥ 3 odd holds one
// for level ≤ 0.75 (l = 1 at k = 3). Throws invalid_argument when none has.
std::size_t median_interval_rank(std::size_t k, double level);

// The mean (k ≥ 2) or the median (k ≥ 3 odd) of the k values, with its error bar. Throws
// invalid_argument for a k outside those, naming it.
combined_replicates combine_replicates(std::span<const double> values, replicate_estimator how);

}  // namespace quadmc
