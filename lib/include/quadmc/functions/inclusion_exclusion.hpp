// Alternating sums over the 2^s vertices of the unit cube, Σ_{v∈{0,1}^s} (−1)^{|v|} g(a·v), with
// a rounding-error bound: the closed forms of the Genz corner peak and of the half-space volume
// are such sums (integrate one coordinate at a time: each step turns into a difference
// g(c) − g(c + a_j)).
//
// Why 50 digits: the terms are O(1) while their sum can be 10^-12 of that (corner peak, s = 12,
// Genz difficulty), so a sum in double or even long double loses the answer. Measured against
// 100-digit arithmetic (tests/functions/genz_test.cpp), random Genz corner-peak weights with
// Σa = 1.85: double errs 5.5e-12 relative at s = 8, 2.2e-10 at s = 10, 8e-7 at s = 14; long
// double (x86 80-bit) 8e-15 at s = 8, 8e-14 at s = 10, 6e-10 at s = 14. So the sum runs in Boost's
// cpp_bin_float_50 (≈ 50 significant digits, header-only): cancellation up to ~10^30 is harmless.
// Vertices are visited in Gray-code order so that a·v changes by one ±a_j per vertex (one
// 50-digit addition per term instead of s). Cost ≈ 1 µs per vertex (-O2): 1 s at s = 20.
//
// Use it only where the 2^s terms are affordable (s ≤ 20); callers still check the returned bound
// and refuse parameters whose reference would be untrustworthy.
#pragma once

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>

namespace quadmc {

using wide_float = boost::multiprecision::cpp_bin_float_50;

struct vertex_sum {
  wide_float value;        // Σ (−1)^{|v|} g(a·v)
  wide_float error_bound;  // bound on |value − exact sum| from rounding
};

// g(const wide_float& t, const wide_float& t_error) returns {g(t), a bound on the absolute error
// of the computed g(t) given |t − a·v| ≤ t_error}. The Gray-code updates put at most 2^s
// roundings of size ε·Σ|a| into t; the sum's own rounding is ≤ 2^s·ε·Σ|g| (Higham, "Accuracy and
// Stability of Numerical Algorithms", §4.2).
template <class G>
vertex_sum alternating_vertex_sum(std::span<const double> a, G&& g) {
  const std::size_t s = a.size();
  const std::uint64_t count = std::uint64_t{1} << s;
  const wide_float eps = std::numeric_limits<wide_float>::epsilon();
  wide_float abs_a = 0;
  for (double aj : a) abs_a += std::abs(aj);
  const wide_float t_error = static_cast<double>(count) * eps * abs_a;
  wide_float sum = 0, magnitude = 0, term_errors = 0, t = 0;
  int parity = 0;
  for (std::uint64_t k = 0; k < count; ++k) {
    if (k > 0) {
      // Gray code k ^ (k >> 1) differs from its predecessor in bit ctz(k).
      const auto j = static_cast<std::size_t>(__builtin_ctzll(k));
      const bool set = ((k ^ (k >> 1)) >> j) & 1U;
      if (set) {
        t += a[j];
      } else {
        t -= a[j];
      }
      parity ^= 1;
    }
    auto [value, error] = g(t, t_error);
    if (parity) {
      sum -= value;
    } else {
      sum += value;
    }
    magnitude += boost::multiprecision::abs(value);
    term_errors += error;
  }
  return {sum, term_errors + static_cast<double>(count) * eps * magnitude};
}

}  // namespace quadmc
