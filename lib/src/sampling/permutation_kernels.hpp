// The vector kernels behind detail::permutation_blocks (sampling/random_permutation.hpp), one per
// instruction set, each in its own file compiled with that ISA's flag (lib/CMakeLists.txt) and
// called only after a run-time CPU check (core/simd_level.hpp).
#pragma once

#include "quadmc/sampling/random_permutation.hpp"

#include <cstddef>
#include <cstdint>

namespace quadmc::detail {

void permutation_blocks_scalar(const permutation_schedule& p, std::uint64_t first,
                               std::size_t count, std::uint64_t* out) noexcept;
#if defined(__x86_64__)
void permutation_blocks_avx2(const permutation_schedule& p, std::uint64_t first, std::size_t count,
                             std::uint64_t* out) noexcept;
void permutation_blocks_avx512(const permutation_schedule& p, std::uint64_t first,
                               std::size_t count, std::uint64_t* out) noexcept;
#endif

}  // namespace quadmc::detail
