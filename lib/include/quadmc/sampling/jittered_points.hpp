// Jittered (stratified) points: k^s equal strata, m uniform points in each
// ([Pharr et al. 2016, §7.3], the StratifiedSampler with jitter; [Ramamoorthi 2009, §4.2] with
// nᵢ = vᵢN).
//
// Use it for smooth integrands in low dimension: the RMSE falls as N^(−1/2−1/s), N^(−1/2−1/(2s))
// for an indicator of a smooth region (docs/theory.md#jittered-variance; [Mitchell 1996],
// [Pilleboue et al. 2015]), and the variance never exceeds plain Monte Carlo's:
// (1/N)Σvᵢσᵢ² ≤ (1/N)[Σvᵢσᵢ² + Σvᵢ(μᵢ−I)²] (docs/theory.md#stratified-vs-random).
// Not for high s: N must be m·k^s (the curse of dimensionality, [Pharr et al. 2016, §7.3]) — use
// padded jittered or Latin hypercube points there. N that is not k^s is rejected (see
// stratum_grid.hpp).
//
// Layout: point i lies in stratum i / m (row-major, last axis fastest), so points of one stratum
// are consecutive and an estimator sees them together. Coordinate j is (cell_j + u)/k with u
// uniform number i·s + j of the stream.
//
// Error estimate (variance()): with m ≥ 2 points per stratum, the stratified estimator's own
// Σ vᵢ²σ̂ᵢ²/nᵢ; with m = 1 the per-stratum variance cannot be estimated, and second differences
// of neighbouring strata along the last axis are used (variance_kind::stratum_differences); for
// k < 3 there is no such triple and std_error is NaN.
#pragma once

#include "quadmc/core/rng.hpp"
#include "quadmc/sampling/point_set.hpp"
#include "quadmc/sampling/stratum_grid.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace quadmc {

namespace detail {

// Largest s that detail::jittered_rows places (a kernel is compiled for each s up to it).
inline constexpr std::size_t jittered_rows_max_dimension = 8;

// Places `count` points of a jittered set with one point per stratum, in place: x holds their
// count·s uniforms (row-major), the first point lies in the stratum with cell coordinates
// cell[0..s) (integers as doubles), the next ones follow row-major (last axis fastest, wrapping
// at k strata per axis), and coordinate j becomes min((cell_j + u)·inv_k, largest_below_one).
// 1 ≤ s ≤ jittered_rows_max_dimension. At the active SIMD level (core/simd_level.hpp), bitwise
// the same at every level: lib/src/sampling/jittered_rows*.cpp.
void jittered_rows(std::size_t s, double k, double inv_k, const double* cell, double* x,
                   std::size_t count) noexcept;

}  // namespace detail

class jittered_points {
 public:
  // N = k^s points, one per stratum; rejects other N with the nearest valid sizes.
  jittered_points(std::size_t dimension, std::uint64_t n, std::uint64_t seed, std::uint64_t stream,
                  rng_kind rng = rng_kind::philox4x32_10)
      : jittered_points(stratum_grid::for_size(dimension, n), 1, seed, stream, rng) {}

  // k^s strata with m points each (the stratified estimator, nᵢ = m for all i).
  jittered_points(stratum_grid grid, std::uint64_t points_per_stratum, std::uint64_t seed,
                  std::uint64_t stream, rng_kind rng = rng_kind::philox4x32_10)
      : grid_(grid), m_(points_per_stratum), rng_(seed, stream, rng) {
    require(m_ >= 1, "points per stratum m", m_, "m ≥ 1");
    require(grid_.strata() <= (std::uint64_t{1} << 62) / m_, "points per stratum m", m_,
            "m·k^s ≤ 2^62");
    n_ = grid_.strata() * m_;
    require_point_set_size(grid_.dimension(), n_);
  }

  std::uint64_t size() const noexcept { return n_; }
  std::size_t dimension() const noexcept { return grid_.dimension(); }
  const stratum_grid& grid() const noexcept { return grid_; }
  std::uint64_t points_per_stratum() const noexcept { return m_; }
  variance_structure variance() const noexcept {
    if (m_ >= 2) return {variance_kind::within_strata, m_};
    return {variance_kind::stratum_differences, grid_.per_axis()};
  }

