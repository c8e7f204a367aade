// Keister's integrand (B. D. Keister, "Multidimensional quadrature algorithms", Computers in
// Physics 10(2), 1996): I_s = ∫_{ℝ^s} cos(‖t‖) e^{−‖t‖²} dt, written on [0,1]^s as in QMCPy:
//   t = z/√2, z = Φ⁻¹(x) coordinate-wise  ⇒  I_s = π^{s/2} E[cos(‖Z‖/√2)],
//   f(x) = π^{s/2} cos(‖Φ⁻¹(x)‖/√2).
// Exact value from the radial form: I_s = |S^{s−1}| ∫₀^∞ cos(r) e^{−r²} r^{s−1} dr with
// |S^{s−1}| = 2π^{s/2}/Γ(s/2), the 1D integral by adaptive Gauss–Kronrod (61 points, Boost.Math)
// at construction. (Closed form for checking: ∫₀^∞ r^{s−1}e^{−r²}cos r dr = ½Γ(s/2)·₁F₁(s/2; ½;
// −¼); s = 1 gives √π·e^{−1/4}.)
//
// Use it as the standard "physics" QMC test in moderate dimension. Not for s > 20 (rejected:
// the radial integrand's cancellation grows with s and the reference was verified only to 20).
// Regularity: analytic inside the cube, but its derivatives are unbounded towards the faces
// (Φ⁻¹ → ±∞), hence smoothness::singular. On the faces themselves (some xⱼ ∈ {0, 1}, a null
// set) ‖Φ⁻¹(x)‖ = ∞ and cos has no limit: f is defined as 0 there, so a rule with end-point
// nodes gets a finite value. Points outside [0,1] give NaN (check_finite_batch reports them).
#pragma once

#include "quadmc/functions/integrand.hpp"

#include <boost/math/policies/policy.hpp>
#include <boost/math/special_functions/erf.hpp>

#include <cmath>
#include <cstddef>
#include <span>

namespace quadmc {

class keister {
 public:
  static constexpr std::size_t max_dimension = 20;

  explicit keister(std::size_t s);  // computes the reference (lib/src/functions/keister.cpp)

  std::size_t dimension() const noexcept { return s_; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    using namespace boost::math::policies;
    // erfc_inv(0) and erfc_inv(2) return ±∞ instead of throwing; outside [0, 2] it returns NaN.
    using quiet = policy<overflow_error<ignore_error>, domain_error<ignore_error>>;
    for (std::size_t i = 0; i < y.size(); ++i) {
      double r2 = 0.0;
      for (std::size_t j = 0; j < s_; ++j) {
        // Φ⁻¹(p) = −√2·erfc⁻¹(2p), so z²/2 = erfc⁻¹(2p)²: ‖Z‖/√2 = √(Σ erfc⁻¹(2xⱼ)²).
        const double e = boost::math::erfc_inv(2.0 * x[i * s_ + j], quiet());
        r2 += e * e;
      }
      y[i] = std::isinf(r2) ? 0.0 : scale_ * std::cos(std::sqrt(r2));
    }
  }
  integrand_info info() const;

  // I_s by the radial Gauss–Kronrod integral, with Boost's error estimate (absolute).
  static double exact_value(std::size_t s, double* error_estimate = nullptr);

 private:
  std::size_t s_;
  double scale_;  // π^{s/2}
  double exact_, error_estimate_;
};

}  // namespace quadmc
