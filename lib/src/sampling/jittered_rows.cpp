// detail::jittered_rows (sampling/jittered_points.hpp): the scalar and SSE2 kernels (SSE2 is part
// of baseline x86-64) and the run-time choice among the levels (core/simd_level.hpp). Every
// level computes the same coordinates bit for bit (tests/sampling/jittered_points_test.cpp checks
// each against the scalar formula).
#include "jittered_rows.hpp"

#include "quadmc/core/simd_level.hpp"

#if defined(__x86_64__)
#include <emmintrin.h>
#endif

namespace quadmc::detail {
namespace {

struct scalar_lanes {
  using reg = double;
  static constexpr std::size_t lanes = 1;
  static reg load(const double* p) { return *p; }
  static void store(double* p, reg v) { *p = v; }
  static reg broadcast(double v) { return v; }
  static reg add(reg a, reg b) { return a + b; }
  static reg mul(reg a, reg b) { return a * b; }
  static reg min(reg a, reg b) { return std::min(a, b); }
};

#if defined(__x86_64__)
struct sse2_lanes {
  using reg = __m128d;
  static constexpr std::size_t lanes = 2;
  static reg load(const double* p) { return _mm_loadu_pd(p); }
  static void store(double* p, reg v) { _mm_storeu_pd(p, v); }
  static reg broadcast(double v) { return _mm_set1_pd(v); }
  static reg add(reg a, reg b) { return _mm_add_pd(a, b); }
  static reg mul(reg a, reg b) { return _mm_mul_pd(a, b); }
  static reg min(reg a, reg b) { return _mm_min_pd(a, b); }
};
#endif

}  // namespace

void jittered_rows_scalar(std::size_t s, double k, double inv_k, const double* cell, double* x,
                          std::size_t count) noexcept {
  jittered_rows_for<scalar_lanes>(s, k, inv_k, cell, x, count);
}

#if defined(__x86_64__)
void jittered_rows_sse2(std::size_t s, double k, double inv_k, const double* cell, double* x,
                        std::size_t count) noexcept {
  jittered_rows_for<sse2_lanes>(s, k, inv_k, cell, x, count);
}
#endif

void jittered_rows(std::size_t s, double k, double inv_k, const double* cell, double* x,
                   std::size_t count) noexcept {
#if defined(__x86_64__)
  switch (active_simd_level()) {
    case simd_level::avx512:
      return jittered_rows_avx512(s, k, inv_k, cell, x, count);
    case simd_level::avx2:
      return jittered_rows_avx2(s, k, inv_k, cell, x, count);
    case simd_level::sse2:
      return jittered_rows_sse2(s, k, inv_k, cell, x, count);
    default:
      break;
  }
#endif
  jittered_rows_scalar(s, k, inv_k, cell, x, count);
}

}  // namespace quadmc::detail
