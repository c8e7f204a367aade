// The vector kernel behind rank1_lattice_points::generate (sampling/rank1_lattice_points.hpp):
// whole blocks of B consecutive points, one register lane per coordinate of a point of the block.
//
// Use it only through rank1_lattice_points. Lane r·s + j holds k = (i + r)·z_j mod N as an exact
// integer, advanced by the constant B·z_j mod N per block (one add and one mask); the coordinate
// is then k·(1/N) + Δ_j, whose product is exact (N = 2^m, k < 2^20), so the sum is the one
// rounding of the scalar code, and x ≥ 1 ? x − 1 : x is exact (Sterbenz). The same operations in
// the same order as the scalar path, lane by lane: the points are bitwise equal, wherever a batch
// starts (no alignment is needed: k is computed from the index). B = 8/gcd(s, 8) for s ≤ 8 (a
// block fills whole 8-lane AVX-512 registers, or pairs of 4-lane AVX2 ones), B = 1 above (the
// coordinates of one point in slices of 64 lanes, 16 with AVX2).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace quadmc::detail {

enum class lattice_periodization { none, baker };

struct rank1_lattice_block_tables {
  std::size_t s = 0;
  std::size_t block = 1;   // B points per block
  std::size_t words = 0;   // B·s coordinates per block
  std::uint64_t mask = 0;  // N − 1
  double inv_n = 1.0;      // 1/N, exact
  lattice_periodization periodization = lattice_periodization::none;
  std::vector<std::uint64_t> point;  // `words`: r, the lane's point within its block
  std::vector<std::uint64_t> z;      // `words`: z_j mod N
  std::vector<std::uint64_t> step;   // `words`: B·z_j mod N
  std::vector<double> shift;         // `words`: Δ_j
};

rank1_lattice_block_tables make_rank1_lattice_block_tables(std::span<const std::uint64_t> z,
                                                           std::span<const double> shift,
                                                           std::uint64_t n,
                                                           lattice_periodization periodization);

// Writes `blocks` whole blocks of points first … first + B·blocks − 1 (row-major doubles,
// out[p·s + j]) and returns true, or returns false and writes nothing when this CPU (or the
// chosen simd level) has no vector kernel: the caller then takes the scalar path.
bool rank1_lattice_blocks(const rank1_lattice_block_tables& t, std::uint64_t first,
                          std::uint64_t blocks, double* out) noexcept;

}  // namespace quadmc::detail
