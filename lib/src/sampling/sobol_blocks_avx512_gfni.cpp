// The AVX-512 Sobol' kernel (sobol_avx512_kernel.hpp) with GFNI bit reversals, for CPUs
// with AVX512F, AVX512DQ, AVX512BW and GFNI. Compiled with those four flags (lib/CMakeLists.txt);
// called only when the CPU has all four (sobol_blocks.cpp).
#if defined(__x86_64__)
#include "sobol_avx512_kernel.hpp"

namespace quadmc::detail {

void sobol_blocks_avx512_gfni(const sobol_block_tables& t, std::uint64_t q, std::uint64_t blocks,
                              double* out) noexcept {
  if (blocks == 0) return;
  switch (t.scramble) {
    case sobol_scramble::xor_constant:
      return run_all<sobol_scramble::xor_constant>(t, q, blocks, out);
    case sobol_scramble::fast_owen:
      return run_all<sobol_scramble::fast_owen>(t, q, blocks, out);
    case sobol_scramble::owen:
      return run_all<sobol_scramble::owen>(t, q, blocks, out);
  }
}

}  // namespace quadmc::detail
#endif
