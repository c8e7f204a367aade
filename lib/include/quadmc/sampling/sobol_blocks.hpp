// The vector kernel behind sobol_points::generate (sampling/sobol_points.hpp): whole blocks of
// B = 2^b consecutive points, one register lane per coordinate of a point of the block.
//
// Use it only through sobol_points. Why blocks: Gray code is linear over GF(2), so for a block
// start B·q (B = 2^b) and r < B, g(B·q + r) = g(B·q) ⊕ g(r), and coordinate j of point B·q + r is
// C_j·g(B·q) ⊕ C_j·g(r). The first term is shared by the B points of the block; from block q to
// q + 1 it changes by C_j·(g(B·(q + 1)) ⊕ g(B·q)) = column ctz(q + 1) + b ⊕ column b − 1 (for
// b ≥ 1: g(B·q) = B·g(q) ⊕ (B/2)·(q mod 2), and the parity of q always changes), one precomputed
// step. The second is a constant table. So a block of B·s coordinates costs one XOR per
// coordinate plus the constant, and every value is the same integer as the point-by-point
// Gray-code walk: the points are bitwise those of the scalar path whatever B and wherever a batch
// starts. B = 8/gcd(s, 8) for s ≤ 8 (a block fills whole 8-lane AVX-512 registers, or pairs of
// 4-lane AVX2 ones), B = 1 above (the coordinates of one point fill the registers). The digital
// shifts (shift, lms_shift) are folded into the constant; the nonlinear scrambles
// (fast_owen, owen) run per lane on the 64-bit words exactly as their scalar code does.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace quadmc::detail {

// What a randomizer does after the linear part: an XOR with a constant per dimension (none,
// shift and lms_shift, whose matrix is already in the columns), or a nonlinear scramble keyed
// per dimension.
enum class sobol_scramble { xor_constant, fast_owen, owen };

// Levels of owen_scramble's flip tree drawn from one 64-bit hash: 1 + 2 + … + 32 = 63 nodes.
// Here rather than in sobol_points.hpp, which the kernels (built for other instruction sets)
// must not include: its inline functions would be compiled with those sets.
inline constexpr unsigned owen_levels_per_hash = 6;

struct sobol_block_tables {
  std::size_t s = 0;
  unsigned log2_block = 0;  // B = 2^log2_block points per block
  std::size_t words = 0;    // B·s coordinates per block
  sobol_scramble scramble = sobol_scramble::xor_constant;
  unsigned depth = 0;  // owen: digits drawn one by one (owen_scramble)
  // owen: the flips of the first `table_digits` digits for every prefix of that length, one table
  // of 2^table_digits words per dimension (bit 63 − b = the flip of digit b, exactly
  // owen_scramble::flips of the prefix): one gather replaces ⌈table_digits/6⌉ hashes and the
  // tree's bit picks per coordinate. table_digits ≤ 12 and the tables ≤ 1 MiB together
  // (s·2^table_digits ≤ 2^17).
  unsigned table_digits = 0;
  std::vector<std::uint64_t> flips;
  std::vector<std::uint64_t> flip_base;  // `words`: j·2^table_digits for the lane's dimension j
  std::vector<std::uint64_t> rows;       // 32 rows of `words`: column k of each lane's dimension
  std::vector<std::uint64_t> steps;      // b ≥ 1: 32 − b rows, column k + b ⊕ column b − 1
  std::vector<std::uint64_t> offset;     // `words`: C_j·g(r) for lane r·s + j (⊕ the shift)
  std::vector<std::uint64_t> key;        // `words`: the dimension's scramble key (fast_owen, owen)
};

// columns: 32 per dimension, dimension-major (as sobol_points holds them); keys: one per
// dimension (the XOR constant, or the scramble seed).
sobol_block_tables make_sobol_block_tables(std::span<const std::uint64_t> columns, std::size_t s,
                                           sobol_scramble scramble,
                                           std::span<const std::uint64_t> keys, unsigned depth);

// Writes `blocks` whole blocks starting at point B·q (the Gray-code index; row-major doubles,
// out[p·s + j]) and returns true, or returns false and writes nothing when this CPU (or the
// chosen simd level) has no vector kernel: the caller then takes the scalar path.
bool sobol_blocks(const sobol_block_tables& t, std::uint64_t q, std::uint64_t blocks,
                  double* out) noexcept;

// Whether the AVX-512 kernel may take its GFNI build where the CPU has GFNI, AVX512BW,
// AVX512_VBMI and AVX512_BITALG (the default, true). For tests: with false, a CPU with GFNI runs
// the plain AVX-512 build too, the one a CPU without GFNI gets, so both are checked against the
// scalar walk on one machine.
void allow_sobol_gfni(bool allowed) noexcept;

}  // namespace quadmc::detail
