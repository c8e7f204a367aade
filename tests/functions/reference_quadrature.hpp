// Independent reference integration for the functions tests: adaptive Gauss–Kronrod from
// Boost.Math (not the library's rules layer), split at the known kinks and jumps of the
// integrand, so they do not limit the accuracy.
#pragma once

#include "quadmc/functions/integrand.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <span>
#include <vector>

namespace quadmc::test {

// ∫_a^b f by 61-point adaptive Gauss–Kronrod, one piece per interval between the breakpoints that
// fall strictly inside (a, b). Tolerance 1e-13 relative to ∫|f| with at most 2^7 subintervals
// per piece: an outer integral of inner integrals sees their ~1e-14 noise, and a tighter
// tolerance would only recurse to max depth (2^depth intervals) without gaining a digit.
// f is taken as a std::function so that Boost's adaptive integrator is instantiated once per test
// file, not once per lambda: nested integrals of many integrands made these files the slowest of
// the build (compiling genz_test with the sanitizers took 111 s before); an indirect call per
// evaluation is nothing beside the integrand.
inline double gauss_kronrod(const std::function<double(double)>& f, double a, double b,
                            std::vector<double> breaks = {}, unsigned max_depth = 7) {
  breaks.push_back(a);
  breaks.push_back(b);
  std::sort(breaks.begin(), breaks.end());
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double lo = std::max(a, breaks[i]);
    const double hi = std::min(b, breaks[i + 1]);
    if (hi <= lo) continue;
    sum +=
        boost::math::quadrature::gauss_kronrod<double, 61>::integrate(f, lo, hi, max_depth, 1e-13);
  }
  return sum;
}

// f at one point, through the batch interface.
template <class F>
double at(const F& f, std::span<const double> x) {
  double y = 0.0;
  f.evaluate(x, std::span<double>(&y, 1));
  return y;
}
template <class F>
double at(const F& f, std::initializer_list<double> x) {
  return at(f, std::span<const double>(x.begin(), x.size()));
}

inline double relative_error(double value, double exact) {
  return std::abs(value - exact) / std::abs(exact);
}

}  // namespace quadmc::test
