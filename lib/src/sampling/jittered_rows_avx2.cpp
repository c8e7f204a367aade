// The AVX2 placement of jittered points: 4 coordinates per register (jittered_rows.hpp).
// Compiled with -mavx2 (lib/CMakeLists.txt) and called only when the CPU has AVX2
// (jittered_rows.cpp).
#if defined(__x86_64__)
#include "jittered_rows.hpp"

#include <immintrin.h>

namespace quadmc::detail {
namespace {

struct avx2_lanes {
  using reg = __m256d;
  static constexpr std::size_t lanes = 4;
  static reg load(const double* p) { return _mm256_loadu_pd(p); }
  static void store(double* p, reg v) { _mm256_storeu_pd(p, v); }
  static reg broadcast(double v) { return _mm256_set1_pd(v); }
  static reg add(reg a, reg b) { return _mm256_add_pd(a, b); }
  static reg mul(reg a, reg b) { return _mm256_mul_pd(a, b); }
  static reg min(reg a, reg b) { return _mm256_min_pd(a, b); }
};

}  // namespace

void jittered_rows_avx2(std::size_t s, double k, double inv_k, const double* cell, double* x,
                        std::size_t count) noexcept {
  jittered_rows_for<avx2_lanes>(s, k, inv_k, cell, x, count);
}

}  // namespace quadmc::detail
#endif
