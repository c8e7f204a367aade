// Vector stores of one value at the active SIMD level; what and why: memory_write.hpp.
#include "memory_write.hpp"

#include "quadmc/core/simd_level.hpp"

#include <cstdint>
#include <cstring>
#include <new>
#include <stdexcept>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace quadmc::peers {
namespace {

// Each level's kernel is compiled for its own instruction set (the function's target attribute)
// and called only when the level is active, which core/simd_level.cpp grants only on a CPU that
// has it: the same run-time dispatch as the library's kernels, in a baseline x86-64 build.
#if defined(__x86_64__)
__attribute__((target("avx512f"))) void write_avx512(double* p, std::size_t n, double v,
                                                     bool streaming) {
  const __m512d x = _mm512_set1_pd(v);
  if (streaming) {
    for (std::size_t k = 0; k < n; k += 8) _mm512_stream_pd(p + k, x);
  } else {
    for (std::size_t k = 0; k < n; k += 8) _mm512_store_pd(p + k, x);
  }
}

__attribute__((target("avx"))) void write_avx(double* p, std::size_t n, double v, bool streaming) {
  const __m256d x = _mm256_set1_pd(v);
  if (streaming) {
    for (std::size_t k = 0; k < n; k += 4) _mm256_stream_pd(p + k, x);
  } else {
    for (std::size_t k = 0; k < n; k += 4) _mm256_store_pd(p + k, x);
  }
}

void write_sse2(double* p, std::size_t n, double v, bool streaming) {
  const __m128d x = _mm_set1_pd(v);
  if (streaming) {
    for (std::size_t k = 0; k < n; k += 2) _mm_stream_pd(p + k, x);
  } else {
    for (std::size_t k = 0; k < n; k += 2) _mm_store_pd(p + k, x);
  }
}

// The scalar level's streaming store: movnti of 64 bits, in every x86-64.
void stream_scalar(double* p, std::size_t n, double v) {
  long long bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  for (std::size_t k = 0; k < n; ++k) _mm_stream_si64(reinterpret_cast<long long*>(p + k), bits);
}
#endif

}  // namespace

void write_doubles(std::span<double> out, double value, store_kind kind) {
  double* p = out.data();
  const std::size_t n = out.size();
  if (reinterpret_cast<std::uintptr_t>(p) % 64 != 0 || n % 8 != 0) {
    throw std::invalid_argument("write_doubles: needs 64-byte alignment and a multiple of 8");
  }
  const bool streaming = kind == store_kind::streaming;
#if defined(__x86_64__)
  switch (active_simd_level()) {
    case simd_level::avx512:
      write_avx512(p, n, value, streaming);
      break;
    case simd_level::avx2:
      write_avx(p, n, value, streaming);
      break;
    case simd_level::sse2:
      write_sse2(p, n, value, streaming);
      break;
    case simd_level::scalar:
      if (streaming) {
        stream_scalar(p, n, value);
      } else {
        for (std::size_t k = 0; k < n; ++k) p[k] = value;
      }
      break;
  }
  // Non-temporal stores are weakly ordered: fence them, so that the run ends after them.
  if (streaming) _mm_sfence();
#else
  for (std::size_t k = 0; k < n; ++k) p[k] = value;
#endif
}

std::string_view write_kernel(store_kind kind) {
  const bool streaming = kind == store_kind::streaming;
#if defined(__x86_64__)
  switch (active_simd_level()) {
    case simd_level::avx512:
      return streaming ? "512-bit vmovntpd (avx512)" : "512-bit vmovapd (avx512)";
    case simd_level::avx2:
      return streaming ? "256-bit vmovntpd (avx2)" : "256-bit vmovapd (avx2)";
    case simd_level::sse2:
      return streaming ? "128-bit movntpd (sse2)" : "128-bit movapd (sse2)";
    case simd_level::scalar:
      return streaming ? "64-bit movnti (scalar)" : "a C++ loop of doubles (scalar)";
  }
  return "?";
#else
  return streaming ? "a C++ loop of doubles (no streaming store here)" : "a C++ loop of doubles";
#endif
}

aligned_doubles::aligned_doubles(std::size_t n)
    : data_(static_cast<double*>(::operator new[](n * sizeof(double), std::align_val_t{64}))),
      n_(n) {
  for (std::size_t k = 0; k < n; ++k) data_[k] = 0.0;
}

aligned_doubles::~aligned_doubles() {
  ::operator delete[](data_, std::align_val_t{64});
}

}  // namespace quadmc::peers
