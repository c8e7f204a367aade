// A reference integral computed once, for an integrand whose scene table says
// `reference = "computed"` (parse.hpp): the most accurate method of the suite for its dimension,
// run to a tight tolerance, with the method's own error estimate as the reference's uncertainty
// (docs/theory.md#references-without-a-closed-form).
//
// Use it through make_plan, which calls it once per such integrand and states the result in the
// plan listing and on the results page. Not a replacement for a closed form: the uncertainty is
// an a-posteriori estimate (a difference of two levels or two embedded rules), reliable on
// smooth integrands and blind to what falls between the nodes (a narrow peak, an interior jump).
// Not for s > max_computed_reference_dimension: Genz–Malik needs 2^s + 2s² + 2s + 1 evaluations
// per region.
#pragma once

#include "quadmc/functions/any_integrand.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

namespace quadmc {

// The largest s a reference is computed for (2^10 + 221 = 1245 evaluations per region).
inline constexpr std::size_t max_computed_reference_dimension = 10;

struct computed_reference {
  double value = std::numeric_limits<double>::quiet_NaN();
  // Absolute: the method's error estimate plus the rounding of its sum (4ε·scale), so that a
  // reference whose levels agree to the last bit still states the rounding it carries.
  double uncertainty = std::numeric_limits<double>::quiet_NaN();
  std::string method;  // "tanh-sinh (Boost.Math)" or "Genz–Malik h-adaptive cubature"
  double relative_tolerance = std::numeric_limits<double>::quiet_NaN();  // the target asked for
  std::uint64_t evaluations = 0;
  bool converged = false;  // the method reached its tolerance within its budget

  // "tanh-sinh (Boost.Math), relative tolerance 1e-12, 147 evaluations, uncertainty 2.1e-16".
  std::string describe() const;
};

// ∫ f over f.info().domain: tanh-sinh in s = 1 (endpoint singularities included), Genz–Malik
// h-adaptive cubature for 2 ≤ s ≤ max_computed_reference_dimension. Throws invalid_argument for a
// larger s or a domain that is not a finite box, non_finite_value if f returns NaN/±inf.
computed_reference compute_reference(const any_integrand& f);

}  // namespace quadmc
