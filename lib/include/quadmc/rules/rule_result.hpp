// What a deterministic quadrature rule returns: more than a number (Boost's trapezoidal returns
// an error estimate and the L1 norm through out-pointers; we return one small struct).
#pragma once

#include <cstdint>
#include <limits>

namespace quadmc {

struct rule_result {
  double value = 0.0;
  // A-posteriori error estimate where the rule has one (Romberg: difference of the last two
  // diagonal extrapolants); NaN for the fixed rules of tensor_product.hpp, whose accuracy is
  // stated a priori by error_bounds.hpp instead.
  double error_estimate = std::numeric_limits<double>::quiet_NaN();
  std::uint64_t evaluations = 0;
};

}  // namespace quadmc
