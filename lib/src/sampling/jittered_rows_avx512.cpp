// The AVX-512 placement of jittered points: 8 coordinates per register (jittered_rows.hpp).
// Compiled with -mavx512f (lib/CMakeLists.txt) and called only when the CPU has AVX-512F
// (jittered_rows.cpp).
#if defined(__x86_64__)
#include "jittered_rows.hpp"

#include <immintrin.h>

namespace quadmc::detail {
namespace {

struct avx512_lanes {
  using reg = __m512d;
  static constexpr std::size_t lanes = 8;
  static reg load(const double* p) { return _mm512_loadu_pd(p); }
  static void store(double* p, reg v) { _mm512_storeu_pd(p, v); }
  static reg broadcast(double v) { return _mm512_set1_pd(v); }
  static reg add(reg a, reg b) { return _mm512_add_pd(a, b); }
  static reg mul(reg a, reg b) { return _mm512_mul_pd(a, b); }
  static reg min(reg a, reg b) { return _mm512_min_pd(a, b); }
};

}  // namespace

void jittered_rows_avx512(std::size_t s, double k, double inv_k, const double* cell, double* x,
                          std::size_t count) noexcept {
  jittered_rows_for<avx512_lanes>(s, k, inv_k, cell, x, count);
}

}  // namespace quadmc::detail
#endif
