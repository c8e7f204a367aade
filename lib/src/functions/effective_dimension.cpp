// exact_effective_dimensions (functions/effective_dimension.hpp). The formulas, derived in
// docs/theory.md#effective-dimension: for f = Re[c·P], P = Π_j h_j with μ_j = E h_j,
// v_j = E|h_j|² − |μ_j|² and w_j = E h_j² − μ_j²,
//   σ²_u = ½|c|²·Π_{j∈u} v_j·Π_{j∉u} |μ_j|² + ½ Re[c²·Π_{j∈u} w_j·Π_{j∉u} μ_j²].
// Divided by N = ½|c|²·Π|μ_j|²·Π(1 + r_j), r_j = v_j/|μ_j|², every term is a product of numbers in
// [0, 1] (p_j = 1/(1 + r_j), a_j = r_j·p_j, b_j = (w_j/μ_j²)·p_j with |b_j| ≤ a_j, since
// |E(h − μ)²| ≤ E|h − μ|²), so that s = 1024 factors neither overflow nor underflow into wrong
// shares:
//   σ²_u/N = Π_{j∈u} a_j·Π_{j∉u} p_j + Re[e^{iθ}·Π_{j∈u} b_j·Π_{j∉u} p_j],
// e^{iθ} = (c/|c|)²·Π(μ_j/|μ_j|)². The superposition sums are the coefficients of t^k in
// Π(p_j + t·a_j) and Π(p_j + t·b_j), O(s²) by one multiplication per factor; the truncation sums
// have the closed form Π_{j>d} p_j·[(1 − Π_{j≤d} p_j) + Re(e^{iθ}·Π_{j≤d} p_j·(Π_{j≤d}(1 + ρ_j) −
// 1))] with ρ_j = w_j/μ_j², computed through log1p and expm1 so that a nearly constant factor (r_j
// ≈ 1e-12) loses no digits to 1 − (1 − r_j).
#include "quadmc/functions/effective_dimension.hpp"

#include "quadmc/core/errors.hpp"

#include <cmath>
#include <complex>
#include <cstddef>
#include <optional>
#include <vector>

