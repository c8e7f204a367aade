// exp and cos of a whole batch at once: the transcendental part of an integrand's batch
// evaluation (functions/genz.hpp), on glibc's vector math library libmvec where the CPU allows.
//
// Why: one scalar glibc exp or cos costs about as much as all the arithmetic around it in a Genz
// integrand; libmvec evaluates 2, 4 or 8 of them per call (SSE2, AVX2, AVX-512 variants of the
// x86_64 vector function ABI), chosen at run time by simd_level.hpp. Accuracy: glibc documents
// libmvec's functions to 4 ulp, scalar glibc's to under 1 ulp; the two paths are compared on every
// integrand in tests/core/vector_math_test.cpp and tests/functions/catalogue_test.cpp, which
// state the bound they hold. Every element goes through the same vector routine (a short tail is
// padded, not handed to scalar code), so a point's value does not depend on where in a batch it
// falls.
//
// Calls with fewer than vector_math_min_size values (a point evaluated alone, as the per-point
// peers and the scalar reference loop of bench/ do) take scalar glibc inline: a vector call would
// cost more than it saves there. So "the scalar path" of an integrand is its evaluation one point
// at a time, and the vector path is its batch evaluation; a given call size always takes the same
// path, so results stay bitwise reproducible for any thread count (batches are fixed by the
// problem, not the schedule).
//
// Use it inside batch evaluate() loops: compute the arguments into y, then apply in place.
#pragma once

#include <cmath>
#include <cstddef>
#include <span>

namespace quadmc {

inline constexpr std::size_t vector_math_min_size = 8;

namespace detail {
enum class vector_function { exp, cos };
// The out-of-line part: checks sizes and dispatches on active_simd_level().
void vector_math(vector_function f, std::span<const double> x, std::span<double> y);
[[noreturn]] void throw_vector_math_size_mismatch(std::size_t x_size, std::size_t y_size);
}  // namespace detail

// y[i] = exp(x[i]) for i < x.size(); x and y may be the same span; y.size() must equal x.size()
// (invalid_argument otherwise).
inline void vector_exp(std::span<const double> x, std::span<double> y) {
  if (x.size() >= vector_math_min_size)
    return detail::vector_math(detail::vector_function::exp, x, y);
  if (y.size() != x.size()) detail::throw_vector_math_size_mismatch(x.size(), y.size());
  for (std::size_t i = 0; i < x.size(); ++i) y[i] = std::exp(x[i]);
}

// y[i] = cos(x[i]), the same way.
inline void vector_cos(std::span<const double> x, std::span<double> y) {
  if (x.size() >= vector_math_min_size)
    return detail::vector_math(detail::vector_function::cos, x, y);
  if (y.size() != x.size()) detail::throw_vector_math_size_mismatch(x.size(), y.size());
  for (std::size_t i = 0; i < x.size(); ++i) y[i] = std::cos(x[i]);
}

}  // namespace quadmc
