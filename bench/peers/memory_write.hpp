// The machine's write rate for doubles, the yardstick beside random_stream::fill_uniform's
// uniforms per second in results/peers (measurement.hpp, measure_uniforms): how fast this core can
// store doubles at all, into a buffer in cache and into one far larger than the caches.
//
// Use it from the peers driver only. Not a library kernel: it writes one value everywhere, with
// the widest vector store of the active SIMD level (core/simd_level.hpp), the level the generator
// kernels beside it run at, so that the yardstick is what this core can store at that level.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

namespace quadmc::peers {

enum class store_kind {
  ordinary,   // ordinary stores: the line is read into the cache first (read for ownership)
  streaming,  // non-temporal stores: written around the caches, no read for ownership
};

// out[k] = value for every k. Needs out.data() aligned to 64 bytes and out.size() a multiple of
// 8 (aligned_doubles gives both); throws std::invalid_argument otherwise.
void write_doubles(std::span<double> out, double value, store_kind kind);

// What write_doubles runs at the active level, e.g. "512-bit stores (avx512)".
std::string_view write_kernel(store_kind kind);

// A zeroed buffer of n doubles (n a multiple of 8) aligned to 64 bytes: every page touched once
// before any timing, so that no run pays the first touch.
class aligned_doubles {
 public:
  explicit aligned_doubles(std::size_t n);
  ~aligned_doubles();
  aligned_doubles(const aligned_doubles&) = delete;
  aligned_doubles& operator=(const aligned_doubles&) = delete;
  std::span<double> span() noexcept { return {data_, n_}; }

 private:
  double* data_;
  std::size_t n_;
};

}  // namespace quadmc::peers
