// A batch integrand (quadmc's contract, functions/integrand.hpp) evaluated at one point: the
// adapter for peers whose API calls the integrand point by point (GSL's gsl_monte_function,
// Boost's naive_monte_carlo and 1D quadrature, the scalar reference loop).
//
// Why a batch of one rather than a re-written formula: every method then runs the very same
// integrand code (docs/design.md#performance-targets). evaluate() is an inline member function of
// a class the compiler sees whole, so with y.size() == 1 the loop over points folds away; what
// remains per call is the formula plus whatever the peer's own calling convention costs (a
// function pointer for GSL, a std::function for Boost). A batch of one takes the integrands'
// scalar path: vector_exp/vector_cos (core/vector_math.hpp) call scalar glibc inline for fewer
// than 8 values, so per-point peers are not charged for quadmc's vector math.
#pragma once

#include <cstddef>
#include <span>

namespace quadmc::bench {

template <class F>
inline double evaluate_point(const F& f, const double* x, std::size_t s) noexcept {
  double y;
  f.evaluate(std::span<const double>(x, s), std::span<double>(&y, 1));
  return y;
}

}  // namespace quadmc::bench
