// The AVX-512 Sobol' kernel (sobol_avx512_kernel.hpp) with GFNI bit reversals and owen's tree
// six levels at a time (AVX512_VBMI's vpmultishiftqb, AVX512_BITALG's vpshufbitqmb), for CPUs
// with AVX512F, AVX512DQ, AVX512BW, AVX512_VBMI, AVX512_BITALG and GFNI. Compiled with those six
// flags (lib/CMakeLists.txt); called only when the CPU has all six (sobol_blocks.cpp).
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