  void generate(std::uint64_t first, std::span<double> out) const {
    const std::size_t s = grid_.dimension();
    require_batch(s, n_, first, out);
    rng_.fill_uniform(first * s, out);  // the jitters, then shifted into their cells in place
    const double inv_k = 1.0 / static_cast<double>(grid_.per_axis());
    std::array<std::uint64_t, 16> small{};
    std::vector<std::uint64_t> large(s > small.size() ? s : 0);
    std::span<std::uint64_t> cell = s > small.size() ? std::span<std::uint64_t>(large)
                                                     : std::span<std::uint64_t>(small).first(s);
    const std::uint64_t count = out.size() / s;
    const std::uint64_t k = grid_.per_axis();
    grid_.cell(first / m_, cell);
    // The last axis moves fastest: its coordinate lives in a register, as a double (exact: cell
    // coordinates are integers < 2^53), so no integer conversion or division is paid per point;
    // only its wrap-around touches the other axes (a counter kept in memory would chain every
    // point through a store-to-load forward).
    std::array<double, 16> small_leading{};
    std::vector<double> large_leading(s > small_leading.size() ? s : 0);
    const std::span<double> leading = s > small_leading.size()
                                          ? std::span<double>(large_leading)
                                          : std::span<double>(small_leading).first(s);
    for (std::size_t j = 0; j + 1 < s; ++j) leading[j] = static_cast<double>(cell[j]);
    const double k_double = static_cast<double>(k);
    double last = static_cast<double>(cell[s - 1]);
    std::uint64_t in_stratum = first % m_;  // points of the current stratum already placed
    if (m_ == 1 && s <= detail::jittered_rows_max_dimension) {
      // One point per stratum, s ≤ 8 (the dimensions where N = k^s is practical): whole rows of
      // the last axis in vector registers at the active SIMD level (detail::jittered_rows), the
      // same operations on the same operands as the loops below, so the same bits at every level.
      std::array<double, detail::jittered_rows_max_dimension> offset{};
      for (std::size_t j = 0; j + 1 < s; ++j) offset[j] = leading[j];
      offset[s - 1] = last;
      detail::jittered_rows(s, k_double, inv_k, offset.data(), out.data(),
                            static_cast<std::size_t>(count));
      return;
    }
    if (m_ == 1) {
      // One point per stratum, s > 8: the batch in runs of whole rows of the last
      // axis (the points that share their leading cells). Per run, each leading coordinate is
      // shifted down its column with its cell in a register, and the last axis's cells are an
      // induction variable (c, c + 1, …) — no per-point branch. The same operations on the same
      // operands as the general loop below, so the same bits.
      for (std::uint64_t p = 0; p < count;) {
        const std::uint64_t run = std::min<std::uint64_t>(
            count - p, k - static_cast<std::uint64_t>(last));  // to the end of the row
        double* row = out.data() + p * s;
        for (std::size_t j = 0; j + 1 < s; ++j) {
          const double c = leading[j];
          for (std::uint64_t r = 0; r < run; ++r) {
            row[r * s + j] = std::min((c + row[r * s + j]) * inv_k, largest_below_one);
          }
        }
        double c = last;
        double* x_last = row + (s - 1);
        for (std::uint64_t r = 0; r < run; ++r, c += 1.0) {
          x_last[r * s] = std::min((c + x_last[r * s]) * inv_k, largest_below_one);
        }
        p += run;
        last = c;
        if (last == k_double) {
          last = 0.0;
          cell[s - 1] = k - 1;  // so that next_cell carries into the leading axes
          grid_.next_cell(cell);
          for (std::size_t j = 0; j + 1 < s; ++j) leading[j] = static_cast<double>(cell[j]);
        }
      }
      return;
    }
    for (std::uint64_t p = 0; p < count; ++p) {
      double* x = out.data() + p * s;
      for (std::size_t j = 0; j + 1 < s; ++j) {
        x[j] = std::min((leading[j] + x[j]) * inv_k, largest_below_one);
      }
      x[s - 1] = std::min((last + x[s - 1]) * inv_k, largest_below_one);
      if (++in_stratum == m_) {
        in_stratum = 0;
        last += 1.0;
        if (last == k_double) {
          last = 0.0;
          cell[s - 1] = k - 1;  // so that next_cell carries into the leading axes
          grid_.next_cell(cell);
          for (std::size_t j = 0; j + 1 < s; ++j) leading[j] = static_cast<double>(cell[j]);
        }
      }
    }
  }

 private:
  stratum_grid grid_;
  std::uint64_t m_;
  std::uint64_t n_ = 0;
  random_stream rng_;
};

}  // namespace quadmc
