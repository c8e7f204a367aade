// The extensible rank-1 lattice in radical-inverse order: point q is x_q = φ({ψ(q)·z + Δ}),
// ψ(q) = Σ_k q_k 2^(−k−1) the van der Corput radical inverse of q in base 2, with the generating
// vector z and the shift Δ of rank1_lattice_points ([Hickernell & Niederreiter 2003];
// docs/theory.md#stopping-rules).
//
// Use it where N grows by doubling and the points already spent must be kept (the stopping rules
// of estimators/stopping_rules.hpp): for every m, points 0 … 2^m − 1 are exactly the 2^m-point
// lattice of rank1_lattice_points (ψ(q) for q < 2^m runs over the multiples of 2^−m), and points
// 2^m … 2^(m+1) − 1 are the ones the 2^(m+1)-point lattice adds, so a doubling costs only the new
// half. The order is the bit-reversed order of the lattice's own index, which is the input order
// of the decimation-in-time FFT that the guaranteed lattice rule runs on the values. Not for a
// fixed N (rank1_lattice_points gives the same points in index order, with a vector kernel).
//
// A point is a pure function of (s, seed, stream, q): batches may run in any order on any thread.
// The shift is uniform number j of random_stream(seed, stream), as rank1_lattice_points draws it,
// so both sets of one stream share Δ.
#pragma once

#include "quadmc/core/rng.hpp"
#include "quadmc/sampling/point_set.hpp"
#include "quadmc/sampling/rank1_lattice_points.hpp"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace quadmc {

// The radical inverse of the 32-bit index q as a 32-digit binary fraction (bits reversed).
inline std::uint32_t radical_inverse_bits(std::uint32_t q) noexcept {
  q = ((q >> 1) & 0x55555555U) | ((q & 0x55555555U) << 1);
  q = ((q >> 2) & 0x33333333U) | ((q & 0x33333333U) << 2);
  q = ((q >> 4) & 0x0F0F0F0FU) | ((q & 0x0F0F0F0FU) << 4);
  q = ((q >> 8) & 0x00FF00FFU) | ((q & 0x00FF00FFU) << 8);
  return (q >> 16) | (q << 16);
}

template <class Periodization>
class rank1_lattice_sequence {
 public:
  // n: the points it may be asked for (a power of two ≤ 2^20, the generating vector's range).
  rank1_lattice_sequence(std::size_t dimension, std::uint64_t n, std::uint64_t seed,
                         std::uint64_t stream, bool shifted = true,
                         rng_kind rng = rng_kind::philox4x32_10)
      : s_(require_lattice_size(dimension, n)), n_(n), shift_(dimension, 0.0), z_(dimension) {
    const auto z = lattice_generating_vector();
    for (std::size_t j = 0; j < s_; ++j) z_[j] = z[j];
    if (shifted) random_stream(seed, stream, rng).fill_uniform(0, shift_);
  }

  std::uint64_t size() const noexcept { return n_; }
  std::size_t dimension() const noexcept { return s_; }
  variance_structure variance() const noexcept { return {variance_kind::not_estimable, 1}; }

  void generate(std::uint64_t first, std::span<double> out) const {
    require_batch(s_, n_, first, out);
    const std::uint64_t count = out.size() / s_;
    constexpr double inv_2_32 = 0x1p-32;
    const Periodization periodize;
    for (std::uint64_t p = 0; p < count; ++p) {
      const std::uint32_t psi = radical_inverse_bits(static_cast<std::uint32_t>(first + p));
      for (std::size_t j = 0; j < s_; ++j) {
        // ψ(q)·z_j mod 1 as 32-bit integer arithmetic: exact, since ψ(q) has at most 32 digits.
        const std::uint32_t k = psi * z_[j];
        double x = static_cast<double>(k) * inv_2_32 + shift_[j];  // k/2^32 exact; x < 2
        x = x >= 1.0 ? x - 1.0 : x;                                // exact (Sterbenz)
        out[p * s_ + j] = periodize(x);
      }
    }
  }

 private:
  std::size_t s_;
  std::uint64_t n_;
  std::vector<double> shift_;
  std::vector<std::uint32_t> z_;
};

}  // namespace quadmc
