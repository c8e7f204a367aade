// The parts of the Genz families (genz.hpp) that run in 50-digit arithmetic: compiled here once,
// so that the many files that include genz.hpp neither parse Boost.Multiprecision nor generate its
// arithmetic again (docs/design.md#build-time).
#include "quadmc/functions/genz.hpp"

#include "quadmc/functions/inclusion_exclusion.hpp"

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <utility>

namespace quadmc {

namespace detail {

double scaled_product(std::span<const double> factors) {
  double product = 1.0;
  for (double f : factors) product *= f;
  if (std::isnormal(product)) return product;
  wide_float wide = 1;
  for (double f : factors) wide *= f;
  return static_cast<double>(wide);
}

}  // namespace detail

std::pair<double, double> genz_corner_peak::closed_form(std::span<const double> a) {
  const std::size_t s = a.size();
  const wide_float eps = std::numeric_limits<wide_float>::epsilon();
  // g(t) = 1/(1 + t) after s integrations; |Δg| ≤ g²·|Δt| plus one rounding of the division.
  const vertex_sum sum = alternating_vertex_sum(a, [&](const wide_float& t, const wide_float& dt) {
    wide_float g = 1 / (1 + t);
    wide_float error = g * g * dt + eps * g;
    return std::pair{std::move(g), std::move(error)};
  });
  wide_float denominator = 1;
  for (std::size_t j = 0; j < s; ++j) denominator *= static_cast<double>(j + 1) * a[j];
  // + 2s·ε for the s!·Π aᵢ divisor.
  const wide_float relative =
      sum.error_bound / boost::multiprecision::abs(sum.value) + 2 * static_cast<double>(s) * eps;
  return {static_cast<double>(sum.value / denominator), static_cast<double>(relative)};
}

}  // namespace quadmc
