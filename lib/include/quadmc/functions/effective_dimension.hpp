// The effective dimensions of an integrand: how many of its coordinates, and interactions of how
// many coordinates, carry its variance (docs/theory.md#effective-dimension, after
// [Caflisch, Morokoff & Owen 1997]). They explain why quasi-Monte Carlo beats Monte Carlo in
// hundreds of dimensions on one integrand and not on another of the same s.
//
// With the ANOVA decomposition f = Σ_u f_u over subsets u of {1, …, s} and σ²_u = Var f_u, so
// that σ² = Var f = Σ_{u≠∅} σ²_u:
//  - the truncation dimension d_T is the smallest d with Σ_{∅≠u⊆{1..d}} σ²_u ≥ q·σ²;
//  - the superposition dimension d_S the smallest d with Σ_{0<|u|≤d} σ²_u ≥ q·σ²;
// q = 0.99 unless asked otherwise.
//
// Use exact_effective_dimensions on a family whose info() gives its separable_moments
// (integrand.hpp): f = Re[c·Π_j g_j(x_j)], where every σ²_u has a closed form in the factors'
// moments. Other integrands get nullopt: they need an estimate.
#pragma once

#include "quadmc/functions/integrand.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace quadmc {

struct effective_dimensions {
  double share = 0.99;            // q
  std::size_t truncation = 0;     // d_T
  std::size_t superposition = 0;  // d_S
  double variance = 0.0;          // σ² = Var f
  // Σ_{∅≠u⊆{1..d}} σ²_u / σ² at d = 1 … s (the last is 1), and Σ_{0<|u|≤k} σ²_u / σ² at
  // k = 1 … s: the curves d_T and d_S are read from.
  std::vector<double> truncation_shares;
  std::vector<double> superposition_shares;
};

// The exact effective dimensions of f = Re[c·Π_j g_j(x_j)] from its factors' moments
// (docs/theory.md#effective-dimension has the formulas). nullopt when f has no variance, a factor
// has mean 0 (the normalised form divides by it) or a moment is not finite; throws
// invalid_argument for a share outside (0, 1].
std::optional<effective_dimensions> exact_effective_dimensions(const separable_moments& f,
                                                               double share = 0.99);

}  // namespace quadmc
