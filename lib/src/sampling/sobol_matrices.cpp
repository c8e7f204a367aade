// The Sobol' generator matrices of sobol_points.hpp, built from Boost's table of primitive
// polynomials and initial direction numbers ([Joe & Kuo 2008], new-joe-kuo-6.21201).
#include "quadmc/sampling/sobol_points.hpp"

#include <boost/random/detail/sobol_table.hpp>

#include <array>
#include <bit>

namespace quadmc {

namespace {
using table = boost::random::detail::qrng_tables::sobol;
static_assert(table::max_dimension == sobol_matrices::max_dimension,
              "sobol_matrices::max_dimension must be the dimension of Boost's table");
}  // namespace

sobol_matrices::sobol_matrices(std::size_t dimension) : columns_(dimension * digits) {
  require(dimension >= 1 && dimension <= max_dimension, "dimension s", dimension,
          "1 ≤ s ≤ 3667 (the dimensions of Boost's Sobol' table)");
  std::array<std::uint64_t, digits> m{};
  for (std::size_t j = 0; j < dimension; ++j) {
    if (j == 0) {
      m.fill(1);  // van der Corput: v_k = 2^-(k+1), the identity matrix
    } else {
      // Primitive polynomial x^d + a_1 x^(d−1) + … + a_(d−1) x + 1, bit k of `poly` the
      // coefficient of x^k; initial m_0 … m_(d−1) from the table; then
      //   m_k = m_(k−d) ⊕ Σ_(i=1…d) a_i 2^i m_(k−i),  a_d = 1   ([Joe & Kuo 2008, eq. 3]).
      const unsigned poly = table::polynomial(j - 1);
      const auto degree = static_cast<unsigned>(std::bit_width(poly) - 1);
      for (unsigned k = 0; k < degree && k < digits; ++k) m[k] = table::minit(j - 1, k);
      for (unsigned k = degree; k < digits; ++k) {
        std::uint64_t value = m[k - degree];
        for (unsigned i = 1; i <= degree; ++i) {
          // a_i is the coefficient of x^(d−i).
          if (((poly >> (degree - i)) & 1u) != 0) value ^= m[k - i] << i;
        }
        m[k] = value;
      }
    }
    // v_k = m_k / 2^(k+1): as a 32-digit fraction, m_k shifted to end at digit k + 1.
    for (unsigned k = 0; k < digits; ++k) {
      columns_[j * digits + k] = static_cast<std::uint32_t>(m[k] << (digits - 1 - k));
    }
  }
}

}  // namespace quadmc