namespace quadmc {

namespace {

using complex = std::complex<double>;

// log(1 + z) without the cancellation of log(1 + z) at small |z|: log|1 + z| = ½·log1p(2x + |z|²).
complex log1p(complex z) {
  const double x = z.real(), y = z.imag();
  return {0.5 * std::log1p(2.0 * x + x * x + y * y), std::atan2(y, 1.0 + x)};
}

// e^z − 1 = 2·e^{z/2}·sinh(z/2), accurate at small |z|.
complex expm1(complex z) {
  return 2.0 * std::exp(0.5 * z) * std::sinh(0.5 * z);
}

// The first d for which shares[d − 1] reaches q (shares rise to 1; the last one is 1 by
// construction, so one is always found). The tolerance lets a share that is q in exact arithmetic
// count although rounding left it an ulp below.
std::size_t first_reaching(const std::vector<double>& shares, double q) {
  for (std::size_t d = 0; d < shares.size(); ++d) {
    if (shares[d] >= q - 1e-12) return d + 1;
  }
  return shares.size();
}

}  // namespace

std::optional<effective_dimensions> exact_effective_dimensions(const separable_moments& f,
                                                               double share) {
  require(share > 0.0 && share <= 1.0, "share", share, "a fraction of the variance in (0, 1]");
  const std::size_t s = f.factors.size();
  if (s == 0 || f.scale == 0.0 || !std::isfinite(std::abs(f.scale))) return std::nullopt;
  std::vector<double> r(s), p(s), a(s);
  std::vector<complex> rho(s), b(s);
  complex phase = (f.scale / std::abs(f.scale)) * (f.scale / std::abs(f.scale));
  double log_scale = std::log(0.5 * std::norm(f.scale));  // log N, summed below
  for (std::size_t j = 0; j < s; ++j) {
    const factor_moments& m = f.factors[j];
    const double mean_norm = std::norm(m.mean);
    if (!(mean_norm > 0.0) || !std::isfinite(mean_norm) || !std::isfinite(m.mean_abs_square) ||
        !std::isfinite(m.mean_square.real()) || !std::isfinite(m.mean_square.imag())) {
      return std::nullopt;
    }
    // v ≥ 0 in exact arithmetic; a rounding-negative v of a constant factor is 0.
    r[j] = std::max(0.0, m.mean_abs_square - mean_norm) / mean_norm;
    rho[j] = (m.mean_square - m.mean * m.mean) / (m.mean * m.mean);
    if (std::abs(rho[j]) > r[j]) rho[j] *= r[j] / std::abs(rho[j]);  // |ρ| ≤ r, up to rounding
    p[j] = 1.0 / (1.0 + r[j]);
    a[j] = r[j] * p[j];
    b[j] = rho[j] * p[j];
    const complex unit = m.mean / std::sqrt(mean_norm);
    phase *= unit * unit;
    log_scale += std::log(mean_norm) + std::log1p(r[j]);
  }

  // Superposition: the coefficients of Π(p_j + t·a_j) and Π(p_j + t·b_j), one factor at a time.
  std::vector<double> real_coefficients(s + 1, 0.0);
  std::vector<complex> complex_coefficients(s + 1, 0.0);
  real_coefficients[0] = 1.0;
  complex_coefficients[0] = 1.0;
  for (std::size_t j = 0; j < s; ++j) {
    for (std::size_t k = j + 1; k >= 1; --k) {
      real_coefficients[k] = real_coefficients[k] * p[j] + real_coefficients[k - 1] * a[j];
      complex_coefficients[k] = complex_coefficients[k] * p[j] + complex_coefficients[k - 1] * b[j];
    }
    real_coefficients[0] *= p[j];
    complex_coefficients[0] *= p[j];
  }
  std::vector<double> by_order(s);  // Σ_{|u|=k} σ²_u / N, k = 1 … s
  for (std::size_t k = 1; k <= s; ++k) {
    by_order[k - 1] = real_coefficients[k] + (phase * complex_coefficients[k]).real();
  }
  double total = 0.0;
  for (const double v : by_order) total += v;

  // Truncation: T(d)/N = Π_{j>d} p_j·[(1 − Π_{j≤d} p_j) + Re(e^{iθ}·Π_{j≤d} p_j·expm1(Σ_{j≤d}
  // log(1 + ρ_j)))], with Π_{j≤d} p_j = e^{−L(d)}, L(d) = Σ_{j≤d} log1p(r_j).
  std::vector<double> log_tail(s + 1, 0.0);  // Σ_{j>d} log p_j = −(L(s) − L(d))
  for (std::size_t j = s; j-- > 0;) log_tail[j] = log_tail[j + 1] - std::log1p(r[j]);
  std::vector<double> truncated(s);
  double L = 0.0;
  complex Lambda = 0.0;
  for (std::size_t d = 1; d <= s; ++d) {
    L += std::log1p(r[d - 1]);
    Lambda += log1p(rho[d - 1]);
    const double tail = std::exp(log_tail[d]);
    const double real_part = -std::expm1(-L);
    const complex complex_part = std::exp(-L) * expm1(Lambda);
    truncated[d - 1] = tail * (real_part + (phase * complex_part).real());
  }

  if (!(total > 0.0) || !std::isfinite(total)) return std::nullopt;
  effective_dimensions out;
  out.share = share;
  out.variance = std::exp(log_scale) * total;
  double running = 0.0;
  for (std::size_t k = 0; k < s; ++k) {
    running += by_order[k];
    out.superposition_shares.push_back(std::min(1.0, running / total));
  }
  out.superposition_shares.back() = 1.0;
  for (std::size_t d = 0; d < s; ++d) {
    out.truncation_shares.push_back(std::min(1.0, truncated[d] / truncated[s - 1]));
  }
  out.truncation_shares.back() = 1.0;
  out.truncation = first_reaching(out.truncation_shares, share);
  out.superposition = first_reaching(out.superposition_shares, share);
  return out;
}

}  // namespace quadmc
