// random_stream::fill_uniform's kernel: the scalar reference and the run-time choice among the
// vector kernels (philox_lanes.hpp). The scalar path is Random123's own Philox4x32-10, so the
// vector kernels are tested against it bit for bit (tests/core/philox_blocks_test.cpp).
#include "philox_constants.hpp"

#include "quadmc/core/rng.hpp"
#include "quadmc/core/simd_level.hpp"

namespace quadmc::detail {

void philox_uniform_blocks_scalar(const philox_counter_key& k, std::uint64_t first_block,
                                  std::size_t blocks, double* out) noexcept {
  const r123::Philox4x32::key_type key = {{k.key0, k.key1}};
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::uint64_t block = first_block + b;
    const r123::Philox4x32::ctr_type ctr = {{static_cast<std::uint32_t>(block),
                                             static_cast<std::uint32_t>(block >> 32), k.stream_lo,
                                             k.stream_hi}};
    const auto r = r123::Philox4x32{}(ctr, key);
    out[2 * b] = random_stream::to_unit((static_cast<std::uint64_t>(r.v[1]) << 32) | r.v[0]);
    out[2 * b + 1] = random_stream::to_unit((static_cast<std::uint64_t>(r.v[3]) << 32) | r.v[2]);
  }
}

void philox_uniform_blocks(std::uint32_t key0, std::uint32_t key1, std::uint32_t stream_lo,
                           std::uint32_t stream_hi, std::uint64_t first_block, std::size_t blocks,
                           double* out) {
  const philox_counter_key k{key0, key1, stream_lo, stream_hi};
  switch (active_simd_level()) {
#if defined(__x86_64__)
    case simd_level::avx512:
      return philox_uniform_blocks_avx512(k, first_block, blocks, out);
    case simd_level::avx2:
      return philox_uniform_blocks_avx2(k, first_block, blocks, out);
    case simd_level::sse2:
      return philox_uniform_blocks_sse2(k, first_block, blocks, out);
#endif
    default:
      return philox_uniform_blocks_scalar(k, first_block, blocks, out);
  }
}

}  // namespace quadmc::detail
