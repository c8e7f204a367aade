// The Black–Scholes geometric-average Asian call [Kemna & Vorst 1990], the standard option-pricing
// test of QMC in high dimension, on [0,1]^s through zᵢ = Φ⁻¹(xᵢ):
//   f(x) = e^(−rT)·max(G − K, 0),  G = (Π S(tᵢ))^(1/s),  tᵢ = iT/s, i = 1..s,
//   S(t) = S₀·exp((r − σ²/2)t + σW(t)),
// with the Brownian path W(t₁..t_s) built from z by one of three constructions
// (docs/theory.md#the-geometric-asian-option):
//   standard: cumulative sums W(tᵢ) = W(tᵢ₋₁) + √Δt·zᵢ;
//   bridge:   z₁ sets W(T), then midpoints recursively [Caflisch, Morokoff & Owen 1997];
//   pca:      W = V·Λ^(1/2)·z, the eigenvectors of the covariance min(tᵢ, tⱼ), in closed form
//             [Acworth, Broadie & Glasserman 1998].
// All three give W the same distribution, hence the same integral, the closed form of
// [Kemna & Vorst 1990]: log G is normal. They differ in how much of f's variance the first
// coordinates carry (bridge and pca put most of it in z₁), which is what QMC feels.
//
// Use it for a C0 integrand (the max has a kink across a hyperplane in z) of nominally high
// dimension whose effective dimension the construction sets. log G is linear in z, so the
// price needs only one direction; the path is built anyway, point by point, because that is the
// cost a path-dependent payoff pays: O(s) per point for standard and bridge, O(s²) for pca.
// On the faces (some xⱼ ∈ {0, 1}, a null set) zⱼ = ±∞ and f is defined as 0, as keister.hpp
// does; points outside [0,1] give NaN (check_finite_batch reports them).
#pragma once

#include "quadmc/functions/integrand.hpp"

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

enum class path_construction { standard, bridge, pca };
// The construction key's choices, in the enum's order (the catalogue lists them).
inline constexpr std::array<std::string_view, 3> path_construction_names = {"standard", "bridge",
                                                                            "pca"};

// "standard", "bridge", "pca"; parse_path_construction throws invalid_argument naming
// `construction` and the three choices for anything else.
std::string_view to_string(path_construction c) noexcept;
path_construction parse_path_construction(std::string_view text);

struct geometric_asian_parameters {
  double spot = 100.0;      // S₀ > 0
  double strike = 100.0;    // K > 0
  double rate = 0.05;       // r, finite
  double volatility = 0.2;  // σ > 0
  double maturity = 1.0;    // T > 0
  path_construction construction = path_construction::standard;
};

class geometric_asian {
 public:
  static constexpr std::size_t max_dimension = 1024;

  // Validates s (1 ≤ s ≤ 1024) and the parameters (S₀, K, σ, T > 0, r finite, and every value f
  // can take at a double finite: see the constructor); precomputes the bridge's weights or the pca
  // matrix (s² doubles: 8 MB at s = 1024). lib/src/functions/geometric_asian.cpp.
  geometric_asian(std::size_t s, const geometric_asian_parameters& p);

  std::size_t dimension() const noexcept { return s_; }
  // x row-major, x[i·s + j]; no allocation (the path lives in two stack buffers of 8 KB).
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept;
  integrand_info info() const;

  // W(t₁..t_s) from the standard normals z (both of length s) by the chosen construction; for
  // the tests, which check that every construction reproduces the covariance min(tᵢ, tⱼ).
  void path(std::span<const double> z, std::span<double> w) const noexcept;

  // The closed form [Kemna & Vorst 1990]: log G ~ N(μ, v) with
  //   μ = log S₀ + (r − σ²/2)·T(s+1)/(2s),  v = σ²·T(s+1)(2s+1)/(6s²),
  // price = e^(−rT)·(e^(μ+v/2)·Φ(d₁) − K·Φ(d₂)), d₂ = (μ − log K)/√v, d₁ = d₂ + √v.
  static double exact_value(std::size_t s, const geometric_asian_parameters& p);

  const geometric_asian_parameters& parameters() const noexcept { return p_; }

 private:
  // One step of the bridge: W[index] from W[left], W[right] (index s stands for W(0) = 0) and the
  // next z, in the order the z are consumed.
  struct bridge_step {
    std::size_t left, right, index;
    double left_weight, right_weight, sd;
  };

  std::size_t s_;
  geometric_asian_parameters p_;
  double sqrt_dt_;    // √(T/s)
  double log_drift_;  // log S₀ + (r − σ²/2)·T(s+1)/(2s): the mean of log G
  double discount_;   // e^(−rT)
  double exact_;
  std::vector<bridge_step> bridge_;  // s − 1 steps after W(T) (bridge only)
  std::vector<double> pca_;          // s×s, row i: W(tᵢ) = Σₖ pca_[i·s + k]·zₖ (pca only)
};

}  // namespace quadmc
