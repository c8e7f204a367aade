// Running mean and variance that can be merged: the accumulator of every Monte Carlo estimator.
//
// Why not Σx² − (Σx)²/n: for data with mean 1e9 and standard deviation 1e-3, Σx² ≈ n·1e18 and the
// difference is ~1e-6 of it — below double precision, so the textbook formula returns noise or a
// negative variance. Welford's update (Welford 1962; Knuth TAOCP vol. 2 §4.2.2) accumulates
// deviations from the running mean and keeps full relative accuracy in the variance.
// Two accumulators combine with the pairwise formula of Chan, Golub & LeVeque (1979):
//   δ = mean_b − mean_a,  mean = mean_a + δ·n_b/n,  M2 = M2_a + M2_b + δ²·n_a·n_b/n,
// so chunks computed on different threads merge in a fixed order into bitwise-reproducible
// results.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

namespace quadmc {

class welford {
 public:
  constexpr welford() noexcept = default;
  // The statistics of a block computed elsewhere (e.g. by two passes over a batch): `count`
  // values with this mean and sum of squared deviations m2 = Σ(x − mean)².
  constexpr welford(std::uint64_t count, double mean, double m2) noexcept
      : count_(count), mean_(count == 0 ? 0.0 : mean), m2_(count == 0 ? 0.0 : m2) {}

  constexpr void add(double x) noexcept {
    ++count_;
    const double delta = x - mean_;
    mean_ += delta / static_cast<double>(count_);
    m2_ += delta * (x - mean_);
  }

  constexpr void merge(const welford& other) noexcept {
    if (other.count_ == 0) return;
    if (count_ == 0) {
      *this = other;
      return;
    }
    const double na = static_cast<double>(count_);
    const double nb = static_cast<double>(other.count_);
    const double n = na + nb;
    const double delta = other.mean_ - mean_;
    mean_ += delta * (nb / n);
    m2_ += other.m2_ + delta * delta * (na * nb / n);
    count_ += other.count_;
  }

  constexpr std::uint64_t count() const noexcept { return count_; }
  constexpr double mean() const noexcept { return mean_; }
  // Sum of squared deviations from the mean, Σ(x − x̄)².
  constexpr double m2() const noexcept { return m2_; }
  // Unbiased sample variance Σ(x − x̄)²/(n − 1); NaN for fewer than two values, because no
  // variance can be estimated from one (returning 0 would claim a perfect estimate).
  constexpr double variance() const noexcept {
    return count_ < 2 ? std::numeric_limits<double>::quiet_NaN()
                      : m2_ / static_cast<double>(count_ - 1);
  }
  // Standard error of the mean, √(s²/n).
  double std_error() const noexcept { return std::sqrt(variance() / static_cast<double>(count_)); }

 private:
  std::uint64_t count_ = 0;
  double mean_ = 0.0;
  double m2_ = 0.0;
};

}  // namespace quadmc
