// vector_exp / vector_cos on sse2: libmvec's 2-lane variants ('b' in the x86_64 vector
// function ABI, glibc sysdeps/x86_64/fpu/libmvec.abilist). SSE2 is part of every x86-64, so this
// file needs no extra compiler flag.
#if defined(__x86_64__) && defined(QUADMC_HAVE_LIBMVEC)
#include "vector_math_kernels.hpp"

#include <emmintrin.h>

extern "C" {
__m128d _ZGVbN2v_exp(__m128d x);
__m128d _ZGVbN2v_cos(__m128d x);
}

namespace quadmc::detail {
namespace {

struct sse2_lanes {
  static constexpr std::size_t lanes = 2;
  static __m128d load(const double* p) { return _mm_loadu_pd(p); }
  static void store(double* p, __m128d v) { _mm_storeu_pd(p, v); }
};

}  // namespace

void vector_math_sse2(vector_function f, const double* x, double* y, std::size_t n) noexcept {
  if (f == vector_function::exp) {
    apply_in_lanes<sse2_lanes>([](__m128d v) { return _ZGVbN2v_exp(v); }, x, y, n);
  } else {
    apply_in_lanes<sse2_lanes>([](__m128d v) { return _ZGVbN2v_cos(v); }, x, y, n);
  }
}

}  // namespace quadmc::detail
#endif
