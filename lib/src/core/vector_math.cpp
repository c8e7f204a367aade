// vector_exp / vector_cos: the scalar reference (glibc's own exp and cos, one at a time) and the
// run-time choice among the libmvec variants (vector_math_<isa>.cpp).
#include "quadmc/core/vector_math.hpp"

#include "vector_math_kernels.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/simd_level.hpp"

#include <cmath>
#include <string>

namespace quadmc::detail {

void throw_vector_math_size_mismatch(std::size_t x_size, std::size_t y_size) {
  throw invalid_argument("y.size()", std::to_string(y_size),
                         "x.size() = " + std::to_string(x_size) + " (one output per input)");
}

void vector_math(vector_function f, std::span<const double> x, std::span<double> y) {
  if (y.size() != x.size()) throw_vector_math_size_mismatch(x.size(), y.size());
  const double* in = x.data();
  double* out = y.data();
  const std::size_t n = x.size();
  switch (active_simd_level()) {
#if defined(__x86_64__) && defined(QUADMC_HAVE_LIBMVEC)
    case simd_level::avx512:
      return vector_math_avx512(f, in, out, n);
    case simd_level::avx2:
      return vector_math_avx2(f, in, out, n);
    case simd_level::sse2:
      return vector_math_sse2(f, in, out, n);
#endif
    default:
      if (f == vector_function::exp) {
        for (std::size_t i = 0; i < n; ++i) out[i] = std::exp(in[i]);
      } else {
        for (std::size_t i = 0; i < n; ++i) out[i] = std::cos(in[i]);
      }
  }
}

}  // namespace quadmc::detail
