// rank1_lattice_blocks' tables and the run-time choice of its kernel
// (sampling/rank1_lattice_blocks.hpp). The kernels compute the same doubles as
// rank1_lattice_points' scalar loop, so the choice changes only the speed
// (tests/sampling/rank1_lattice_points_test.cpp compares them bitwise).
#include "quadmc/sampling/rank1_lattice_blocks.hpp"

#include "quadmc/core/simd_level.hpp"
#include "rank1_lattice_kernels.hpp"

#include <numeric>

namespace quadmc::detail {

rank1_lattice_block_tables make_rank1_lattice_block_tables(std::span<const std::uint64_t> z,
                                                           std::span<const double> shift,
                                                           std::uint64_t n,
                                                           lattice_periodization periodization) {
  rank1_lattice_block_tables t;
  t.s = z.size();
  t.block = t.s <= 8 ? 8 / std::gcd(t.s, std::size_t{8}) : 1;
  t.words = t.block * t.s;
  t.mask = n - 1;
  t.inv_n = 1.0 / static_cast<double>(n);
  t.periodization = periodization;
  for (std::size_t r = 0; r < t.block; ++r) {
    for (std::size_t j = 0; j < t.s; ++j) {
      t.point.push_back(r);
      t.z.push_back(z[j] & t.mask);
      t.step.push_back((t.block * z[j]) & t.mask);
      t.shift.push_back(shift[j]);
    }
  }
  return t;
}

bool rank1_lattice_blocks(const rank1_lattice_block_tables& t, std::uint64_t first,
                          std::uint64_t blocks, double* out) noexcept {
#if defined(__x86_64__)
  // vcvtqq2pd is AVX-512DQ, which the avx512 level (AVX512F) does not imply.
  static const bool has_avx512dq = __builtin_cpu_supports("avx512dq");
  if (active_simd_level() == simd_level::avx512 && has_avx512dq) {
    rank1_lattice_blocks_avx512(t, first, blocks, out);
    return true;
  }
  // AVX2 (or an avx512 level on a CPU without AVX512DQ): 4 lanes, the conversion by exponent bits.
  if (active_simd_level() >= simd_level::avx2) {
    rank1_lattice_blocks_avx2(t, first, blocks, out);
    return true;
  }
#else
  (void)t, (void)first, (void)blocks, (void)out;
#endif
  return false;
}

}  // namespace quadmc::detail
