// vector_exp / vector_cos on avx512: libmvec's 8-lane variants ('e' in the x86_64 vector
// function ABI, glibc sysdeps/x86_64/fpu/libmvec.abilist). Compiled with -mavx512f
// (lib/CMakeLists.txt), called only when the CPU has AVX512F.
#if defined(__x86_64__) && defined(QUADMC_HAVE_LIBMVEC)
#include "vector_math_kernels.hpp"

#include <immintrin.h>

extern "C" {
__m512d _ZGVeN8v_exp(__m512d x);
__m512d _ZGVeN8v_cos(__m512d x);
}

namespace quadmc::detail {
namespace {

struct avx512_lanes {
  static constexpr std::size_t lanes = 8;
  static __m512d load(const double* p) { return _mm512_loadu_pd(p); }
  static void store(double* p, __m512d v) { _mm512_storeu_pd(p, v); }
};

}  // namespace

void vector_math_avx512(vector_function f, const double* x, double* y, std::size_t n) noexcept {
  if (f == vector_function::exp) {
    apply_in_lanes<avx512_lanes>([](__m512d v) { return _ZGVeN8v_exp(v); }, x, y, n);
  } else {
    apply_in_lanes<avx512_lanes>([](__m512d v) { return _ZGVeN8v_cos(v); }, x, y, n);
  }
}

}  // namespace quadmc::detail
#endif
