// The floating-point format an integrand is evaluated in (float, double or long double), which
// sets the rounding floor of every rule on it (analysis/rounding_floor.hpp,
// docs/theory.md#rounding-floor).
//
// Use it in an integrand's metadata (functions/integrand.hpp: integrand_info::precision) when its
// values carry the rounding of a format other than double, e.g. the float twins of the stress
// scene, whose values are rounded to ε_f = 2⁻²³ before the rule adds them in double. Not for the
// accumulator of a sum (core/summation.hpp's enum summation says how terms are added).
#pragma once

#include <limits>

namespace quadmc {

enum class evaluation_precision {
  single_precision,  // float: ε = 2⁻²³ ≈ 1.2e-7
  double_precision,  // double: ε = 2⁻⁵² ≈ 2.2e-16 (every integrand unless it says otherwise)
  extended_precision,  // x87 long double: ε = 2⁻⁶³ ≈ 1.1e-19
};

// Machine epsilon (the spacing of the format's numbers at 1) of the format.
constexpr double epsilon_of(evaluation_precision p) noexcept {
  switch (p) {
    case evaluation_precision::single_precision:
      return static_cast<double>(std::numeric_limits<float>::epsilon());
    case evaluation_precision::double_precision:
      return std::numeric_limits<double>::epsilon();
    case evaluation_precision::extended_precision:
      return static_cast<double>(std::numeric_limits<long double>::epsilon());
  }
  return std::numeric_limits<double>::epsilon();
}

// The C++ name of the format: "float", "double", "long double".
constexpr const char* to_string(evaluation_precision p) noexcept {
  switch (p) {
    case evaluation_precision::single_precision:
      return "float";
    case evaluation_precision::double_precision:
      return "double";
    case evaluation_precision::extended_precision:
      return "long double";
  }
  return "?";
}

}  // namespace quadmc
