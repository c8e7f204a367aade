// How the AVX2 point kernels (sobol_blocks_avx2.cpp, rank1_lattice_blocks_avx2.cpp) walk the
// lanes of a block: in slices of at most 16 lanes, 4 registers, so that a slice's state stays in
// the 16 ymm registers with room for the kernel's temporaries; the last register of a slice keeps
// only its own lanes. Include it only from files compiled with -mavx2.
#pragma once

#include <immintrin.h>

#include <algorithm>
#include <cstddef>
#include <type_traits>

namespace quadmc::detail {
namespace {

// Calls run(std::integral_constant<int, V>{}, w0, tail) for each slice [w0, w0 + lanes) of
// `words` lanes, V = ⌈lanes/4⌉ registers, tail all ones in the lanes its last register keeps.
template <class Run>
void for_each_avx2_slice(std::size_t words, Run&& run) noexcept {
  for (std::size_t w0 = 0; w0 < words; w0 += 16) {
    const std::size_t lanes = std::min<std::size_t>(16, words - w0);
    const std::size_t registers = (lanes + 3) / 4;
    const auto kept = static_cast<long long>(lanes - 4 * (registers - 1));
    const __m256i tail =
        _mm256_cmpgt_epi64(_mm256_set1_epi64x(kept), _mm256_setr_epi64x(0, 1, 2, 3));
    switch (registers) {
      case 1:
        run(std::integral_constant<int, 1>{}, w0, tail);
        break;
      case 2:
        run(std::integral_constant<int, 2>{}, w0, tail);
        break;
      case 3:
        run(std::integral_constant<int, 3>{}, w0, tail);
        break;
      default:
        run(std::integral_constant<int, 4>{}, w0, tail);
        break;
    }
  }
}

}  // namespace
}  // namespace quadmc::detail
