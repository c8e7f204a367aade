// The vector kernels behind detail::rank1_lattice_blocks (sampling/rank1_lattice_blocks.hpp), one
// per instruction set, each in its own file compiled with that ISA's flags (lib/CMakeLists.txt)
// and called only after a run-time CPU check (rank1_lattice_blocks.cpp).
#pragma once

#include "quadmc/sampling/rank1_lattice_blocks.hpp"

#include <cstdint>

namespace quadmc::detail {

#if defined(__x86_64__)
void rank1_lattice_blocks_avx2(const rank1_lattice_block_tables& t, std::uint64_t first,
                               std::uint64_t blocks, double* out) noexcept;
void rank1_lattice_blocks_avx512(const rank1_lattice_block_tables& t, std::uint64_t first,
                                 std::uint64_t blocks, double* out) noexcept;
#endif

}  // namespace quadmc::detail
