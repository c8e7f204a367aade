// The vector kernels behind detail::sobol_blocks (sampling/sobol_blocks.hpp), one per instruction
// set, each in its own file compiled with that ISA's flags (lib/CMakeLists.txt) and called only
// after a run-time CPU check (sobol_blocks.cpp).
#pragma once

#include "quadmc/sampling/sobol_blocks.hpp"

#include <cstdint>

namespace quadmc::detail {

#if defined(__x86_64__)
void sobol_blocks_avx2(const sobol_block_tables& t, std::uint64_t q, std::uint64_t blocks,
                       double* out) noexcept;
void sobol_blocks_avx512(const sobol_block_tables& t, std::uint64_t q, std::uint64_t blocks,
                         double* out) noexcept;
void sobol_blocks_avx512_gfni(const sobol_block_tables& t, std::uint64_t q, std::uint64_t blocks,
                              double* out) noexcept;
#endif

}  // namespace quadmc::detail
