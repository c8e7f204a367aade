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
//  - enum summation: the accumulator a long sum uses (tensor-product rules take it as an option,
//    scenes as the method key `accumulator`), so the stress scene can compare them on the same
//    terms: error bounds (n−1)ε (naive), ε·log2 n (pairwise), 2ε (Neumaier), each times Σ|x_i|,
//    and (n−1)·2⁻⁶⁴ for x87 long double (Higham §4.2–4.3 with u = 2⁻⁶⁴).
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

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

// How a long sum of terms is accumulated.
//  - pairwise: pairwise within each batch of 256 terms, batches and chunks added with Neumaier:
//    the library's default (fast: the batch loop vectorizes; error ≈ 2ε·Σ|x| + ε·8·Σ|batch|).
//  - neumaier: every term through neumaier_sum (error 2ε·Σ|x|, ≈ 4× the flops of a plain add).
//  - naive: one double added left to right over all terms in index order, serially (error up to
//    (n−1)ε·Σ|x|; for smooth terms the rounding is biased, so it really grows like ε·n).
//  - long_double: left to right in long double (x87 80-bit on x86-64: u = 2⁻⁶⁴, so the error is
//    (n−1)·2⁻⁶⁴·Σ|x| — 2048× smaller than naive double but still growing with n; where long
//    double is plain double, e.g. AArch64 Apple or MSVC, it is the naive sum in chunks).
enum class summation { pairwise, neumaier, naive, long_double };

constexpr std::string_view to_string(summation s) noexcept {
  switch (s) {
    case summation::pairwise:
      return "pairwise";
    case summation::neumaier:
      return "neumaier";
    case summation::naive:
      return "naive";
    case summation::long_double:
      return "long_double";
  }
  return "?";
}

// The summation named `name` (the spelling of to_string), or nullopt.
constexpr std::optional<summation> parse_summation(std::string_view name) noexcept {
  for (summation s :
       {summation::pairwise, summation::neumaier, summation::naive, summation::long_double}) {
    if (to_string(s) == name) return s;
  }
  return std::nullopt;
}

}  // namespace quadmc
