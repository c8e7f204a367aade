// Rank-1 lattice points with a random shift ([Cranley & Patterson 1976]), optionally
// periodized by the baker's (tent) transform ([Hickernell 2002]): x_i = φ({i·z/N + Δ}),
// i = 0 … N − 1, with the generating vector z of the embedded lattice rules of
// [Cools, Kuo & Nuyens 2006] as Debian's QuantLib ships them (ql/math/randomnumbers/
// latticerules.hpp, rule D: 3600 dimensions, built for N = 2^10 … 2^20).
//
// Use it for smooth integrands: a randomly shifted lattice has RMSE O(N^(−1+ε)) for f with
// square-integrable mixed first derivatives, and with the baker's transform O(N^(−2+ε)) for f with
// square-integrable mixed second derivatives — no periodic f needed ([Hickernell 2002];
// [Dick, Nuyens & Pillichshammer 2014]; docs/theory.md#lattice-rules). Not for N other than 2^m
// (the vector is embedded for powers of two: its components are odd, hence units modulo 2^m) nor
// above 2^20, nor for discontinuous f (no rate is known there). Below N = 2^10 the same vector
// gives a valid lattice, not one that was optimised for that N.
//
// Why these vectors: they come from a real source (not typed in), cover 3600 dimensions, and one
// vector serves the whole 2^10 … 2^20 ladder (an embedded sequence), so a convergence ladder
// measures one construction, not a different one per N. QuantLib ships four such vectors (A–D,
// undocumented weights); D has the smallest Korobov criteria P_1 and P_2 (weights j^−2) of the
// four at N = 2^16 … 2^20 in s = 8, measured when it was chosen. tests/sampling/
// rank1_lattice_points_test.cpp checks their quality: the worst-case error of the Korobov space
// with smoothness α falls at the proven rate N^(−α+ε) for α = 1 and 2.
//
// Randomness: the shift Δ_j is uniform number j of random_stream(seed, stream) (the points use no
// other), so a point is a pure function of (s, N, seed, stream, i). With `shifted = false` the
// lattice itself (Δ = 0): point 0 is the origin. All points share Δ, so one run cannot estimate
// its own error: variance() is not_estimable (docs/theory.md#replicate-error-bars).
#pragma once

#include "quadmc/core/rng.hpp"
#include "quadmc/sampling/point_set.hpp"
#include "quadmc/sampling/rank1_lattice_blocks.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace quadmc {

inline constexpr std::size_t max_lattice_dimension = 3600;
inline constexpr std::uint64_t max_lattice_points = std::uint64_t{1} << 20;

// The generating vector z_1 … z_3600 (z_1 = 1), from QuantLib's LatticeRule::getRule(D).
std::span<const std::uint32_t> lattice_generating_vector();

// The sizes the generating vector serves, for the lattice and its radical-inverse sequence alike:
// s ≤ 3600 and N = 2^m ≤ 2^20. Returns s.
inline std::size_t require_lattice_size(std::size_t s, std::uint64_t n) {
  require_point_set_size(s, n);
  require(s <= max_lattice_dimension, "dimension s", s,
          "s ≤ 3600 (the dimensions of the Cools–Kuo–Nuyens generating vector)");
  require(std::has_single_bit(n) && n <= max_lattice_points, "number of points N", n,
          "a power of two N = 2^m ≤ 2^20 (the embedded lattice rules of the generating vector)");
  return s;
}

// The lattice coordinate itself.
struct no_periodization {
  static constexpr detail::lattice_periodization kind = detail::lattice_periodization::none;
  double operator()(double x) const noexcept { return x; }
};
// The baker's transform φ(x) = 1 − |2x − 1|: ∫f(φ(x))dx = ∫f, and f∘φ is periodic (it has equal
// values at 0 and 1), which lets the lattice rule gain an order on non-periodic f
// ([Hickernell 2002]).
struct baker_transform {
  static constexpr detail::lattice_periodization kind = detail::lattice_periodization::baker;
  double operator()(double x) const noexcept {
    return std::min(1.0 - std::abs(2.0 * x - 1.0), largest_below_one);
  }
};

template <class Periodization>
class rank1_lattice_points {
 public:
  rank1_lattice_points(std::size_t dimension, std::uint64_t n, std::uint64_t seed,
                       std::uint64_t stream, bool shifted = true,
                       rng_kind rng = rng_kind::philox4x32_10)
      : s_(require_lattice_size(dimension, n)), n_(n), shift_(dimension, 0.0), z_(dimension) {
    const auto z = lattice_generating_vector();
    for (std::size_t j = 0; j < s_; ++j) z_[j] = z[j] & (n_ - 1);
    if (shifted) random_stream(seed, stream, rng).fill_uniform(0, shift_);
    blocks_ = detail::make_rank1_lattice_block_tables(z_, shift_, n_, Periodization::kind);
  }

  std::uint64_t size() const noexcept { return n_; }
  std::size_t dimension() const noexcept { return s_; }
  variance_structure variance() const noexcept { return {variance_kind::not_estimable, 1}; }

  // Whole blocks of the vector kernel where the CPU has one (sampling/rank1_lattice_blocks.hpp),
  // the remaining points by the scalar loop; both give the same bits.
  void generate(std::uint64_t first, std::span<double> out) const {
    require_batch(s_, n_, first, out);
    const std::uint64_t count = out.size() / s_;
    const std::uint64_t blocks = count / blocks_.block;
    if (blocks > 0 && detail::rank1_lattice_blocks(blocks_, first, blocks, out.data())) {
      const std::uint64_t done = blocks * blocks_.block;
      generate_scalar(first + done, count - done, out.data() + done * s_);
      return;
    }
    generate_scalar(first, count, out.data());
  }

  // The scalar loop, one coordinate at a time: the reference the vector kernel must equal
  // bitwise (tests), and the path of CPUs without one.
  void generate_reference(std::uint64_t first, std::span<double> out) const {
    require_batch(s_, n_, first, out);
    generate_scalar(first, out.size() / s_, out.data());
  }

 private:
  void generate_scalar(std::uint64_t first, std::uint64_t count, double* out) const {
    const std::uint64_t mask = n_ - 1;
    const double inv_n = 1.0 / static_cast<double>(n_);  // exact: N = 2^m
    const Periodization periodize;
    for (std::size_t j = 0; j < s_; ++j) {
      const std::uint64_t z = z_[j];
      const double shift = shift_[j];
      // k = i·z mod N, advanced by z per point: exact integers, one addition each.
      std::uint64_t k = (first * z) & mask;
      for (std::uint64_t p = 0; p < count; ++p) {
        double x = static_cast<double>(k) * inv_n + shift;  // k/N exact; x < 2
        x = x >= 1.0 ? x - 1.0 : x;                         // exact (Sterbenz)
        out[p * s_ + j] = periodize(x);
        k = (k + z) & mask;
      }
    }
  }

  std::size_t s_;
  std::uint64_t n_;
  std::vector<double> shift_;
  std::vector<std::uint64_t> z_;
  detail::rank1_lattice_block_tables blocks_;  // the vector kernel's tables
};

}  // namespace quadmc
