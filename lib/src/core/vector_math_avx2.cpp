// vector_exp / vector_cos on avx2: libmvec's 4-lane variants ('d' in the x86_64 vector
// function ABI, glibc sysdeps/x86_64/fpu/libmvec.abilist). Compiled with -mavx2
// (lib/CMakeLists.txt), called only when the CPU has AVX2.
#if defined(__x86_64__) && defined(QUADMC_HAVE_LIBMVEC)
#include "vector_math_kernels.hpp"

#include <immintrin.h>

extern "C" {
__m256d _ZGVdN4v_exp(__m256d x);
__m256d _ZGVdN4v_cos(__m256d x);
}

namespace quadmc::detail {
namespace {

struct avx2_lanes {
  static constexpr std::size_t lanes = 4;
  static __m256d load(const double* p) { return _mm256_loadu_pd(p); }
  static void store(double* p, __m256d v) { _mm256_storeu_pd(p, v); }
};

}  // namespace

void vector_math_avx2(vector_function f, const double* x, double* y, std::size_t n) noexcept {
  if (f == vector_function::exp) {
    apply_in_lanes<avx2_lanes>([](__m256d v) { return _ZGVdN4v_exp(v); }, x, y, n);
  } else {
    apply_in_lanes<avx2_lanes>([](__m256d v) { return _ZGVdN4v_cos(v); }, x, y, n);
  }
}

}  // namespace quadmc::detail
#endif
