// Two measures of how well a point set fills the cube beyond its discrepancies (discrepancy.hpp):
// the exact t-value of N = 2^m points as a (t, m, s)-net in base 2, and the smallest distance
// between two points against the densest packing's (docs/theory.md#net-quality).
//
// Use them to tell which structure a set really has at a given N: a scrambled Sobol' pair or a
// pmj02 pair is a (0, m, 2)-net (t = 0, every elementary interval of area 2^−m holds one point),
// jittered points are not (t grows with m), and the minimum distance separates blue-noise-like
// sets (ratio near 1) from independent points (ratio → 0 as N grows). Not a substitute for the
// integration error: a set with t = 0 may still integrate a given f worse than one without.
//
// t-value: the smallest t such that every elementary interval Π [a_j 2^−d_j, (a_j + 1) 2^−d_j)
// with Σ d_j = m − t holds exactly 2^t points, found by counting the points of every such
// interval for t = 0, 1, … (C(m − t + s − 1, s − 1) shapes of N boxes each), on the coordinates'
// first 53 binary digits. Every set of N = 2^m points is a (m, m, s)-net, so t ≤ m.
//
// Minimum distance: min over pairs of the Euclidean distance (no wrap-around), divided by the
// distance of N balls packed in unit volume at the densest lattice packing's density Δ_s
// ([Conway & Sloane 1999, ch. 1]): d_Δ = 2·(Δ_s/(N·V_s))^(1/s), V_s the unit ball's volume; in 2D
// d_Δ = (2/(√3·N))^(1/2), the hexagonal packing's. Known for s ≤ 8 (NaN beyond); O(N²·s), so
// N ≤ max_discrepancy_points, as for the discrepancies. The ratio may exceed 1 at small N, where
// the cube's faces leave room the infinite packing has not (16 points of the square can be 1/3
// apart, 1.24 times the hexagonal d_Δ).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace quadmc {

// The largest N and s the t-value counts take (2^20 points; the whole set's t for s ≤ 8), and
// the work they may cost: C(m + k − 1, k − 1) shapes of elementary intervals in k coordinates,
// each counting all N = 2^m points, at most 2^31 counts (seconds) for t = 0.
inline constexpr unsigned max_net_log2_points = 20;
inline constexpr std::size_t max_net_dimension = 8;
inline constexpr double max_net_box_counts = 2147483648.0;

// The t-value of the N = 2^m points given row-major (x[i·s + j]) in coordinates `axes` (all s
// when empty), or nullopt when N is not a power of two. Throws invalid_argument for s = 0, a size
// that is not a multiple of s, N > 2^20, more than 8 axes, an axis ≥ s, more box counts than
// max_net_box_counts, or a coordinate outside [0, 1).
std::optional<unsigned> net_t_value(std::span<const double> points, std::size_t s,
                                    std::span<const std::size_t> axes = {});

// The largest t-value over the s(s − 1)/2 projections on pairs of coordinates (nullopt when N is
// not a power of two or s < 2), and the first pair (j, k), 0-based, that has it.
struct pair_t_values {
  unsigned worst = 0;
  unsigned best = 0;
  std::size_t worst_j = 0;
  std::size_t worst_k = 1;
};
std::optional<pair_t_values> pairwise_t_values(std::span<const double> points, std::size_t s);

// The smallest distance between two of the points over the densest packing's d_Δ (NaN for s > 8
// or fewer than 2 points). Throws invalid_argument as discrepancies() does (N ≤ 2^14).
double normalized_min_distance(std::span<const double> points, std::size_t s);

}  // namespace quadmc
