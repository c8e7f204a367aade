// The partner offsets a_k of pmj02_points.hpp, solved once from the first two Sobol' generator
// matrices (sobol_matrices: the identity and Pascal's matrix mod 2, a (0,2)-sequence in base 2).
#include "quadmc/sampling/pmj02_points.hpp"

#include "quadmc/sampling/sobol_points.hpp"

namespace quadmc {

namespace {

// a_k with C_k·a_k = the first k digits of column k, by back substitution: column b of a Sobol'
// matrix has digits 1 … b + 1 only, digit b + 1 set (m_b is odd: sobol_matrices.cpp), so digit
// b + 1 of the remainder decides bit b of a_k once the columns above b are taken, from b = k − 1
// down to 0. The remainder ends at 0 because C_k is invertible (unit upper triangular).
std::array<std::uint32_t, 32> offsets_of(std::span<const std::uint32_t, 32> columns) {
  std::array<std::uint32_t, 32> a{};
  for (unsigned k = 1; k < 32; ++k) {
    // First k digits as a k-bit integer: digit r is bit k − r.
    const auto first_digits = [k](std::uint32_t column) { return column >> (32 - k); };
    std::uint32_t rest = first_digits(columns[k]);
    for (unsigned b = k; b-- > 0;) {
      if (((rest >> (k - 1 - b)) & 1u) != 0) {
        a[k] |= std::uint32_t{1} << b;
        rest ^= first_digits(columns[b]);
      }
    }
    require(rest == 0, "Sobol' generator matrix", k, "a unit upper triangular leading block");
  }
  return a;
}

pmj02_partners solved() {
  const sobol_matrices matrices(2);
  return {offsets_of(matrices.columns(0)), offsets_of(matrices.columns(1))};
}

}  // namespace

const pmj02_partners& pmj02_partner_offsets() {
  static const pmj02_partners partners = solved();
  return partners;
}

}  // namespace quadmc
