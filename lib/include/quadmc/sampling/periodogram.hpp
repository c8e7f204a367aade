// The radially averaged periodogram of 2D point sets: the power spectrum by which sampling
// patterns are compared in rendering ([Pilleboue et al. 2015]; [Pharr et al. 2016, §7.1]).
//
// Use it to see how a 2D point set distributes its energy over frequencies: flat (white noise)
// for independent points, low power near the origin (blue noise) for stratified points, spikes
// for a grid. Average it over many independent realizations (add() once per realization): one
// realization's periodogram fluctuates by 100 % at every frequency. Not for s ≠ 2 and not a
// discrepancy (sampling/discrepancy.hpp puts one number on uniformity).
//
// Definition: for N points x_j in [0,1)² and an integer frequency f ∈ Z² (the unit square's
// Fourier series, so the torus [0,1)² has no leakage between frequencies),
//   P(f) = |Σ_j exp(−2πi f·x_j)|² / N.
// For N independent uniform points and f ≠ 0, E[P(f)] = 1 and Var[P(f)] = 1 − 1/N, and P(f),
// P(f') are uncorrelated unless f' = ±f (the fourth moments of Σ_j exp(−2πi f·x_j) pair up only
// when f ± f' = 0). Since P(−f) = P(f), each bin holds the frequencies of one half plane
// (f₁ > 0, or f₁ = 0 and f₂ > 0): bin r = 1, 2, …, R holds the f with round(|f|) = r, i.e. the
// integers r² − r + 1 ≤ |f|² ≤ r² + r. The radial average of a bin is the mean of P over its
// frequencies and over the realizations; its standard error is the standard deviation of the
// per-realization bin means over √R.
//
// Cost per realization: one sine and cosine per point and frequency component, then one complex
// multiply-add per point and frequency, O(N·R_max²) (N = 1024, R_max = 64: about 7·10⁶).
#pragma once

#include "quadmc/core/welford.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace quadmc {

struct radial_power_bin {
  std::size_t radius = 0;         // r: the frequencies with round(|f|) = r
  std::uint64_t frequencies = 0;  // in the half plane (P(−f) = P(f) counted once)
  double mean_power = 0.0;        // over the bin's frequencies and the realizations
  double standard_error = 0.0;    // of mean_power, from the spread of the realizations
};

// The number of frequencies of the half plane with r² − r + 1 ≤ |f|² ≤ r² + r.
std::uint64_t half_plane_frequencies(std::size_t radius);

class radial_periodogram {
 public:
  // Bins r = 1 … max_radius (max_radius ≥ 1, ≤ 4096).
  explicit radial_periodogram(std::size_t max_radius);

  // One realization: N = points.size()/2 points row-major (x, y), every coordinate finite.
  // Throws invalid_argument for an odd size or no point.
  void add(std::span<const double> points);

  std::size_t max_radius() const noexcept { return max_radius_; }
  std::uint64_t realizations() const noexcept { return realizations_; }
  // The bins r = 1 … max_radius; the standard error is NaN with fewer than two realizations.
  std::vector<radial_power_bin> bins() const;

 private:
  std::size_t max_radius_;
  std::uint64_t realizations_ = 0;
  std::vector<welford> bin_means_;  // per bin, over the realizations
};

}  // namespace quadmc
