// Summation of many terms without losing the answer to rounding.
//
// Why it matters here: a quadrature rule with n = 10^8 panels adds 10^8 terms. Naive recursive
// summation has an error bound of (n-1)·ε·Σ|x_i| (Higham, "Accuracy and Stability of Numerical
// Algorithms", 2nd ed., §4.2), so past n ≈ 1/ε^(1/2) its rounding error exceeds the O(n^-2)
// discretisation error of a midpoint rule and the convergence curve turns back up: "the error is
// σ/√N + εN, which diverges faster than it converges" (Boost.Math naive_monte_carlo.hpp).
//
//  - neumaier_sum: compensated summation (Neumaier 1974, improved Kahan–Babuška). Error bound
//    2ε·Σ|x_i| + O(nε²)·Σ|x_i| (Higham §4.3): independent of n to first order. Use it to stream
//    terms one at a time (chunk results, batch sums).
//  - pairwise_sum: recursive halving, error bound ε·log2(n)·Σ|x_i| (Higham §4.2). Cheaper than
//    Neumaier per term and vectorizes; use it on a contiguous batch.
//  - naive_sum: kept only so tests and the stress scene can show what the others buy.
#pragma once

#include <cmath>
#include <cstddef>
#include <span>

namespace quadmc {

// Neumaier's variant of Kahan summation: also correct when the new term is larger in magnitude
// than the running sum (plain Kahan loses the small sum then). Not vectorizable by design: the
// compiler must not reassociate it, so never build this with -ffast-math.
class neumaier_sum {
 public:
  constexpr neumaier_sum() = default;
  constexpr explicit neumaier_sum(double initial) : sum_(initial) {}

  constexpr void add(double x) noexcept {
    const double t = sum_ + x;
    // The low-order bits lost in t are recovered from whichever operand was larger.
    if (std::abs(sum_) >= std::abs(x)) {
      compensation_ += (sum_ - t) + x;
    } else {
      compensation_ += (x - t) + sum_;
    }
    sum_ = t;
  }
  constexpr neumaier_sum& operator+=(double x) noexcept {
    add(x);
    return *this;
  }
  // Combines two partial sums (e.g. of two chunks) keeping both compensations.
  constexpr void merge(const neumaier_sum& other) noexcept {
    add(other.sum_);
    compensation_ += other.compensation_;
  }
  constexpr double value() const noexcept { return sum_ + compensation_; }

 private:
  double sum_ = 0.0;
  double compensation_ = 0.0;
};

// Pairwise (cascade) summation. Below the block size a plain loop with eight independent
// accumulators runs: that is itself an 8-way pairwise split, lets the compiler vectorize, and
// keeps the recursion depth at log2(n/128).
inline double pairwise_sum(std::span<const double> x) noexcept {
  constexpr std::size_t block = 128;
  if (x.size() <= block) {
    double acc[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    std::size_t i = 0;
    for (; i + 8 <= x.size(); i += 8) {
      for (std::size_t k = 0; k < 8; ++k) acc[k] += x[i + k];
    }
    // The tail has x.size() % 8 terms; bounding the loop by that (< 8) rather than by
    // i < x.size() keeps GCC from a false -Werror=aggressive-loop-optimizations when the
    // recursion is inlined (GCC 12, -O2). Same accumulators, same order as before.
    for (std::size_t k = 0; k < x.size() % 8; ++k) acc[k] += x[i + k];
    return ((acc[0] + acc[1]) + (acc[2] + acc[3])) + ((acc[4] + acc[5]) + (acc[6] + acc[7]));
  }
  // Split on a multiple of the block so every leaf but the last is full.
  const std::size_t half = ((x.size() / 2 + block - 1) / block) * block;
  return pairwise_sum(x.first(half)) + pairwise_sum(x.subspan(half));
}

// Left-to-right recursive summation: the baseline the other two are measured against.
inline double naive_sum(std::span<const double> x) noexcept {
  double s = 0.0;
  for (double v : x) s += v;
  return s;
}

}  // namespace quadmc
